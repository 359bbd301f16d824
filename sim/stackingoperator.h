// SPDX-License-Identifier: MIT
#pragma once

#include "handplan.h"
#include "operator.h"
#include "random.h"

#include <deque>

namespace semhap {

/**
 * Stacks block_stacking's blocks the way a person would (sim/README.md, "block_stacking"):
 * takes the topmost free block from the pile with a seeded grip, carries it over the tower,
 * and lets go of it where the eye judges the tower's top to be: off the axis by a seeded few
 * millimetres, and a seeded gap above the top (at times a little into it, pressing). A block
 * dropped on the way is left to the task, which puts it back; the hand goes for the next.
 *
 * `scripted` does this whatever it feels. `reactive` does the same, and squeezes harder
 * (half as hard again, up to 60 N) when it feels a warning with a block in hand,
 * `reactionTime` after it felt it. Without feedback the two are the same person.
 */
class StackingOperator : public Operator
{
public:
    StackingOperator(std::uint64_t seed, bool reactive, double reactionTime);

    QString name() const override;
    void act(World &world) override;
    /**
     * Starts over from where the hand is: a block in hand is carried to the tower, else the
     * hand opens and rises clear before taking the next one.
     */
    void engage(const World &world) override;
    void feel(Gripper hand, const Feeling &feeling, double t) override;

private:
    enum class Phase
    {
        Idle,     ///< waiting for a block in the pile (or a finished tower to be cleared)
        Picking,  ///< reaching, closing
        Carrying, ///< lifting, over the tower, down to where it lets go
        Leaving   ///< letting go, rising clear
    };

    void planPick(World &world);
    void planCarry(const World &world);
    void planLeave(const World &world);

    Random m_random;
    bool m_reactive;
    double m_reactionTime;
    HandPlan m_hand{Gripper::Right};
    std::deque<double> m_warnings; ///< when each warning felt is acted on
    Phase m_phase = Phase::Idle;
    int m_block = -1;
    double m_pace = 1.0;
    double m_grip = 0.0;       ///< the grip it closed with, or squeezed up to (N)
    double m_lostSince = -1.0; ///< when the carried block left the fingertips; -1: held
};

} // namespace semhap
