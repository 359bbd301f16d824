// SPDX-License-Identifier: MIT
#include "insertionoperator.h"

#include "insertiontask.h"
#include "perception.h"
#include "world.h"

#include <algorithm>
#include <cmath>

namespace semhap {

namespace {

// Heights of the wrist (m) carrying, and of the pads' centre above a standing plug's centre
// when grasping it (14 mm: the pads' lowest taxels then stay above the port's face when the
// plug is seated). Where the pads are below the wrist is the gripper's (World::padDrop).
constexpr double CarryHeight = 0.2;
constexpr double GraspAbove = 0.014;
// The plug's width across the grip (m; 12 x 4.5 mm, taken by its wide faces).
constexpr double PlugWidth = 0.0045;
// How far above the port's face the tip is held while aligning (m).
constexpr double Hover = 0.015;
// The eye's error above the port (sim/README.md, "usb_insertion"): after the carry, turned
// by N(0, 0.1 rad) and off by N(0, 2 mm) per axis; corrections shrink it with this time
// constant towards a residual of N(0, 0.025 rad) and N(0, 0.25 mm) per axis.
constexpr double YawError = 0.1;
constexpr double YawResidual = 0.025;
constexpr double OffsetError = 0.002;
constexpr double OffsetResidual = 0.00025;
constexpr double CorrectionTime = 0.5;
// Scripted: it aligns for this long (s, uniform) before going in.
constexpr double MinAlignTime = 0.8;
constexpr double MaxAlignTime = 2.0;
// Reactive: a squeeze felt this soon after aligning began may still be the grasp's fading
// (air.squeeze deflates in 0.5 s).
constexpr double FadeWait = 0.6;
// Going in: the tip lowered at this speed (m/s), the wrist's target never more than PushLead
// below the wrist: a gentle push, about 5 N on a plug held on the face (measured).
constexpr double InsertSpeed = 0.01;
constexpr double BackSpeed = 0.02;
constexpr double PushLead = 0.0001;
// Stuck: the tip has not gone 0.3 mm deeper for this long (s, times the pace).
constexpr double StuckTime = 0.6;
constexpr double Progress = 0.0003;
// Out of the fingertips this long (s), the plug was dropped.
constexpr double DropTime = 0.1;

double yawOf(const std::array<double, 4> &q)
{
    // The direction of the frame's x axis in the horizontal plane.
    return std::atan2(2 * (q[1] * q[2] + q[0] * q[3]), 1 - 2 * (q[2] * q[2] + q[3] * q[3]));
}

/** `v` turned about the vertical by `yaw`. */
std::array<double, 3> turned(const std::array<double, 3> &v, double yaw)
{
    const double c = std::cos(yaw);
    const double s = std::sin(yaw);
    return {c * v[0] - s * v[1], s * v[0] + c * v[1], v[2]};
}

/** How deep the plug's tip is below the port's face (m; negative above it). */
double depthOf(const World &world)
{
    const Pose tip = *world.sitePose(QStringLiteral("plug.tip"));
    const Pose mouth = *world.sitePose(QStringLiteral("port.mouth"));
    return mouth.pos[2] - tip.pos[2];
}

/** How far the plug's tip is from the port's axis (m). */
double lateralOf(const World &world)
{
    const Pose tip = *world.sitePose(QStringLiteral("plug.tip"));
    const Pose mouth = *world.sitePose(QStringLiteral("port.mouth"));
    return std::hypot(tip.pos[0] - mouth.pos[0], tip.pos[1] - mouth.pos[1]);
}

} // namespace

InsertionOperator::InsertionOperator(std::uint64_t seed, bool reactive, double reactionTime)
    : m_random(seed), m_reactive(reactive), m_reactionTime(reactionTime)
{}

QString InsertionOperator::name() const
{
    return m_reactive ? QStringLiteral("reactive") : QStringLiteral("scripted");
}

void InsertionOperator::act(World &world)
{
    const double t = world.time();
    if (m_plug < 0)
        m_plug = world.objectIndex(QStringLiteral("plug"));
    while (!m_percepts.empty() && m_percepts.front().due <= t) {
        react(world, m_percepts.front());
        m_percepts.pop_front();
    }
    const bool carrying = m_phase == Phase::Carrying || m_phase == Phase::Aligning ||
                          m_phase == Phase::Inserting || m_phase == Phase::Backing;
    if (carrying) {
        if (world.isBetween(Gripper::Right, m_plug)) {
            m_lostSince = -1.0;
        } else if (m_lostSince < 0) {
            m_lostSince = t;
        } else if (t - m_lostSince > DropTime) {
            // Dropped: open, rise, and wait for it to be back on the table.
            m_hand.clear();
            m_hand.grip(HandPlan::OpenGrip, 0.1);
            Pose wrist = world.target(Gripper::Right);
            m_hand.move({wrist.pos[0], wrist.pos[1], CarryHeight}, 0.6);
            m_phase = Phase::Idle;
            m_lostSince = -1.0;
        }
    }
    switch (m_phase) {
    case Phase::Idle:
        if (m_hand.isIdle())
            planPick(world);
        break;
    case Phase::Picking:
        if (!m_hand.isIdle())
            break;
        if (!world.isBetween(Gripper::Right, m_plug)) {
            m_hand.grip(HandPlan::OpenGrip, 0.1);
            m_phase = Phase::Idle;
            break;
        }
        {
            // Where the plug sits in the hand, as the eye sees it; then over to the port.
            lookAtHand(world);
            m_yawError0 = m_random.normal(0.0, YawError);
            m_offset0 = {m_random.normal(0.0, OffsetError), m_random.normal(0.0, OffsetError)};
            m_yawResidual = m_random.normal(0.0, YawResidual);
            m_offsetResidual = {m_random.normal(0.0, OffsetResidual),
                                m_random.normal(0.0, OffsetResidual)};
            m_lookedAt = t;
            // The carry: turned and placed with the first error, which holds until it aligns.
            Pose target = world.target(Gripper::Right);
            aim(world, Hover);
            const Pose aimed = world.target(Gripper::Right);
            target.quat = aimed.quat;
            world.setTarget(Gripper::Right, target);
            m_hand.move({aimed.pos[0], aimed.pos[1], CarryHeight}, 0.8 * m_pace);
            m_hand.move(aimed.pos, 0.8 * m_pace);
            m_phase = Phase::Carrying;
        }
        break;
    case Phase::Carrying:
        if (m_hand.isIdle())
            startAligning(world, t, false);
        break;
    case Phase::Aligning:
        aim(world, Hover);
        if (t - m_since >= m_alignTime)
            startInserting(world);
        break;
    case Phase::Inserting: {
        const double depth = depthOf(world);
        if (InsertionTask::isSeated(depth, lateralOf(world))) {
            m_hand.clear();
            m_hand.grip(HandPlan::OpenGrip, 0.2);
            m_hand.wait(0.2);
            const Pose wrist = world.target(Gripper::Right);
            m_hand.move({wrist.pos[0], wrist.pos[1], CarryHeight}, 0.8 * m_pace);
            m_phase = Phase::Leaving;
            break;
        }
        m_command =
            std::min(m_command + InsertSpeed * world.timestep(), InsertionTask::FullDepth + 0.001);
        const double wristZ = world.gripperPose(Gripper::Right).pos[2];
        aim(world, -m_command);
        Pose target = world.target(Gripper::Right);
        target.pos[2] = std::max(target.pos[2], wristZ - PushLead);
        world.setTarget(Gripper::Right, target);
        if (depth > m_bestDepth + Progress) {
            m_bestDepth = depth;
            m_progressAt = t;
        } else if (t - m_progressAt > StuckTime * m_pace && m_command > depth + 0.001) {
            // It does not go in: back off and look again.
            startBacking(depth);
        }
        break;
    }
    case Phase::Backing:
        m_command = std::max(m_command - BackSpeed * world.timestep(), -Hover);
        aim(world, -m_command);
        if (m_command <= -Hover)
            startAligning(world, t, true);
        break;
    case Phase::Leaving:
        if (m_hand.isIdle())
            m_phase = Phase::Idle;
        break;
    }
    m_hand.apply(world);
}

void InsertionOperator::engage(const World &world)
{
    // The plan and the phase from before the hand-over are stale: resumed, the wrist would jump
    // to where they left off.
    m_hand.clear();
    m_percepts.clear();
    m_pending = {};
    m_lostSince = -1.0;
    const int plug = world.objectIndex(QStringLiteral("plug"));
    // A plug the user seated is let go of, as after an insertion.
    const bool held = world.isBetween(Gripper::Right, plug) &&
                      !InsertionTask::isSeated(depthOf(world), lateralOf(world));
    if (!held)
        m_hand.grip(HandPlan::OpenGrip, 0.1);
    const auto wrist = world.target(Gripper::Right).pos;
    if (wrist[2] < CarryHeight)
        m_hand.move({wrist[0], wrist[1], CarryHeight}, 0.8);
    // Picking ends, once the hand is idle, by looking at the plug in hand and carrying it over.
    m_phase = held ? Phase::Picking : Phase::Leaving;
}

void InsertionOperator::planPick(World &world)
{
    // A plug standing on the table, at rest, not in the port: take it from above, the
    // fingers across its thickness.
    const Pose plug = world.objectPose(m_plug);
    const double upright = 1 - 2 * (plug.quat[1] * plug.quat[1] + plug.quat[2] * plug.quat[2]);
    const auto v = world.objectVelocity(m_plug);
    const bool resting = std::hypot(v[0], v[1], v[2]) < 0.01 && upright > 0.95 &&
                         lateralOf(world) > InsertionTask::InOpening;
    if (!resting) {
        m_hand.wait(0.2);
        return;
    }
    m_pace = m_random.uniform(0.85, 1.2);
    Pose wrist = world.target(Gripper::Right);
    wrist.quat = yawQuaternion(yawOf(plug.quat));
    world.setTarget(Gripper::Right, wrist);
    const double x = plug.pos[0] + m_random.normal(0.0, 0.0005);
    const double y = plug.pos[1] + m_random.normal(0.0, 0.0005);
    const double force = std::clamp(m_random.normal(20.0, 4.0), 10.0, 30.0);
    m_hand.grip(HandPlan::OpenGrip, 0.1);
    m_hand.move({x, y, CarryHeight}, 0.9 * m_pace);
    m_hand.move({x, y, plug.pos[2] + GraspAbove + world.padDrop(Gripper::Right, PlugWidth)},
                0.6 * m_pace);
    m_hand.wait(0.1);
    m_hand.grip(force, 0.5 * m_pace);
    m_hand.wait(0.2);
    m_hand.move({x, y, CarryHeight}, 0.6 * m_pace);
    m_phase = Phase::Picking;
}

void InsertionOperator::lookAtHand(const World &world)
{
    const Pose wrist = world.gripperPose(Gripper::Right);
    const Pose tip = *world.sitePose(QStringLiteral("plug.tip"));
    const double yaw = yawOf(wrist.quat);
    m_tipInHand = turned(
        {tip.pos[0] - wrist.pos[0], tip.pos[1] - wrist.pos[1], tip.pos[2] - wrist.pos[2]}, -yaw);
    m_plugYawInHand = yawOf(world.objectPose(m_plug).quat) - yaw;
}

void InsertionOperator::startAligning(World &world, double t, bool lookAgain)
{
    if (lookAgain) {
        // The plug may have shifted in the fingers when it met the face; shifted so far that
        // the fingers would meet the face before it is seated, it is let go of, to be taken
        // again from the table (the task puts a dropped plug back).
        lookAtHand(world);
        if (m_tipInHand[2] >
            -(world.padReach(Gripper::Right, PlugWidth) + InsertionTask::FullDepth)) {
            m_hand.clear();
            m_hand.grip(HandPlan::OpenGrip, 0.2);
            const Pose wrist = world.target(Gripper::Right);
            m_hand.move({wrist.pos[0], wrist.pos[1], CarryHeight}, 0.8);
            m_phase = Phase::Leaving;
            return;
        }
        // A fresh look: the error now is where the next corrections start from.
        const double decay = std::exp(-(t - m_lookedAt) / CorrectionTime);
        m_yawError0 = m_yawResidual + (m_yawError0 - m_yawResidual) * decay;
        for (size_t i = 0; i < 2; ++i)
            m_offset0[i] = m_offsetResidual[i] + (m_offset0[i] - m_offsetResidual[i]) * decay;
        m_yawResidual = m_random.normal(0.0, YawResidual);
        m_offsetResidual = {m_random.normal(0.0, OffsetResidual),
                            m_random.normal(0.0, OffsetResidual)};
        m_lookedAt = t;
    }
    if (m_phase != Phase::Aligning || !lookAgain)
        m_since = t;
    m_alignTime = m_random.uniform(MinAlignTime, MaxAlignTime) * m_pace;
    m_phase = Phase::Aligning;
    aim(world, Hover);
}

void InsertionOperator::startInserting(const World &world)
{
    m_phase = Phase::Inserting;
    m_since = world.time();
    m_command = -Hover;
    m_bestDepth = depthOf(world);
    m_progressAt = world.time();
}

void InsertionOperator::startBacking(double depth)
{
    // From where the tip is: the command may have run ahead of a plug stuck on the face.
    m_command = std::min(m_command, depth);
    m_phase = Phase::Backing;
}

void InsertionOperator::aim(World &world, double above)
{
    const double t = world.time();
    const double decay = std::exp(-(t - m_lookedAt) / CorrectionTime);
    const double yawError = m_yawResidual + (m_yawError0 - m_yawResidual) * decay;
    const Pose mouth = *world.sitePose(QStringLiteral("port.mouth"));
    const double yaw = yawOf(mouth.quat) - m_plugYawInHand + yawError;
    const auto tip = turned(m_tipInHand, yaw);
    Pose target;
    for (size_t i = 0; i < 2; ++i) {
        const double offset = m_offsetResidual[i] + (m_offset0[i] - m_offsetResidual[i]) * decay;
        target.pos[i] = mouth.pos[i] + offset - tip[i];
    }
    target.pos[2] = mouth.pos[2] + above - tip[2];
    target.quat = yawQuaternion(yaw);
    world.setTarget(Gripper::Right, target);
}

void InsertionOperator::feel(Gripper hand, const Feeling &feeling, double t)
{
    if (!m_reactive || hand != Gripper::Right)
        return;
    // One percept of each kind on its way at a time: what is felt meanwhile is the same cue.
    const std::array<bool, 2> felt{feeling.confirmation >= Perception::Noticeable,
                                   feeling.warning >= Perception::Noticeable};
    for (size_t kind = 0; kind < 2; ++kind) {
        if (felt[kind] && !m_pending[kind]) {
            m_percepts.push_back({t + m_reactionTime, kind == 1, t});
            m_pending[kind] = true;
        }
    }
}

void InsertionOperator::react(World &world, const Percept &percept)
{
    m_pending[percept.warning ? 1 : 0] = false;
    if (!percept.warning && m_phase == Phase::Aligning && percept.felt >= m_since + FadeWait) {
        startInserting(world);
    } else if (percept.warning && m_phase == Phase::Inserting && depthOf(world) < 0.0) {
        startBacking(depthOf(world));
    }
}

} // namespace semhap
