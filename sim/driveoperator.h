// SPDX-License-Identifier: MIT
#pragma once

#include "handcommand.h"
#include "operator.h"
#include "world.h"

#include <array>
#include <mutex>
#include <optional>

namespace semhap {

/**
 * The pose-and-grip input: whatever drives the grippers from outside — the studio's
 * keyboard and mouse, a VR or motion-capture rig over the network — sets each hand's
 * wrist target and grip here, from any thread; act() applies the latest on the simulation
 * thread. A command being written while the simulation steps is applied on the next step:
 * the simulation never waits for the input.
 */
class DriveOperator : public Operator
{
public:
    QString name() const override { return QStringLiteral("drive"); }
    void act(World &world) override;

    /** Sets where `hand`'s wrist should be. Thread-safe. */
    void setTarget(Gripper hand, const Pose &target);
    /** Sets `hand`'s total grip force (N; negative opens). Thread-safe. */
    void setGrip(Gripper hand, double force);
    /** Sets what `command` says: its hand's target and grip. Thread-safe. */
    void setCommand(const HandCommand &command);

private:
    /** What one hand was last told; a part never set leaves the world's as it is. */
    struct Update
    {
        std::optional<Pose> target;
        std::optional<double> grip;
    };

    std::mutex m_mutex;
    std::array<Update, 2> m_pending{};
    std::array<Update, 2> m_current{};
};

/**
 * Each hand's target and grip as the world has them now (none for a hand the scene lacks):
 * driving starts there, so the grippers do not jump. Read the world on the thread that
 * steps it, or while it is paused.
 */
std::array<std::optional<HandCommand>, 2> currentCommands(const World &world);

} // namespace semhap
