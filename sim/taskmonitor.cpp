// SPDX-License-Identifier: MIT
#include "taskmonitor.h"

#include "perception.h"

#include <cmath>

namespace semhap {

namespace {

// Steps a grasped object must be out of the fingertips before the grasp counts as over.
constexpr int GraspLostSteps = 25;
// An object counts as come to rest below this speed (m/s).
constexpr double AtRest = 0.05;
// The container is lost once its fingertips have not held it for this long (s) and it
// has fallen this far (m) below where it was held.
constexpr double LostAfter = 0.25;
constexpr double FallenBy = 0.02;

double speed(const std::array<double, 3> &v)
{
    return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

QJsonValue mean(double sum, double count)
{
    return count > 0 ? QJsonValue(sum / count) : QJsonValue(QJsonValue::Null);
}

} // namespace

TaskMonitor::TaskMonitor(const World &world) : m_transferred(world.objects().size(), false)
{
    m_hasPlace = world.region(QStringLiteral("place"), &m_place);
    m_container = world.objectIndex(QStringLiteral("container"));
    if (m_container >= 0 && !world.region(QStringLiteral("home"), &m_home))
        m_container = -1;
}

void TaskMonitor::observe(World &world)
{
    for (const Fracture &fracture : world.fractures()) {
        ++m_broken;
        if (m_lastFelt >= 0 && fracture.t - m_lastFelt <= Perception::PulseGap) {
            ++m_warnedBreaks;
            m_leadTimeSum += fracture.t - m_warningSince;
        }
    }
    observeGrasp(world);
    observeTransfers(world);
    if (m_container >= 0)
        observeContainer(world);
}

void TaskMonitor::setWarningFelt(Gripper hand, bool felt, double t)
{
    // Breaks happen in the picking (right) hand; its warnings are the ones that count. A
    // pulsed warning (Geiger, 5 Hz) is one warning while its pulses keep coming.
    if (hand != Gripper::Right || !felt)
        return;
    if (m_lastFelt < 0 || t - m_lastFelt > Perception::PulseGap)
        m_warningSince = t;
    m_lastFelt = t;
}

void TaskMonitor::observeGrasp(World &world)
{
    if (!world.hasGripper(Gripper::Right))
        return;
    const ContactFrame &frame = world.frame(Gripper::Right);
    int held = -1;
    if (frame.left.actor >= 0 && frame.left.actor == frame.right.actor) {
        for (size_t i = 0; i < world.objects().size(); ++i) {
            if (world.objects()[i].actor == frame.left.actor && int(i) != m_container)
                held = int(i);
        }
    }
    // A grasp ends only once the object has been out of both fingertips for a moment: an
    // object shifting in the grip loses a fingertip for a step or two.
    if (held >= 0)
        m_lostSteps = 0;
    else if (m_grasped >= 0 && ++m_lostSteps < GraspLostSteps)
        held = m_grasped;
    if (held != m_grasped && m_grasped >= 0) {
        // A grasp ended. Unless the hand was letting go or the object broke, it slipped.
        m_peakSum += m_peak;
        if (world.grip(Gripper::Right) > 0 && !world.objects()[size_t(m_grasped)].broken)
            ++m_dropped;
    }
    if (held >= 0 && held != m_grasped) {
        ++m_grasps;
        m_peak = 0.0;
    }
    if (held >= 0) {
        m_graspForceSum += frame.totalForce();
        ++m_graspSteps;
        m_peak = std::max(m_peak, frame.totalForce());
    }
    m_grasped = held;
}

void TaskMonitor::observeTransfers(const World &world)
{
    std::array<double, 3> container{};
    const SceneObject *walls = m_container >= 0 ? &world.objects()[size_t(m_container)] : nullptr;
    if (walls)
        container = world.objectPosition(m_container);
    for (size_t i = 0; i < world.objects().size(); ++i) {
        const SceneObject &object = world.objects()[i];
        if (m_transferred[i] || object.broken || int(i) == m_grasped || int(i) == m_container)
            continue;
        const auto pos = world.objectPosition(int(i));
        bool arrived = false;
        if (m_container >= 0) {
            // Inside the held container (within its walls, above its floor), swaying with it.
            arrived = m_containerHeld && std::abs(pos[0] - container[0]) < walls->upper[0] &&
                      std::abs(pos[1] - container[1]) < walls->upper[1] && pos[2] > container[2] &&
                      pos[2] < container[2] + walls->upper[2];
        } else if (m_hasPlace) {
            arrived = m_place.contains(pos) && speed(world.objectVelocity(int(i))) < AtRest;
        }
        if (arrived) {
            m_transferred[i] = true;
            ++m_transfers;
        }
    }
}

void TaskMonitor::observeContainer(World &world)
{
    const double t = world.time();
    const int actor = world.objects()[size_t(m_container)].actor;
    const ContactFrame &frame = world.frame(Gripper::Left);
    const bool held = frame.left.actor == actor && frame.right.actor == actor;
    const double z = world.objectPosition(m_container)[2];
    if (m_containerDown) {
        if (t - m_containerDroppedAt >= RespawnPenalty) {
            world.placeObject(m_container, m_home.center);
            m_containerDown = false;
        }
        return;
    }
    if (held) {
        // The highest it was held: a slipping container slides down between the fingertips
        // before it leaves them.
        m_heldHeight = m_containerHeld ? std::max(m_heldHeight, z) : z;
        m_containerHeld = true;
        m_containerLostAt = -1.0;
        return;
    }
    if (!m_containerHeld)
        return;
    if (m_containerLostAt < 0)
        m_containerLostAt = t;
    if (t - m_containerLostAt >= LostAfter && z < m_heldHeight - FallenBy) {
        ++m_containersDropped;
        m_containerHeld = false;
        m_containerDown = true;
        m_containerDroppedAt = t;
    }
}

QJsonObject TaskMonitor::metrics() const
{
    QJsonObject metrics{
        {QStringLiteral("cubes_transferred"), m_transfers},
        {QStringLiteral("cubes_dropped"), m_dropped},
        {QStringLiteral("cubes_broken"), m_broken},
        {QStringLiteral("grasps"), m_grasps},
        {QStringLiteral("average_grasp_force"), mean(m_graspForceSum, double(m_graspSteps))},
        {QStringLiteral("grasps_per_transfer"), mean(m_grasps, m_transfers)},
        {QStringLiteral("average_peak_grasp_force"),
         mean(m_peakSum + (m_grasped >= 0 ? m_peak : 0.0), m_grasps)},
        {QStringLiteral("warning_lead_time"), mean(m_leadTimeSum, m_warnedBreaks)},
        {QStringLiteral("breaks_warned_share"), mean(m_warnedBreaks, m_broken)},
    };
    if (m_container >= 0) {
        metrics.insert(QStringLiteral("containers_dropped"), m_containersDropped);
        metrics.insert(QStringLiteral("transfers_per_container_cycle"),
                       double(m_transfers) / (m_containersDropped + 1));
    }
    return metrics;
}

} // namespace semhap
