// SPDX-License-Identifier: MIT
#pragma once

#include "handplan.h"
#include "operator.h"
#include "random.h"

#include <deque>

namespace semhap {

/**
 * A person wiping a plate (the dish_wiping scene, sim/README.md): the left hand holds the
 * plate's rim, the right wipes it with the sponge lane by lane in strokes across, pressing by
 * where it puts the wrist — its intended press, its eye's estimate of the plate's height, its
 * pace and a tremor of the press vary, seeded. It sees a broken plate, lets go, and waits for
 * the next one. Without feedback it cannot notice the sponge's holder stiffening.
 *
 * Reactive, it acts on what it feels `reactionTime` later: a confirmation (the sponge
 * engaged) ends the settling pause before a stroke; a warning (the press near the plate's
 * limit) eases off by 30 % of the press now, and it presses 30 % less from then on.
 */
class WipingOperator : public Operator
{
public:
    WipingOperator(const World &world, std::uint64_t seed, bool reactive, double reactionTime);

    QString name() const override;
    void act(World &world) override;
    /**
     * Starts over from where the hands are: the sponge rises clear of the plate and the next
     * lane is visited afresh; the left hand takes the plate again (unless it broke).
     */
    void engage(const World &world) override;
    void feel(Gripper hand, const Feeling &feeling, double t) override;

private:
    struct Segment
    {
        std::array<double, 3> to{};
        double seconds = 0.0;
        bool pressing = false; ///< on the plate: the press trembles
        bool settle = false;   ///< the pause on the plate before the strokes
    };
    struct Percept
    {
        double due;
        bool warning; ///< else a confirmation
    };

    /** Queues one visit of the next lane: reach, press down, settle, strokes, lift. */
    void planLane(const World &world);
    /** The nominal wrist position now; advances through finished segments. */
    std::array<double, 3> follow(double t);
    void react(const Percept &percept);
    /** Lets go of a broken plate and waits above; takes the next plate once it is there. */
    bool handleBrokenPlate(World &world);

    Random m_random;
    bool m_reactive;
    double m_reactionTime;
    int m_plate = -1;
    double m_reach = 0.0; ///< from the wrist down to the sponge's face, at rest (m)
    HandPlan m_left{Gripper::Left};
    double m_holdGrip = 0.0; ///< the left hand's grip on the plate (N)
    std::deque<Segment> m_path;
    bool m_segmentStarted = false;
    double m_segmentStart = 0.0;
    std::array<double, 3> m_from{};
    std::array<double, 3> m_pos{};
    int m_lane = 0;
    double m_side = -1.0;      ///< where the next lane's strokes begin, -1 or 1 along x
    double m_depth = 0.0;      ///< the press this lane visit was planned with (m)
    double m_pressScale = 1.0; ///< the reactive person's learned lightening of its press
    double m_ease = 0.0;       ///< the reactive person's ease-off this visit (m, up)
    double m_easeTarget = 0.0;
    double m_tremorPhase = 0.0;
    bool m_plateOut = false;   ///< the plate broke: waiting for the next
    double m_plateBack = -1.0; ///< when the next plate was taken, -1: not yet
    std::deque<Percept> m_percepts;
    std::array<double, 2> m_lastFelt{-1e9, -1e9}; ///< confirmation, warning
};

} // namespace semhap
