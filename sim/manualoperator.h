// SPDX-License-Identifier: MIT
#pragma once

#include "operator.h"
#include "world.h"

#include <array>
#include <mutex>

namespace semhap {

/**
 * The pose-and-grip input: whatever drives the grippers from outside — the studio's
 * keyboard and mouse, a VR or motion-capture rig over the network — sets each hand's
 * wrist target and grip here, from any thread; act() applies the latest on the simulation
 * thread. A command being written while the simulation steps is applied on the next step:
 * the simulation never waits for the input.
 */
class ManualOperator : public Operator
{
public:
    QString name() const override { return QStringLiteral("manual"); }
    void act(World &world) override;

    /** Sets where `hand`'s wrist should be. Thread-safe. */
    void setTarget(Gripper hand, const Pose &target);
    /** Sets `hand`'s total grip force (N; negative opens). Thread-safe. */
    void setGrip(Gripper hand, double force);

private:
    struct Command
    {
        bool hasTarget = false;
        Pose target;
        bool hasGrip = false;
        double grip = 0.0;
    };

    std::mutex m_mutex;
    std::array<Command, 2> m_pending{};
    std::array<Command, 2> m_current{};
};

} // namespace semhap
