// SPDX-License-Identifier: MIT
#pragma once

#include "metricspec.h"
#include "random.h"
#include "task.h"
#include "world.h"

#include <vector>

namespace semhap {

/**
 * The dish_wiping task (docs/metrics.md): a plate whose face is a grid of stained cells, each
 * cleaned by wiping it with enough force; a plate pressed past its limit breaks and is
 * replaced, stained, after a penalty; a plate wiped clean is stained again, so a run keeps
 * going. At a seeded moment the sponge's holder stiffens, unseen (the same press then gives
 * 2.5 times the force). Its metrics are the area cleaned, the time to clean, the peak force,
 * the time above the safe force and the plates broken.
 */
class WipingTask : public Task
{
public:
    /** The scene's `semhap:task` text that selects this task. */
    static constexpr const char *Name = "dish_wiping";
    /** The press (N) at which wiping takes a stain off, and how far a cell must be wiped. */
    static constexpr double CleanForce = 8.0;
    static constexpr double CleanDistance = 0.1; // m
    /** The most a plate takes without risk (N); its break force is `fragile:plate`. */
    static constexpr double SafeForce = 25.0;
    /** How long a broken plate is out of play before the next one is put in its place (s). */
    static constexpr double ReplacePenalty = 2.0;
    /** When the unseen stiffening may come: uniformly in this window (s). */
    static constexpr double StiffenEarliest = 15.0;
    static constexpr double StiffenLatest = 35.0;

    /**
     * The task on `world`; null with `error` when the scene lacks what it needs: a free body
     * `plate` with stains `plate.stain.*`, and a geom `right.sponge`.
     */
    static std::unique_ptr<WipingTask> create(const World &world, std::uint64_t seed,
                                              QString *error);

    void observe(World &world) override;
    void feel(Gripper hand, const Feeling &feeling, double t) override;
    QJsonObject metrics() const override;
    /** Its metrics, a row each (docs/metrics.md). */
    static const std::vector<MetricSpec> &metricSpecs();

    /** The stained cells: how many there are and whether one is clean now. */
    int cellCount() const { return int(m_cells.size()); }
    bool isClean(int cell) const { return m_cells[size_t(cell)].wiped >= CleanDistance; }
    /** Where a cell's centre is on the plate's face, x and y from the plate's centre (m). */
    std::array<double, 2> cellCenter(int cell) const { return m_cells[size_t(cell)].center; }
    /** The sponge's normal force on the plate at the last step (N). */
    double pressForce() const { return m_press; }
    /** When the sponge's holder stiffens (s). */
    double stiffenAt() const { return m_stiffenAt; }

private:
    WipingTask(const World &world, std::uint64_t seed);

    struct Cell
    {
        int geom = -1;
        std::array<double, 2> center{}; ///< in the plate's frame (m)
        double wiped = 0.0;             ///< distance wiped over it with enough force (m)
    };

    /** The sponge's normal force on the plate now, summed over their contacts (N). */
    double press(const World &world) const;
    /** The sponge's centre in the plate's frame, x and y (m). */
    std::array<double, 2> spongeOnPlate(const World &world) const;
    void wipe(World &world, double force);
    void restain(World &world);
    void replaceBroken(World &world);

    int m_plate = -1;
    int m_sponge = -1;      ///< the sponge's geom
    float m_stainAlpha = 1; ///< how a stain is drawn while dirty
    std::vector<Cell> m_cells;
    double m_breakForce = 0.0;
    double m_stiffenAt = 0.0;
    bool m_stiffened = false;

    double m_press = 0.0;
    int m_overSteps = 0;
    bool m_hasLast = false;
    std::array<double, 2> m_last{}; ///< the sponge on the plate, last step
    int m_cleaned = 0;              ///< cells cleaned in all
    int m_platesCleaned = 0;
    double m_cleanAt = -1.0; ///< when the first plate was all clean; -1: not yet
    double m_peak = 0.0;
    double m_aboveSafe = 0.0; ///< s
    double m_pressSum = 0.0;
    long m_pressSteps = 0;
    int m_broken = 0;
    double m_brokenAt = -1.0; ///< when the plate out of play broke; -1: it is in play
    double m_lastWarned = -1e9;
    int m_warnings = 0;
};

} // namespace semhap
