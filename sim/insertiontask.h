// SPDX-License-Identifier: MIT
#pragma once

#include "metricspec.h"
#include "pose.h"
#include "random.h"
#include "task.h"
#include "world.h"

#include <cmath>

namespace semhap {

/**
 * usb_insertion's rules and metrics (docs/metrics.md): a plug taken from the table and
 * seated in a port. The task lays the port and the plug out at seeded poses, and again
 * after each insertion (once the hand has let go and risen) or 2 s after a drop; it counts
 * insertions, the time each took from pick-up, collisions with the port's face and the
 * highest plug–port force. It reads the scene's signals plug.lateral, plug.angle,
 * plug.depth and plug.force on the right gripper's frames.
 */
class InsertionTask : public Task
{
public:
    /** The `semhap:task` text of the scenes this task runs. */
    static constexpr const char *Name = "usb_insertion";
    /** The port's play per side (m): resources/scenes/usb_insertion.xml. */
    static constexpr double Clearance = 0.0003;
    /** How deep a seated plug is (m). */
    static constexpr double FullDepth = 0.012;
    /** Within this of full depth (m), a plug counts as seated. */
    static constexpr double SeatedWithin = 0.001;
    /** How far from its centre each layout moves the port and the plug (m), and turns (rad). */
    static constexpr double Scatter = 0.03;
    static constexpr double MaxYaw = 20.0 * 3.14159265358979323846 / 180.0;
    /** Seconds a dropped plug lies before the task puts it back on the table. */
    static constexpr double DropPenalty = 2.0;

    /** The task on `world`, laid out from `seed`; null with `error` if the scene lacks it. */
    static std::unique_ptr<InsertionTask> create(World &world, std::uint64_t seed, QString *error);

    void observe(World &world) override;
    void feel(Gripper hand, const Feeling &feeling, double t) override;
    QJsonObject metrics() const override;
    /** Its metrics, a row each (docs/metrics.md). */
    static const std::vector<MetricSpec> &metricSpecs();

    /**
     * Whether the plug sits in the port: its tip within SeatedWithin of full depth, on the
     * opening's axis (`lateral` below InOpening; a plug on the table is as deep, elsewhere).
     */
    static bool isSeated(double depth, double lateral)
    {
        return std::abs(depth - FullDepth) <= SeatedWithin && lateral < InOpening;
    }
    /** Farther than this from the port's axis (m), the plug's tip is not in the opening. */
    static constexpr double InOpening = 0.002;

private:
    InsertionTask(World &world, std::uint64_t seed, const std::array<double, 3> &portHome);
    /** Puts the port and the plug at a new seeded pose, the plug upright at rest. */
    void layOut(World &world);
    /** A signal of the right frame, 0 when the frame lacks it. */
    double signal(const World &world, int id) const;

    Random m_random;
    int m_plug = -1;
    std::array<double, 3> m_portHome{};
    std::array<double, 3> m_plugHome{};
    double m_face = 0.0; ///< the height of the port's face (m)
    int m_lateral = -1;
    int m_depth = -1;
    int m_force = -1;

    bool m_held = false;
    double m_lostAt = -1.0;   ///< when the held plug left the fingertips; -1: in them
    double m_pickedAt = -1.0; ///< when the plug was lifted in this attempt; -1: not yet
    bool m_seated = false;    ///< this layout's plug has been seated
    double m_droppedAt = -1.0;
    bool m_colliding = false;
    double m_quietSince = -1.0; ///< during a collision: since when the push is gone

    int m_pickups = 0;
    int m_insertions = 0;
    double m_insertTimeSum = 0.0;
    int m_collisions = 0;
    int m_drops = 0;
    double m_peakForce = 0.0;
};

} // namespace semhap
