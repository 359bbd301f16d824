// SPDX-License-Identifier: MIT
#include "driveoperator.h"

#include <algorithm>
#include <cmath>

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
    const double now = world.time();
    const double dt = world.timestep();
    // Never wait for the input's thread: if it is writing, use what came before.
    if (m_mutex.try_lock()) {
        for (size_t hand = 0; hand < 2; ++hand) {
            Update &pending = m_pending[hand];
            Update &current = m_current[hand];
            if (pending.target && world.hasGripper(Gripper(hand))) {
                // Glide from where the target is now to the new one over the time since the
                // last command, so an input that updates ten times a second moves as
                // smoothly as one at sixty.
                // A command after a pause in the input (the first, or the first after the
                // run's own operator drove) starts from where the world's target is now.
                Glide &glide = m_glide[hand];
                const bool following = glide.started && now - glide.start <= MaxGlide;
                glide.from = following ? glide.at(now) : world.target(Gripper(hand));
                glide.to = *pending.target;
                glide.span = following ? std::max(now - glide.start, dt) : dt;
                glide.start = now;
                glide.started = true;
                current.target = pending.target;
            }
            if (pending.grip)
                current.grip = pending.grip;
            pending = Update();
        }
        m_mutex.unlock();
    }
    std::array<DriveStatus, 2> status{};
    for (Gripper hand : {Gripper::Left, Gripper::Right}) {
        const Update &update = m_current[size_t(hand)];
        if (!world.hasGripper(hand))
            continue;
        if (update.target) {
            DriveStatus &out = status[size_t(hand)];
            out.driven = true;
            out.target = m_glide[size_t(hand)].at(now + dt);
            // The soft landing: coming down, the target slows as the gap below closes.
            const double was = world.target(hand).pos[2];
            const std::optional<double> gap = world.clearanceBelow(hand);
            if (gap && out.target.pos[2] < was) {
                const double speed = LandingSpeed + *gap / LandingTime;
                out.target.pos[2] = std::max(out.target.pos[2], was - speed * dt);
            }
            out.floor = guard(world, hand, out.target.pos[2]);
            if (out.floor)
                out.target.pos[2] = std::max(out.target.pos[2], *out.floor);
            out.surface = world.surfaceBelow(hand, out.target.pos);
            world.setTarget(hand, out.target);
        }
        if (update.grip) {
            DriveStatus &out = status[size_t(hand)];
            out.gripCommand = *update.grip;
            out.grip = guardedGrip(world, hand, *update.grip);
            out.squeezing = m_squeezing[size_t(hand)];
            world.setGrip(hand, *out.grip);
        }
    }
    // The readers (the viewport, at display rate) take this lock briefly; a step that finds
    // it taken keeps the previous status rather than wait.
    if (m_statusMutex.try_lock()) {
        m_status = status;
        m_statusMutex.unlock();
    }
}

void DriveOperator::engage(const World &)
{
    // What the last drive left is stale: its command would pull a hand back to where the user
    // left it, its floor would hold a target at a height the run's operator has since left. The
    // input's next command (the studio sends where the hands are now) starts afresh.
    m_current = {};
    m_glide = {};
    m_floor = {};
    m_quiet = {};
    m_squeezing = {};
    m_liftedOff = {};
}

Pose DriveOperator::Glide::at(double t) const
{
    const double f = span > 0 ? std::clamp((t - start) / span, 0.0, 1.0) : 1.0;
    if (f >= 1.0)
        return to; // exactly what was asked, not what rounding makes of it
    Pose pose = to;
    for (size_t axis = 0; axis < 3; ++axis)
        pose.pos[axis] = from.pos[axis] + (to.pos[axis] - from.pos[axis]) * f;
    // Normalised linear interpolation, the short way round: the turns between two commands
    // are small.
    const double dot = from.quat[0] * to.quat[0] + from.quat[1] * to.quat[1] +
                       from.quat[2] * to.quat[2] + from.quat[3] * to.quat[3];
    const double sign = dot < 0 ? -1.0 : 1.0;
    double norm = 0.0;
    for (size_t i = 0; i < 4; ++i) {
        pose.quat[i] = from.quat[i] + (sign * to.quat[i] - from.quat[i]) * f;
        norm += pose.quat[i] * pose.quat[i];
    }
    for (double &q : pose.quat)
        q /= std::sqrt(norm);
    return pose;
}

std::optional<double> DriveOperator::guard(const World &world, Gripper hand, double targetZ)
{
    const size_t index = size_t(hand);
    std::optional<double> &floor = m_floor[index];
    const double support = world.supportForce(hand);
    const double wrist = world.gripperPose(hand).pos[2];
    const double dt = world.timestep();
    if (floor) {
        // The user lifts: a target above the wrist and the floor is free again. (Not only
        // "above the floor": a drive holding its target on an older floor is not lifting;
        // nor is one holding it on a floor lifted off for a close.)
        if (targetZ > std::max(wrist, *floor) + GuardRelease)
            floor.reset();
        else
            m_quiet[index] = support < GuardForce ? m_quiet[index] + dt : 0.0;
    }
    if (!floor && support > GuardForce && targetZ < wrist) {
        floor = wrist;
        m_quiet[index] = 0.0;
    }
    // A closed or closing hand hovers over what it rested on: pressed on it, the pads
    // dragged over it and met the cube pinned between them and the table, 100-220 N in a
    // step. It lifts off once as the close begins, then settles where nothing pushes.
    const Update &update = m_current[index];
    const bool gripping = update.grip && *update.grip > 0;
    if (floor && gripping && !m_liftedOff[index])
        *floor += LiftOff;
    m_liftedOff[index] = gripping && floor;
    if (floor) {
        // Hold the push near GuardPush; when nothing has pushed back for a while (the cube
        // below broke or was taken), go on down, but only at the approach speed.
        if (!gripping && m_quiet[index] > GuardQuiet)
            *floor -= GuardApproach * dt;
        else
            *floor += (support - (gripping ? 0.0 : GuardPush)) * GuardRate * dt;
    }
    return floor;
}

double DriveOperator::guardedGrip(const World &world, Gripper hand, double command)
{
    bool &squeezing = m_squeezing[size_t(hand)];
    if (command <= 0) {
        squeezing = false;
        return command;
    }
    squeezing = squeezing || world.objectBetween(hand) >= 0;
    if (squeezing)
        return std::min(command, world.grip(hand) + SqueezeRate * world.timestep());
    const double approach = world.closingForce(hand, ClosingSpeed);
    return approach > 0 ? std::min(command, approach) : command;
}

DriveStatus DriveOperator::status(Gripper hand) const
{
    const std::lock_guard<std::mutex> lock(m_statusMutex);
    return m_status[size_t(hand)];
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
