// SPDX-License-Identifier: MIT
#pragma once

#include "handplan.h"
#include "operator.h"
#include "random.h"

#include <deque>
#include <vector>

namespace semhap {

/**
 * Performs the scene's task the way a person would: reach, close at a human speed, lift,
 * carry, release, return, with seeded variation in timing and grip force — so that without
 * feedback some cubes break and some slip, as in the paper's no-feedback condition. In the
 * bimanual task the left hand holds the container as the grip/load-force literature says a
 * hand without feeling does (sim/README.md, "The holding hand"): a chosen grip-to-load
 * ratio, an unnoticed exponential drift, a grip raised as the other hand drops a cube in; a
 * full container is put down to be emptied.
 *
 * Reactive, it also acts on what it perceives, `reactionTime` later: it stops closing on a
 * grasp confirmation (or once the fingertip pressure is clear), eases off on a break warning
 * or high pressure, and grips the container as for the load it sees on a slip warning; the
 * overlay counts only while it
 * looks at that hand (it watches the picking hand and glances at the other every few s).
 */
class ScriptedOperator : public Operator
{
public:
    enum class Task
    {
        BoxAndBlock,
        BimanualSorting
    };

    /**
     * Stress scripts for the benchmarks: the same person with one failure made likely.
     * `FastSqueeze` closes fast and hard on fragile cubes; `DriftingHold` lets the holding
     * hand relax steadily while the picking hand works. Neither reacts to feedback.
     */
    enum class Variant
    {
        Normal,
        FastSqueeze,
        DriftingHold
    };

    ScriptedOperator(Task task, std::uint64_t seed, bool reactive, double reactionTime,
                     Variant variant = Variant::Normal);
    /**
     * The operator `name` (scripted, reactive, fast_squeeze, drifting_hold) for a cube scene:
     * bimanual_sorting's when it has a container, a left gripper and a home site, else
     * box_and_block's. Null with `error` when the scene lacks the sites it needs.
     */
    static std::unique_ptr<Operator> create(const QString &name, const World &world,
                                            std::uint64_t seed, double reactionTime,
                                            QString *error);

    QString name() const override;
    void act(World &world) override;
    /**
     * Starts over from where the hands are: a cube in the picking hand is carried to where it
     * goes, an empty one opens and rises clear before reaching for the next; a held container
     * is held there, else taken again.
     */
    void engage(const World &world) override;
    void feel(Gripper hand, const Feeling &feeling, double t) override;

private:
    enum class Cue
    {
        Confirmation,
        Warning,
        Pressure,
        HighPressure
    };
    struct Percept
    {
        double due;
        Gripper hand;
        Cue cue;
    };
    struct HandState
    {
        /** Per Cue: when it was last above the noticeable level. */
        std::array<double, 4> lastFelt{-1e9, -1e9, -1e9, -1e9};
    };

    void planPick(World &world);
    void planGrasp(World &world);
    /** Carries the cube in the right hand from above `from` (x, y) to where it goes, and lets go.
     */
    void planPlace(const World &world, const std::array<double, 3> &from, double pace);
    /** The wrist's yaw to grip `cube` by a pair of its faces, the roomier pair. */
    double graspYaw(const World &world, int cube) const;
    /** The room the fingers have around `cube` gripping at `yaw` (m; negative: none). */
    double fingerClearance(const World &world, int cube, double yaw) const;
    void planHold(World &world);
    void react(World &world, const Percept &percept);
    bool looksAt(Gripper hand, double t) const;
    /** The cubes in the container (within its walls, up to a cube above its rim). */
    std::vector<int> cubesIn(const World &world) const;
    /** Whether the picking hand lets go above the container this step. */
    bool releasesIntoContainer(const World &world) const;
    std::array<double, 3> placePoint(const World &world);

    Task m_task;
    Random m_random;
    bool m_reactive;
    Variant m_variant;
    double m_reactionTime;
    HandPlan m_right{Gripper::Right};
    HandPlan m_left{Gripper::Left};
    std::array<HandState, 2> m_hands{};
    std::deque<Percept> m_percepts;
    int m_target = -1; ///< the cube the right hand is reaching for, until it descends

    // Bimanual: the holding hand's state.
    enum class Hold
    {
        Acquire,
        Holding,
        SetDown,
        Dropped
    } m_hold = Hold::Acquire;
    double m_holdStart = 0.0;
    double m_holdGrip = 0.0;    ///< the grip last chosen (N), from which it drifts
    double m_gripPerLoad = 1.0; ///< grip over the load it holds, as chosen for the container
    int m_carried = -1;         ///< the cube the picking hand took last
    double m_lastRightGrip = 0.0;
    bool m_rightOpens = false; ///< the picking hand began to open this step
    double m_droppedAt = 0.0;
    std::array<double, 3> m_holdPos{};
    std::array<double, 2> m_wobblePhase{};
};

} // namespace semhap
