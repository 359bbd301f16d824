// SPDX-License-Identifier: MIT
#include "taskmonitor.h"

#include "perception.h"

#include <algorithm>
#include <cmath>

namespace semhap {

namespace {

// Steps a grasped object must be out of the fingertips before the grasp counts as over.
constexpr int GraspLostSteps = 25;
// How high (m) the hand must have lifted a grasp for its loss to be a drop.
constexpr double LiftedBy = 0.01;
// An object counts as come to rest below this speed (m/s).
constexpr double AtRest = 0.05;
// The container is lost once its fingertips have not held it for this long (s) and it
// has fallen this far (m) below where it was held.
constexpr double LostAfter = 0.25;
constexpr double FallenBy = 0.02;
// A slip episode: the container slides in the fingertips faster than SlipSpeed (m/s, its
// speed relative to the gripper smoothed over SlipSmoothing s), and is over once it has
// been slower for SlipQuiet s (or has left the fingertips).
constexpr double SlipSpeed = 0.005;
constexpr double SlipSmoothing = 0.02;
constexpr double SlipQuiet = 0.2;
// A container put down is emptied this long after the hand let go (s).
constexpr double SetDownSettle = 0.5;
// Cubes returned to the box go to where the scene started them, or this much higher per
// layer while that spot is taken (m).
constexpr double Layer = 0.052;
constexpr int Layers = 4;

double speed(const std::array<double, 3> &v)
{
    return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

QJsonValue mean(double sum, double count)
{
    return count > 0 ? QJsonValue(sum / count) : QJsonValue(QJsonValue::Null);
}

/** `p` in the frame of `pose`: R^T (p - pos), R from the unit quaternion (w, x, y, z). */
std::array<double, 3> toFrame(const Pose &pose, const std::array<double, 3> &p)
{
    const auto &[w, x, y, z] = pose.quat;
    const double r[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
                            {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
                            {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}};
    std::array<double, 3> d{p[0] - pose.pos[0], p[1] - pose.pos[1], p[2] - pose.pos[2]};
    std::array<double, 3> out{};
    for (size_t i = 0; i < 3; ++i)
        out[i] = r[0][i] * d[0] + r[1][i] * d[1] + r[2][i] * d[2];
    return out;
}

} // namespace

void TaskMonitor::Cue::feel(bool felt, double t)
{
    // A pulsed warning (Geiger, 5 Hz) is one cue while its pulses keep coming.
    if (!felt)
        return;
    if (!feltAt(t)) {
        since = t;
        ++onsets;
    }
    lastFelt = t;
}

bool TaskMonitor::Cue::feltAt(double t) const
{
    return lastFelt >= 0 && t - lastFelt <= Perception::PulseGap;
}

void TaskMonitor::Failures::add(double t, const Cue &warning, double reactionTime)
{
    ++count;
    if (!warning.feltAt(t))
        return;
    ++warned;
    leadTimeSum += t - warning.since;
    if (t - warning.since >= reactionTime)
        ++inTime;
}

QJsonValue TaskMonitor::Alarms::warnedByOnsetShare(double reactionTime, double horizon) const
{
    if (failures.empty())
        return QJsonValue();
    int warned = 0;
    for (double failure : failures) {
        // A new warning: one that began in the window, not one already on before it.
        warned += std::any_of(onsets.begin(), onsets.end(), [&](double onset) {
            return onset >= failure - horizon && onset <= failure - reactionTime;
        });
    }
    return double(warned) / double(failures.size());
}

QJsonValue TaskMonitor::Alarms::precision(double horizon, double end) const
{
    // An onset within the horizon of the run's end cannot be judged yet.
    int judged = 0;
    int answered = 0;
    for (double onset : onsets) {
        if (onset > end - horizon)
            continue;
        ++judged;
        answered += borneOut(onset, horizon) ? 1 : 0;
    }
    return judged ? QJsonValue(double(answered) / judged) : QJsonValue();
}

bool TaskMonitor::Alarms::borneOut(double onset, double horizon) const
{
    const auto follows = [&](double t) { return t >= onset && t <= onset + horizon; };
    return std::any_of(failures.begin(), failures.end(), follows) ||
           std::any_of(episodes.begin(), episodes.end(), follows);
}

std::optional<bool> TaskMonitor::warranted(Gripper hand, double onset, double t) const
{
    if (t < onset + m_horizon)
        return std::nullopt;
    return m_alarms[size_t(hand)].borneOut(onset, m_horizon);
}

QJsonValue TaskMonitor::Alarms::duty() const
{
    return held > 0 ? QJsonValue(warnedHeld / held) : QJsonValue();
}

TaskMonitor::TaskMonitor(const World &world, double reactionTime, double horizon)
    : m_reactionTime(reactionTime), m_horizon(horizon), m_inGrasp(world.objects().size(), false),
      m_transferred(world.objects().size(), false)
{
    m_hasPlace = world.region(QStringLiteral("place"), &m_place);
    m_hasPick = world.region(QStringLiteral("pick"), &m_pick);
    m_container = world.objectIndex(QStringLiteral("container"));
    if (m_container >= 0 && !world.region(QStringLiteral("home"), &m_home))
        m_container = -1;
}

void TaskMonitor::observe(World &world)
{
    // Breaks happen in the picking (right) hand; its warnings are the ones that count.
    for (const Fracture &fracture : world.fractures()) {
        m_breaks.add(fracture.t, m_warnings[size_t(Gripper::Right)], m_reactionTime);
        m_alarms[size_t(Gripper::Right)].failures.push_back(fracture.t);
    }
    m_time = world.time();
    observeGrasp(world);
    observeTransfers(world);
    // Before the refill, which puts the finished pile back in the box.
    observeCompletion(world);
    if (m_container >= 0)
        observeContainer(world);
    refill(world);
}

void TaskMonitor::feel(Gripper hand, const Feeling &feeling, double t)
{
    const auto felt = [](double band, double shown) {
        return std::max(band, shown) >= Perception::Noticeable;
    };
    Cue &warning = m_warnings[size_t(hand)];
    const int onsets = warning.onsets;
    warning.feel(felt(feeling.warning, feeling.shownWarning), t);
    if (warning.onsets > onsets)
        m_alarms[size_t(hand)].onsets.push_back(t);
    m_confirmations[size_t(hand)].feel(felt(feeling.confirmation, feeling.shownConfirmation), t);
}

void TaskMonitor::observeGrasp(World &world)
{
    if (!world.hasGripper(Gripper::Right))
        return;
    const ContactFrame &frame = world.frame(Gripper::Right);
    // Held: an object both fingertips squeeze, whatever else they touch harder (the table, the
    // cube beside it: which one a fingertip presses most flickers), the one already held first;
    // not one the closed fingertips rest on. Once held, touching it with both is enough.
    // A grasp ends only once the object has been out of both fingertips for a moment: an
    // object shifting in the grip loses a fingertip for a step or two (also while another
    // object is between them).
    int held = -1;
    if (m_grasped >= 0 && world.isBetween(Gripper::Right, m_grasped)) {
        held = m_grasped;
        m_lostSteps = 0;
    } else if (m_grasped >= 0 && ++m_lostSteps < GraspLostSteps) {
        held = m_grasped;
    } else {
        held = world.objectSqueezed(Gripper::Right);
        m_lostSteps = 0;
    }
    if (held == m_container)
        held = -1;
    // Pads closed on two cubes side by side hold both in one grasp: when one slips out, the
    // grasp goes on with the other, not a new one.
    const bool goesOn = m_grasped >= 0 && held >= 0 && m_inGrasp[size_t(held)];
    if (held != m_grasped && m_grasped >= 0) {
        // The object left the fingertips. It was dropped if the hand had lifted and still
        // gripped as hard as it had: not letting go (opening ramps the grip down), not
        // broken, not a cube the fingers slid off on the pile.
        const double grip = world.grip(Gripper::Right);
        const bool lifted = m_liftedBy >= LiftedBy;
        if (grip > 0 && grip >= m_graspGrip && lifted &&
            !world.objects()[size_t(m_grasped)].broken)
            ++m_dropped;
        if (!goesOn) {
            m_peakSum += m_peak;
            std::fill(m_inGrasp.begin(), m_inGrasp.end(), false);
        }
    }
    if (held >= 0) {
        for (size_t i = 0; i < m_inGrasp.size(); ++i)
            m_inGrasp[i] = m_inGrasp[i] || world.isBetween(Gripper::Right, int(i));
    }
    if (held >= 0 && held != m_grasped && !goesOn) {
        ++m_grasps;
        m_peak = 0.0;
        m_graspGrip = 0.0;
        m_graspHeight = world.gripperPose(Gripper::Right).pos[2];
        m_liftedBy = 0.0;
    }
    if (held >= 0) {
        m_graspForceSum += frame.totalForce();
        ++m_graspSteps;
        m_peak = std::max(m_peak, frame.totalForce());
        m_graspGrip = std::max(m_graspGrip, world.grip(Gripper::Right));
        m_liftedBy =
            std::max(m_liftedBy, world.gripperPose(Gripper::Right).pos[2] - m_graspHeight);
    }
    // A break warning is warranted each time the grip crosses the force that breaks what it
    // holds, whether or not it breaks (that needs the force held: sim/README.md).
    const double breakLine = held >= 0 ? world.objects()[size_t(held)].fragileForce : 0.0;
    const bool over = breakLine > 0 && frame.totalForce() >= breakLine;
    if (over && !m_overBreakLine)
        m_alarms[size_t(Gripper::Right)].episodes.push_back(world.time());
    m_overBreakLine = over;
    if (held >= 0)
        m_alarms[size_t(Gripper::Right)].hold(
            world.timestep(), m_warnings[size_t(Gripper::Right)].feltAt(world.time()));
    m_grasped = held;
}

void TaskMonitor::observeTransfers(const World &world)
{
    for (size_t i = 0; i < world.objects().size(); ++i) {
        const SceneObject &object = world.objects()[i];
        if (m_transferred[i] || object.broken || int(i) == m_grasped || int(i) == m_container)
            continue;
        const auto pos = world.objectPosition(int(i));
        bool arrived = false;
        if (m_container >= 0) {
            // Inside the held container (within its walls, above its floor), swaying with it.
            arrived = m_containerHeld && isInContainer(world, int(i));
        } else if (m_hasPlace) {
            arrived = m_place.contains(pos) && speed(world.objectVelocity(int(i))) < AtRest;
        }
        if (arrived) {
            m_transferred[i] = true;
            ++m_transfers;
        }
    }
}

void TaskMonitor::observeCompletion(const World &world)
{
    // The pile is finished once none of its cubes is left to carry: each one is over the
    // partition or broken (a broken cube cannot be transferred). A cube dropped outside
    // box B is still to be carried; if the box is refilled before it is, the next pile
    // counts.
    if (m_completedAt >= 0 || !m_hasPlace || m_container >= 0)
        return;
    bool any = false;
    for (size_t i = 0; i < world.objects().size(); ++i) {
        if (!isCube(world, i))
            continue;
        if (!m_transferred[i] && !world.objects()[i].broken)
            return;
        any = true;
    }
    if (any)
        m_completedAt = world.time();
}

void TaskMonitor::observeContainer(World &world)
{
    const double t = world.time();
    const int actor = world.objects()[size_t(m_container)].actor;
    const ContactFrame &frame = world.frame(Gripper::Left);
    const bool held = frame.left.actor == actor && frame.right.actor == actor;
    const double z = world.objectPosition(m_container)[2];
    observeContainerSlip(world, held);
    if (!m_containerDown && !m_containerHeld && !held) {
        // Knocked off its base (by the other hand, or respawned onto a spilled cube): the
        // same rule as a drop, without counting one.
        if (!isOnBase(world, m_container, m_home) &&
            speed(world.objectVelocity(m_container)) < AtRest) {
            m_containerDown = true;
            m_containerDroppedAt = t;
        }
    }
    if (m_containerDown) {
        if (t - m_containerDroppedAt >= RespawnPenalty) {
            respawnContainer(world);
            m_containerDown = false;
        }
        return;
    }
    if (held) {
        m_alarms[size_t(Gripper::Left)].hold(world.timestep(),
                                             m_warnings[size_t(Gripper::Left)].feltAt(world.time()));
        // The highest it was held: a slipping container slides down between the fingertips
        // before it leaves them.
        m_heldHeight = m_containerHeld ? std::max(m_heldHeight, z) : z;
        if (!m_containerHeld)
            ++m_holds;
        m_containerHeld = true;
        m_containerLostAt = -1.0;
        return;
    }
    if (!m_containerHeld) {
        // Put down on its base by an open hand: emptied once it rests (the next cycle).
        if (m_emptyAt >= 0 && t >= m_emptyAt) {
            for (size_t i = 0; i < world.objects().size(); ++i) {
                if (int(i) != m_container && !world.objects()[i].broken &&
                    isInContainer(world, int(i)))
                    returnToBox(world, int(i));
            }
            m_emptyAt = -1.0;
        }
        return;
    }
    if (m_containerLostAt < 0 && world.grip(Gripper::Left) <= 0) {
        // Let go of, not lost: the hand opened while still holding it.
        m_containerHeld = false;
        ++m_setDowns;
        m_emptyAt = t + SetDownSettle;
        return;
    }
    if (m_containerLostAt < 0) {
        // The failure is the moment it left the fingertips: what was felt up to then counts.
        m_containerLostAt = t;
        m_warningAtLoss = m_warnings[size_t(Gripper::Left)];
    }
    if (t - m_containerLostAt >= LostAfter && z < m_heldHeight - FallenBy) {
        m_drops.add(m_containerLostAt, m_warningAtLoss, m_reactionTime);
        m_alarms[size_t(Gripper::Left)].failures.push_back(m_containerLostAt);
        m_containerHeld = false;
        m_containerDown = true;
        m_containerDroppedAt = t;
    }
}

void TaskMonitor::observeContainerSlip(const World &world, bool held)
{
    if (!held) {
        m_hasRelative = false;
        m_slipping = false;
        m_slipSpeed = 0.0;
        return;
    }
    const std::array<double, 3> relative =
        toFrame(world.gripperPose(Gripper::Left), world.objectPosition(m_container));
    const double t = world.time();
    if (m_hasRelative) {
        const double dt = world.timestep();
        // Along the pads only (the gripper frame's x and z): closing the fingers centres the
        // container along the grip axis, which is no slip.
        const std::array<double, 3> delta{relative[0] - m_relative[0], 0.0,
                                          relative[2] - m_relative[2]};
        m_slipSpeed += (speed(delta) / dt - m_slipSpeed) * std::min(1.0, dt / SlipSmoothing);
    }
    m_relative = relative;
    m_hasRelative = true;
    if (m_slipSpeed > SlipSpeed) {
        if (!m_slipping) {
            ++m_slipEpisodes;
            m_alarms[size_t(Gripper::Left)].episodes.push_back(t);
        }
        m_slipping = true;
        m_slipQuietSince = t;
    } else if (m_slipping && t - m_slipQuietSince >= SlipQuiet) {
        m_slipping = false;
    }
}

void TaskMonitor::refill(World &world)
{
    // The experimenter refills the cube box once it is empty (the paper's participants
    // repeated the task for as long as it lasted): every cube out of play — transferred,
    // dropped, spilled or broken — goes back to where the scene started it. Cubes in hand or
    // in the held container stay; the refill waits until the hand is open and every cube has
    // come to rest.
    if (!m_hasPick || m_grasped >= 0 || world.grip(Gripper::Right) > 0)
        return;
    const auto &objects = world.objects();
    for (size_t i = 0; i < objects.size(); ++i) {
        // Not while a cube is still on its way (it may yet land in the box or count).
        if (isCube(world, i) && !objects[i].broken &&
            (m_pick.contains(world.objectPosition(int(i))) ||
             speed(world.objectVelocity(int(i))) >= AtRest))
            return;
    }
    bool any = false;
    for (size_t i = 0; i < objects.size(); ++i) {
        if (!isCube(world, i))
            continue;
        if (m_container >= 0 && !objects[i].broken && isInContainer(world, int(i)))
            continue;
        returnToBox(world, int(i));
        any = true;
    }
    if (any)
        ++m_refills;
}

bool TaskMonitor::isCube(const World &world, size_t object) const
{
    return int(object) != m_container &&
           world.objects()[object].name.startsWith(QLatin1String("cube"));
}

bool TaskMonitor::isOnBase(const World &world, int container, const Region &home)
{
    const auto pos = world.objectPosition(container);
    const auto &q = world.objectPose(container).quat;
    // Its up axis within 20 degrees of the vertical: 1 - 2 (x^2 + y^2) is that axis' z.
    const bool upright = 1.0 - 2.0 * (q[1] * q[1] + q[2] * q[2]) > std::cos(0.35);
    return upright && std::hypot(pos[0] - home.center[0], pos[1] - home.center[1]) <= OffHome;
}

bool TaskMonitor::isInContainer(const World &world, int object) const
{
    const SceneObject &walls = world.objects()[size_t(m_container)];
    const auto container = world.objectPosition(m_container);
    const auto pos = world.objectPosition(object);
    return std::abs(pos[0] - container[0]) < walls.upper[0] &&
           std::abs(pos[1] - container[1]) < walls.upper[1] && pos[2] > container[2] &&
           pos[2] < container[2] + walls.upper[2];
}

void TaskMonitor::respawnContainer(World &world)
{
    // A respawn resets the container: it comes back empty, its cubes and any spilled onto
    // the base (which would tip it over) go back to the box.
    const double reach = world.objects()[size_t(m_container)].upper[0] + 0.04;
    for (size_t i = 0; i < world.objects().size(); ++i) {
        if (int(i) == m_container || world.objects()[i].broken)
            continue;
        const auto pos = world.objectPosition(int(i));
        if (isInContainer(world, int(i)) ||
            std::hypot(pos[0] - m_home.center[0], pos[1] - m_home.center[1]) < reach)
            returnToBox(world, int(i));
    }
    world.placeObject(m_container, m_home.center);
}

void TaskMonitor::returnToBox(World &world, int object)
{
    const auto home = world.homePosition(object);
    for (int layer = 0; layer < Layers; ++layer) {
        const std::array<double, 3> spot{home[0], home[1], home[2] + layer * Layer};
        bool free = true;
        for (size_t i = 0; i < world.objects().size() && free; ++i) {
            const auto pos = world.objectPosition(int(i));
            free = int(i) == object || world.objects()[i].broken ||
                   std::max({std::abs(pos[0] - spot[0]), std::abs(pos[1] - spot[1]),
                             std::abs(pos[2] - spot[2])}) > Layer;
        }
        if (free) {
            world.restoreObject(object, spot);
            m_transferred[size_t(object)] = false;
            return;
        }
    }
}

QJsonObject TaskMonitor::metrics() const
{
    const int breaks = m_breaks.count;
    QJsonObject metrics{
        {QLatin1String(CubesTransferred), m_transfers},
        {QStringLiteral("cubes_dropped"), m_dropped},
        {QStringLiteral("cubes_broken"), breaks},
        {QStringLiteral("grasps"), m_grasps},
        {QStringLiteral("average_grasp_force"), mean(m_graspForceSum, double(m_graspSteps))},
        {QStringLiteral("grasps_per_transfer"), mean(m_grasps, m_transfers)},
        {QStringLiteral("average_peak_grasp_force"),
         mean(m_peakSum + (m_grasped >= 0 ? m_peak : 0.0), m_grasps)},
        {QStringLiteral("warning_lead_time"), mean(m_breaks.leadTimeSum, m_breaks.warned)},
        {QStringLiteral("breaks_warned_share"), mean(m_breaks.warned, breaks)},
        {QStringLiteral("breaks_warned_in_time_share"), mean(m_breaks.inTime, breaks)},
        {QStringLiteral("box_refills"), m_refills},
    };
    if (m_hasPlace && m_container < 0)
        metrics.insert(QLatin1String(CompletionTime),
                       m_completedAt >= 0 ? QJsonValue(m_completedAt) : QJsonValue());
    int confirmations = m_confirmations[size_t(Gripper::Right)].onsets;
    int grasps = m_grasps;
    if (m_container >= 0) {
        const int drops = m_drops.count;
        metrics.insert(QStringLiteral("containers_dropped"), drops);
        metrics.insert(QStringLiteral("containers_set_down"), m_setDowns);
        metrics.insert(QStringLiteral("transfers_per_container_cycle"),
                       double(m_transfers) / (drops + m_setDowns + 1));
        metrics.insert(QStringLiteral("drop_warning_lead_time"),
                       mean(m_drops.leadTimeSum, m_drops.warned));
        metrics.insert(QStringLiteral("drops_warned_share"), mean(m_drops.warned, drops));
        metrics.insert(QStringLiteral("drops_warned_in_time_share"), mean(m_drops.inTime, drops));
        metrics.insert(QStringLiteral("slip_episodes"), m_slipEpisodes);
        metrics.insert(QStringLiteral("warnings_per_slip_episode"),
                       mean(m_warnings[size_t(Gripper::Left)].onsets, m_slipEpisodes));
        confirmations += m_confirmations[size_t(Gripper::Left)].onsets;
        grasps += m_holds;
    }
    metrics.insert(QStringLiteral("confirmations_per_grasp"), mean(confirmations, grasps));

    // The warnings judged as alarms are: by onset, precision and duty.
    const Alarms &right = m_alarms[size_t(Gripper::Right)];
    metrics.insert(QStringLiteral("breaks_warned_by_onset_share"),
                   right.warnedByOnsetShare(m_reactionTime, m_horizon));
    metrics.insert(QStringLiteral("right_warning_precision"), right.precision(m_horizon, m_time));
    metrics.insert(QStringLiteral("right_warning_duty"), right.duty());
    if (m_container >= 0) {
        const Alarms &left = m_alarms[size_t(Gripper::Left)];
        metrics.insert(QStringLiteral("drops_warned_by_onset_share"),
                       left.warnedByOnsetShare(m_reactionTime, m_horizon));
        metrics.insert(QStringLiteral("left_warning_precision"), left.precision(m_horizon, m_time));
        metrics.insert(QStringLiteral("left_warning_duty"), left.duty());
    }
    return metrics;
}

const std::vector<MetricSpec> &TaskMonitor::metricSpecs()
{
    static const std::vector<MetricSpec> specs = {
        {CompletionTime, MetricUnit::Seconds, MetricBetter::Lower,
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Completion time"),
         QT_TRANSLATE_NOOP("semhap::MetricSpec",
                           "When the pile was first finished: every cube transferred or broken "
                           "(box_and_block).")},
        {CubesTransferred, MetricUnit::Count, MetricBetter::Higher,
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Cubes transferred"),
         QT_TRANSLATE_NOOP("semhap::MetricSpec",
                           "Cubes that arrived where the task wants them, once per trip.")},
        {"cubes_broken", MetricUnit::Count, MetricBetter::Lower,
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Cubes broken"),
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Cubes that fractured under the fingertips.")},
        {"cubes_dropped", MetricUnit::Count, MetricBetter::Lower,
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Cubes dropped (slipped out)"),
         QT_TRANSLATE_NOOP(
             "semhap::MetricSpec",
             "Grasps that ended while the hand still gripped, after a lift: the cube "
             "slipped out.")},
        {"grasps", MetricUnit::Count, MetricBetter::Neither,
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Grasps"),
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Grasps begun.")},
        {"grasps_per_transfer", MetricUnit::Ratio, MetricBetter::Lower,
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Grasps per transfer"),
         QT_TRANSLATE_NOOP("semhap::MetricSpec",
                           "Grasps per cube transferred: 1 is one grasp for each.")},
        {"average_grasp_force", MetricUnit::Newtons, MetricBetter::Neither,
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Average grasp force"),
         QT_TRANSLATE_NOOP("semhap::MetricSpec",
                           "The mean force of both fingertips over every moment of every grasp.")},
        {"average_peak_grasp_force", MetricUnit::Newtons, MetricBetter::Neither,
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Average peak grasp force"),
         QT_TRANSLATE_NOOP("semhap::MetricSpec",
                           "The mean over grasps of the highest force during each.")},
        {"warning_lead_time", MetricUnit::Seconds, MetricBetter::Higher,
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Warning lead time"),
         QT_TRANSLATE_NOOP("semhap::MetricSpec",
                           "How long before a break its warning was first felt, on average.")},
        {"breaks_warned_share", MetricUnit::Share, MetricBetter::Higher,
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Breaks warned"),
         QT_TRANSLATE_NOOP("semhap::MetricSpec",
                           "The share of breaks a felt warning came before.")},
        {"breaks_warned_in_time_share", MetricUnit::Share, MetricBetter::Higher,
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Breaks warned in time"),
         QT_TRANSLATE_NOOP("semhap::MetricSpec",
                           "The share of breaks warned at least a reaction time before: the "
                           "warnings a person could act on.")},
        {"containers_dropped", MetricUnit::Count, MetricBetter::Lower,
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Containers dropped"),
         QT_TRANSLATE_NOOP(
             "semhap::MetricSpec",
             "Times the held container left the left fingertips and fell (bimanual).")},
        {"drop_warning_lead_time", MetricUnit::Seconds, MetricBetter::Higher,
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Drop warning lead time"),
         QT_TRANSLATE_NOOP("semhap::MetricSpec",
                           "How long before a container drop its warning was first felt, on "
                           "average (bimanual).")},
        {"drops_warned_share", MetricUnit::Share, MetricBetter::Higher,
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Drops warned"),
         QT_TRANSLATE_NOOP("semhap::MetricSpec",
                           "The share of container drops a felt warning came before (bimanual).")},
        {"drops_warned_in_time_share", MetricUnit::Share, MetricBetter::Higher,
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Drops warned in time"),
         QT_TRANSLATE_NOOP("semhap::MetricSpec",
                           "The share of container drops warned at least a reaction time before "
                           "(bimanual).")},
        {"containers_set_down", MetricUnit::Count, MetricBetter::Neither,
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Containers set down"),
         QT_TRANSLATE_NOOP("semhap::MetricSpec",
                           "Times the holding hand set the full container down on its base to be "
                           "emptied (bimanual).")},
        {"transfers_per_container_cycle", MetricUnit::Ratio, MetricBetter::Higher,
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Transfers per container cycle"),
         QT_TRANSLATE_NOOP(
             "semhap::MetricSpec",
             "Cubes transferred per container cycle, which a drop or a set-down ends "
             "(bimanual).")},
        {"confirmations_per_grasp", MetricUnit::Ratio, MetricBetter::Neither,
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Confirmations felt per grasp"),
         QT_TRANSLATE_NOOP("semhap::MetricSpec",
                           "Confirmations felt per real grasp: 1 is one per grasp, more is "
                           "chatter, 0 without feedback.")},
        {"slip_episodes", MetricUnit::Count, MetricBetter::Lower,
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Slip episodes"),
         QT_TRANSLATE_NOOP("semhap::MetricSpec",
                           "Times the container slid in the left fingertips (bimanual).")},
        {"warnings_per_slip_episode", MetricUnit::Ratio, MetricBetter::Neither,
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Warnings felt per slip episode"),
         QT_TRANSLATE_NOOP("semhap::MetricSpec",
                           "Warnings felt on the left hand per slip: above 1, warnings came that "
                           "no slip answered (bimanual).")},
        {"breaks_warned_by_onset_share", MetricUnit::Share, MetricBetter::Higher,
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Breaks warned by onset"),
         QT_TRANSLATE_NOOP("semhap::MetricSpec",
                           "The share of breaks whose warning began within the horizon before, in "
                           "time to act: a warning on all along does not count.")},
        {"right_warning_precision", MetricUnit::Share, MetricBetter::Higher,
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Right warnings borne out"),
         QT_TRANSLATE_NOOP("semhap::MetricSpec",
                           "The share of the right hand's warnings a break, or the grip crossing "
                           "the break line, followed within the horizon: the rest were false "
                           "alarms.")},
        {"right_warning_duty", MetricUnit::Share, MetricBetter::Lower,
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Right warning duty"),
         QT_TRANSLATE_NOOP("semhap::MetricSpec",
                           "The share of grasping time a warning was felt on the right hand.")},
        {"drops_warned_by_onset_share", MetricUnit::Share, MetricBetter::Higher,
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Drops warned by onset"),
         QT_TRANSLATE_NOOP("semhap::MetricSpec",
                           "The share of container drops whose warning began within the horizon "
                           "before, in time to act (bimanual).")},
        {"left_warning_precision", MetricUnit::Share, MetricBetter::Higher,
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Left warnings borne out"),
         QT_TRANSLATE_NOOP(
             "semhap::MetricSpec",
             "The share of the left hand's warnings a drop or a slip followed within "
             "the horizon: the rest were false alarms (bimanual).")},
        {"left_warning_duty", MetricUnit::Share, MetricBetter::Lower,
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Left warning duty"),
         QT_TRANSLATE_NOOP("semhap::MetricSpec",
                           "The share of the time the container was held that a warning was felt "
                           "(bimanual).")},
        {"box_refills", MetricUnit::Count, MetricBetter::Neither,
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Cube box refills"),
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Times the cube box was refilled.")},
    };
    return specs;
}

} // namespace semhap
