// SPDX-License-Identifier: MIT
#include "stackingoperator.h"

#include "perception.h"
#include "stackingtask.h"
#include "world.h"

#include <algorithm>
#include <cmath>

namespace semhap {

namespace {

constexpr double Pi = 3.14159265358979323846;
// The wrist's height (m) reaching over the pile, and how far above a finished tower it
// rises (the task clears a finished tower once the hand is 8 cm above it).
constexpr double CarryHeight = 0.25;
constexpr double ClearAbove = 0.1;
// The grip people close on a wooden block with (N, both fingers): N(25, 12), 4 to 60.
constexpr double GripMean = 25.0;
constexpr double GripSd = 12.0;
constexpr double MaxGrip = 60.0;
constexpr double ClosingTime = 0.7;
// Where the eye puts the block over the tower: off its axis by N(0, 3 mm) per axis, its
// bottom N(4 mm, 3 mm) above the top (-2 to +15 mm: a little into it presses down).
constexpr double AimError = 0.003;
constexpr double GapMean = 0.004;
constexpr double GapSd = 0.003;
constexpr double MinGap = -0.002;
constexpr double MaxGap = 0.015;
// The last few centimetres down are slow: 3 cm in 0.6 s.
constexpr double Approach = 0.03;
// Out of the fingertips this long (s), the block was dropped.
constexpr double DropTime = 0.1;
// Reactive: a warning makes it squeeze this much harder, over this long.
constexpr double Squeeze = 1.5;
constexpr double SqueezeTime = 0.2;

/** The yaw that takes a block by a pair of its faces, folded into ±45 degrees. */
double graspYaw(const std::array<double, 4> &q)
{
    double yaw = std::atan2(2 * (q[0] * q[3] + q[1] * q[2]), 1 - 2 * (q[2] * q[2] + q[3] * q[3]));
    return yaw - (Pi / 2) * std::round(yaw / (Pi / 2));
}

} // namespace

StackingOperator::StackingOperator(std::uint64_t seed, bool reactive, double reactionTime)
    : m_random(seed), m_reactive(reactive), m_reactionTime(reactionTime)
{}

QString StackingOperator::name() const
{
    return m_reactive ? QStringLiteral("reactive") : QStringLiteral("scripted");
}

void StackingOperator::act(World &world)
{
    const double t = world.time();
    while (!m_warnings.empty() && m_warnings.front() <= t) {
        m_warnings.pop_front();
        if (m_phase == Phase::Carrying && m_grip > 0) {
            m_grip = std::min(m_grip * Squeeze, MaxGrip);
            m_hand.regrip(m_grip, SqueezeTime);
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
        if (world.isBetween(Gripper::Right, m_block)) {
            planCarry(world);
        } else {
            m_hand.grip(HandPlan::OpenGrip, 0.1);
            m_phase = Phase::Idle;
        }
        break;
    case Phase::Carrying:
        if (world.isBetween(Gripper::Right, m_block)) {
            m_lostSince = -1.0;
        } else if (m_lostSince < 0) {
            m_lostSince = t;
        } else if (t - m_lostSince > DropTime) {
            // Dropped: the task puts it back; open and go for the next.
            m_hand.clear();
            m_lostSince = -1.0;
            planLeave(world);
            break;
        }
        if (m_hand.isIdle())
            planLeave(world);
        break;
    case Phase::Leaving:
        if (m_hand.isIdle())
            m_phase = Phase::Idle;
        break;
    }
    m_hand.apply(world);
}

void StackingOperator::engage(const World &world)
{
    // The plan from before the hand-over is stale: resumed, the wrist would jump to where it
    // left off.
    m_hand.clear();
    m_warnings.clear();
    m_lostSince = -1.0;
    const int held = world.objectSqueezed(Gripper::Right);
    const std::vector<int> blocks = StackingTask::blocksOf(world);
    if (std::count(blocks.begin(), blocks.end(), held) > 0) {
        m_block = held;
        m_grip = std::max(world.grip(Gripper::Right), 4.0);
        planCarry(world);
        return;
    }
    planLeave(world);
}

void StackingOperator::planPick(World &world)
{
    // The topmost block at rest in the pile; none, or a finished tower still standing: wait.
    Region pick;
    world.region(QStringLiteral("pick"), &pick);
    const std::vector<int> blocks = StackingTask::blocksOf(world);
    int block = -1;
    for (int candidate : blocks) {
        const auto pos = world.objectPosition(candidate);
        const auto v = world.objectVelocity(candidate);
        if (world.objects()[size_t(candidate)].broken || !pick.contains(pos) ||
            std::hypot(v[0], v[1], v[2]) > 0.01)
            continue;
        if (block < 0 || pos[2] > world.objectPosition(block)[2] + 0.01)
            block = candidate;
    }
    if (block < 0 || int(StackingTask::tower(world, blocks).size()) >= StackingTask::Levels) {
        m_hand.wait(0.2);
        return;
    }
    m_block = block;
    m_pace = m_random.uniform(0.85, 1.2);
    m_grip = std::clamp(m_random.normal(GripMean, GripSd), 4.0, MaxGrip);
    const Pose pose = world.objectPose(block);
    Pose wrist = world.target(Gripper::Right);
    wrist.quat = yawQuaternion(graspYaw(pose.quat));
    world.setTarget(Gripper::Right, wrist);
    const double size = StackingTask::blockSize(world, block);
    m_hand.grip(HandPlan::OpenGrip, 0.1);
    m_hand.move({pose.pos[0], pose.pos[1], CarryHeight}, 0.9 * m_pace);
    m_hand.move({pose.pos[0], pose.pos[1], pose.pos[2] + world.padDrop(Gripper::Right, size)},
                0.6 * m_pace);
    m_hand.wait(0.1);
    m_hand.grip(m_grip, ClosingTime * m_pace);
    m_hand.wait(0.25);
    m_phase = Phase::Picking;
}

void StackingOperator::planCarry(const World &world)
{
    // What the eye sees now: the tower's top, and where the block sits in the hand.
    const std::vector<int> blocks = StackingTask::blocksOf(world);
    const double size = StackingTask::blockSize(world, m_block);
    const auto base = StackingTask::base(world);
    const double top = base[2] + double(StackingTask::tower(world, blocks).size()) * size;
    const auto wrist = world.target(Gripper::Right).pos;
    const auto block = world.objectPosition(m_block);
    const std::array<double, 3> inHand{block[0] - wrist[0], block[1] - wrist[1],
                                       block[2] - wrist[2]};
    const double gap = std::clamp(m_random.normal(GapMean, GapSd), MinGap, MaxGap);
    const double x = base[0] + m_random.normal(0.0, AimError) - inHand[0];
    const double y = base[1] + m_random.normal(0.0, AimError) - inHand[1];
    const double release = top + gap + size / 2 - inHand[2];
    const double carry = std::max(CarryHeight, release + Approach + 0.05);
    m_hand.move({wrist[0], wrist[1], carry}, 0.6 * m_pace);
    m_hand.move({x, y, carry}, 1.0 * m_pace);
    m_hand.move({x, y, release + Approach}, 0.5 * m_pace);
    m_hand.move({x, y, release}, 0.6 * m_pace);
    m_lostSince = -1.0;
    m_phase = Phase::Carrying;
}

void StackingOperator::planLeave(const World &world)
{
    // Open, and rise clear of a finished tower, so that the task can clear it.
    const auto wrist = world.target(Gripper::Right).pos;
    const double top = StackingTask::base(world)[2] +
                       StackingTask::Levels *
                           StackingTask::blockSize(world, StackingTask::blocksOf(world).front());
    m_hand.grip(HandPlan::OpenGrip, 0.15 * m_pace);
    m_hand.wait(0.3);
    m_hand.move({wrist[0], wrist[1], std::max(CarryHeight, top + ClearAbove)}, 0.6 * m_pace);
    m_grip = 0.0;
    m_phase = Phase::Leaving;
}

void StackingOperator::feel(Gripper hand, const Feeling &feeling, double t)
{
    if (!m_reactive || hand != Gripper::Right)
        return;
    // One warning on its way at a time: what is felt meanwhile is the same cue.
    if (feeling.warning >= Perception::Noticeable && m_warnings.empty())
        m_warnings.push_back(t + m_reactionTime);
}

} // namespace semhap
