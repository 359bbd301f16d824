// SPDX-License-Identifier: MIT
#include "manualoperator.h"

namespace semhap {

void ManualOperator::setTarget(Gripper hand, const Pose &target)
{
    const std::lock_guard<std::mutex> lock(m_mutex);
    m_pending[size_t(hand)].hasTarget = true;
    m_pending[size_t(hand)].target = target;
}

void ManualOperator::setGrip(Gripper hand, double force)
{
    const std::lock_guard<std::mutex> lock(m_mutex);
    m_pending[size_t(hand)].hasGrip = true;
    m_pending[size_t(hand)].grip = force;
}

void ManualOperator::act(World &world)
{
    // Never wait for the input's thread: if it is writing, use what came before.
    if (m_mutex.try_lock()) {
        for (size_t hand = 0; hand < 2; ++hand) {
            Command &pending = m_pending[hand];
            Command &current = m_current[hand];
            if (pending.hasTarget)
                current.target = pending.target;
            if (pending.hasGrip)
                current.grip = pending.grip;
            current.hasTarget = current.hasTarget || pending.hasTarget;
            current.hasGrip = current.hasGrip || pending.hasGrip;
            pending = Command();
        }
        m_mutex.unlock();
    }
    for (Gripper hand : {Gripper::Left, Gripper::Right}) {
        const Command &command = m_current[size_t(hand)];
        if (!world.hasGripper(hand))
            continue;
        if (command.hasTarget)
            world.setTarget(hand, command.target);
        if (command.hasGrip)
            world.setGrip(hand, command.grip);
    }
}

} // namespace semhap
