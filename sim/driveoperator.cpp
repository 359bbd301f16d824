// SPDX-License-Identifier: MIT
#include "driveoperator.h"

namespace semhap {

void DriveOperator::setTarget(Gripper hand, const Pose &target)
{
    const std::lock_guard<std::mutex> lock(m_mutex);
    m_pending[size_t(hand)].target = target;
}

void DriveOperator::setGrip(Gripper hand, double force)
{
    const std::lock_guard<std::mutex> lock(m_mutex);
    m_pending[size_t(hand)].grip = force;
}

void DriveOperator::setCommand(const HandCommand &command)
{
    const std::lock_guard<std::mutex> lock(m_mutex);
    m_pending[size_t(command.hand)] = {command.target, command.grip};
}

void DriveOperator::act(World &world)
{
    // Never wait for the input's thread: if it is writing, use what came before.
    if (m_mutex.try_lock()) {
        for (size_t hand = 0; hand < 2; ++hand) {
            Update &pending = m_pending[hand];
            Update &current = m_current[hand];
            if (pending.target)
                current.target = pending.target;
            if (pending.grip)
                current.grip = pending.grip;
            pending = Update();
        }
        m_mutex.unlock();
    }
    for (Gripper hand : {Gripper::Left, Gripper::Right}) {
        const Update &update = m_current[size_t(hand)];
        if (!world.hasGripper(hand))
            continue;
        if (update.target)
            world.setTarget(hand, *update.target);
        if (update.grip)
            world.setGrip(hand, *update.grip);
    }
}

std::array<std::optional<HandCommand>, 2> currentCommands(const World &world)
{
    std::array<std::optional<HandCommand>, 2> commands;
    for (Gripper hand : {Gripper::Left, Gripper::Right}) {
        if (world.hasGripper(hand))
            commands[size_t(hand)] = HandCommand{0.0, hand, world.target(hand), world.grip(hand)};
    }
    return commands;
}

} // namespace semhap
