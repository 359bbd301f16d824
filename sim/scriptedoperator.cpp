// SPDX-License-Identifier: MIT
#include "scriptedoperator.h"

#include "perception.h"
#include "taskmonitor.h"
#include "world.h"

#include <algorithm>
#include <cmath>

namespace semhap {

namespace {

constexpr double Pi = 3.14159265358979323846;
// Heights of the wrist; where the pads are below it is the gripper's (World::padDrop).
constexpr double CarryHeight = 0.25;
constexpr double ReleaseHeight = 0.19;
// How far from a cube's centre the fingers come down, and the room they need there.
constexpr double FingerReach = 0.04;
constexpr double MinClearance = 0.008;
// Sensory baseline: pressure (F / ref) at which a person stops closing, and eases off.
constexpr double EnoughPressure = 0.3;
constexpr double TooMuchPressure = 0.65;
constexpr double Gravity = 9.81;
// How high the left hand lifts the container off its base.
constexpr double HoldLift = 0.06;
// The container takes a cube in each quarter; full, it is put down to be emptied.
constexpr int Quarters = 4;
// How long a grip takes to close (s, times the trial's pace), and a hurried one.
constexpr double ClosingTime = 0.7;
constexpr double FastClosingTime = 0.15;
// The drifting hold: the grip relaxes exponentially towards nothing with this time constant (s).
constexpr double RelaxTimeConstant = 20.0;
// The holding hand's grip drifts down unnoticed (sim/README.md, "The holding hand"): without
// feedback on the force, finger forces fall exponentially with a time constant of ~15 s
// (Ambike, Zatsiorsky & Latash 2015), by up to 35 % of the force and more (Hirose et al.
// 2020).
constexpr double DriftTimeConstant = 15.0;
constexpr double DriftShare = 0.35;
// How fast (m/s, on average) an empty hand rises clear after a hand-over.
constexpr double RiseSpeed = 0.3;
// The least a felt slip warning adds to the grip (N), when the grip already matches the load
// the operator expects.
constexpr double RegripStep = 5.0;

} // namespace

ScriptedOperator::ScriptedOperator(Task task, std::uint64_t seed, bool reactive,
                                   double reactionTime, Variant variant)
    : m_task(task), m_random(seed), m_reactive(reactive), m_variant(variant),
      m_reactionTime(reactionTime)
{
    m_wobblePhase = {m_random.uniform(0, 2 * Pi), m_random.uniform(0, 2 * Pi)};
}

QString ScriptedOperator::name() const
{
    switch (m_variant) {
    case Variant::FastSqueeze:
        return QStringLiteral("fast_squeeze");
    case Variant::DriftingHold:
        return QStringLiteral("drifting_hold");
    case Variant::Normal:
        break;
    }
    return m_reactive ? QStringLiteral("reactive") : QStringLiteral("scripted");
}

void ScriptedOperator::act(World &world)
{
    const double t = world.time();
    while (!m_percepts.empty() && m_percepts.front().due <= t) {
        react(world, m_percepts.front());
        m_percepts.pop_front();
    }
    const double rightGrip = world.grip(Gripper::Right);
    m_rightOpens = m_lastRightGrip > 0.0 && rightGrip <= 0.0;
    m_lastRightGrip = rightGrip;
    if (m_task == Task::BimanualSorting)
        planHold(world);
    if (m_right.isIdle())
        m_target >= 0 ? planGrasp(world) : planPick(world);
    m_right.apply(world);
}

std::array<double, 3> ScriptedOperator::placePoint(const World &world)
{
    if (m_task == Task::BimanualSorting) {
        // Above the container's emptiest quarter: it takes four cubes side by side.
        const int container = world.objectIndex(QStringLiteral("container"));
        const SceneObject &walls = world.objects()[size_t(container)];
        const auto pos = world.objectPosition(container);
        const double quarter = walls.upper[0] / 2;
        std::array<double, 3> best{pos[0], pos[1], 0.0};
        double bestClearance = -1.0;
        for (double dx : {-quarter, quarter}) {
            for (double dy : {-quarter, quarter}) {
                double clearance = 1.0;
                for (int cube : cubesIn(world))
                    clearance = std::min(clearance,
                                         std::hypot(world.objectPosition(cube)[0] - pos[0] - dx,
                                                    world.objectPosition(cube)[1] - pos[1] - dy));
                if (clearance > bestClearance + 1e-9) {
                    bestClearance = clearance;
                    best = {pos[0] + dx, pos[1] + dy, 0.0};
                }
            }
        }
        return {best[0], best[1], pos[2] + walls.upper[2] + 0.11};
    }
    // Where the fewest cubes are: the free spot of a 4 x 4 grid farthest from any cube in the
    // place region, released above the rim so the fingers never land on a cube.
    Region place;
    world.region(QStringLiteral("place"), &place);
    std::array<double, 3> best = place.center;
    double bestClearance = -1.0;
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j) {
            const double x = place.center[0] + (i - 1.5) * place.half[0] / 2;
            const double y = place.center[1] + (j - 1.5) * place.half[1] / 2;
            double clearance = 1.0;
            for (size_t k = 0; k < world.objects().size(); ++k) {
                const auto pos = world.objectPosition(int(k));
                if (!world.objects()[k].broken && place.contains(pos))
                    clearance = std::min(clearance, std::hypot(pos[0] - x, pos[1] - y));
            }
            if (clearance > bestClearance + 1e-9) {
                bestClearance = clearance;
                best = {x, y, ReleaseHeight};
            }
        }
    }
    return {best[0] + m_random.uniform(-0.01, 0.01), best[1] + m_random.uniform(-0.01, 0.01),
            best[2]};
}

void ScriptedOperator::planPick(World &world)
{
    // The next cube: from the top of the pile down, the first with room for the fingers; if
    // none has, the roomiest (a person would try it anyway).
    Region pick;
    world.region(QStringLiteral("pick"), &pick);
    int cube = -1;
    double bestZ = -1.0;
    double bestRoom = -1.0;
    for (size_t i = 0; i < world.objects().size(); ++i) {
        const SceneObject &object = world.objects()[i];
        const auto pos = world.objectPosition(int(i));
        if (object.broken || !object.name.startsWith(QLatin1String("cube")) || !pick.contains(pos))
            continue;
        const double yaw = graspYaw(world, int(i));
        const double room = std::min(fingerClearance(world, int(i), yaw), MinClearance);
        if (room > bestRoom + 1e-9 || (room >= bestRoom - 1e-9 && pos[2] > bestZ + 0.01)) {
            bestRoom = room;
            bestZ = pos[2];
            cube = int(i);
        }
    }
    const bool full = m_task == Task::BimanualSorting && int(cubesIn(world).size()) >= Quarters;
    if (cube < 0 || (m_task == Task::BimanualSorting && m_hold != Hold::Holding) || full) {
        m_right.wait(0.2);
        return;
    }
    // Reach above it first; the grasp is planned from there, on what the eyes see then.
    const auto pos = world.objectPosition(cube);
    m_target = cube;
    m_right.grip(HandPlan::OpenGrip, 0.1);
    m_right.move({pos[0], pos[1], CarryHeight}, 0.9 * m_random.uniform(0.85, 1.2));
}

void ScriptedOperator::planGrasp(World &world)
{
    const int cube = m_target;
    m_target = -1;
    m_carried = cube;
    if (world.objects()[size_t(cube)].broken)
        return;
    const auto pos = world.objectPosition(cube);
    const double yaw = graspYaw(world, cube);
    Pose wrist = world.target(Gripper::Right);
    wrist.quat = {std::cos(yaw / 2), 0.0, 0.0, std::sin(yaw / 2)};
    world.setTarget(Gripper::Right, wrist);
    // People vary: this trial's pace and the grip it will squeeze with (N, both fingers).
    const double pace = m_random.uniform(0.85, 1.2);
    double force = std::clamp(m_random.normal(60.0, 40.0), 4.0, world.maxGrip(Gripper::Right));
    double closing = ClosingTime * pace;
    const double fragile = world.objects()[size_t(cube)].fragileForce;
    if (m_variant == Variant::FastSqueeze && fragile > 0) {
        // Hurried and hard, as on a solid block: past the fracture force, in a snap.
        force = std::min(fragile * m_random.uniform(1.1, 1.4), world.maxGrip(Gripper::Right));
        closing = FastClosingTime;
    }
    m_right.move({pos[0], pos[1], CarryHeight}, 0.3 * pace);
    // The pads' centre at the cube's, where they will be once closed on it.
    const SceneObject &object = world.objects()[size_t(cube)];
    const double width =
        std::min(object.upper[0] - object.lower[0], object.upper[1] - object.lower[1]);
    m_right.move({pos[0], pos[1], pos[2] + world.padDrop(Gripper::Right, width)}, 0.5 * pace);
    m_right.wait(0.1);
    m_right.grip(force, closing);
    m_right.wait(0.25);
    planPlace(world, pos, pace);
}

void ScriptedOperator::planPlace(const World &world, const std::array<double, 3> &from,
                                 double pace)
{
    // Carry high enough to clear where it goes (a held container's rim may be higher).
    const auto place = placePoint(world);
    const double carry = std::max(CarryHeight, place[2] + 0.02);
    m_right.move({from[0], from[1], carry}, 0.6 * pace);
    m_right.move({place[0], place[1], carry}, 1.0 * pace);
    m_right.move(place, 0.4 * pace);
    m_right.grip(HandPlan::OpenGrip, 0.15);
    m_right.wait(0.3);
    m_right.move({place[0], place[1], carry}, 0.3 * pace);
}

void ScriptedOperator::engage(const World &world)
{
    // Whatever was planned before the hand-over is stale: resumed, a move begun before it would
    // jump the target to its end (into the pile, from over box B: 3850 N on the fingertips).
    m_right.clear();
    m_left.clear();
    m_percepts.clear();
    m_target = -1;
    m_lastRightGrip = world.grip(Gripper::Right);
    const auto wrist = world.target(Gripper::Right).pos;
    const int held = world.objectSqueezed(Gripper::Right);
    if (held >= 0 && world.objects()[size_t(held)].name.startsWith(QLatin1String("cube"))) {
        m_carried = held;
        planPlace(world, wrist, 1.0);
    } else {
        m_right.grip(HandPlan::OpenGrip, 0.1);
        const double rise = CarryHeight - wrist[2];
        if (rise > 0)
            m_right.move({wrist[0], wrist[1], CarryHeight}, std::max(0.3, rise / RiseSpeed));
    }
    if (m_task != Task::BimanualSorting)
        return;
    const double t = world.time();
    m_holdStart = t;
    if (world.isBetween(Gripper::Left, world.objectIndex(QStringLiteral("container")))) {
        // Held as the user held it: that grip is the one that now drifts.
        m_hold = Hold::Holding;
        m_holdPos = world.target(Gripper::Left).pos;
        m_holdGrip = world.grip(Gripper::Left);
    } else if (m_hold == Hold::Dropped) {
        const auto hand = world.target(Gripper::Left).pos;
        m_left.grip(HandPlan::OpenGrip, 0.15);
        m_left.move({hand[0], hand[1], std::max(hand[2], 0.3)}, 0.6);
    } else {
        m_hold = Hold::Acquire;
    }
}

double ScriptedOperator::graspYaw(const World &world, int cube) const
{
    // A pair of the cube's faces: of its two yaws, folded into ±45 degrees, the one whose
    // fingers come down farthest from walls and other cubes.
    const auto q = world.objectPose(cube).quat;
    double yaw = std::atan2(2 * (q[0] * q[3] + q[1] * q[2]), 1 - 2 * (q[2] * q[2] + q[3] * q[3]));
    yaw -= (Pi / 2) * std::round(yaw / (Pi / 2));
    const double other = yaw + (yaw > 0 ? -Pi / 2 : Pi / 2);
    return fingerClearance(world, cube, other) > fingerClearance(world, cube, yaw) ? other : yaw;
}

double ScriptedOperator::fingerClearance(const World &world, int cube, double yaw) const
{
    // Where each finger comes down: 4 cm to either side of the cube, across the grip.
    Region pick;
    world.region(QStringLiteral("pick"), &pick);
    const auto centre = world.objectPosition(cube);
    double clearance = 1.0;
    for (double side : {-1.0, 1.0}) {
        const double x = centre[0] - side * FingerReach * std::sin(yaw);
        const double y = centre[1] + side * FingerReach * std::cos(yaw);
        clearance = std::min({clearance, pick.half[0] - std::abs(x - pick.center[0]),
                              pick.half[1] - std::abs(y - pick.center[1])});
        for (size_t i = 0; i < world.objects().size(); ++i) {
            if (int(i) == cube || world.objects()[i].broken)
                continue;
            const auto pos = world.objectPosition(int(i));
            if (std::abs(pos[2] - centre[2]) < 0.04)
                clearance = std::min(clearance, std::hypot(pos[0] - x, pos[1] - y) - 0.035);
        }
    }
    return clearance;
}

void ScriptedOperator::planHold(World &world)
{
    const double t = world.time();
    const int container = world.objectIndex(QStringLiteral("container"));
    const SceneObject &object = world.objects()[size_t(container)];
    const ContactFrame &frame = world.frame(Gripper::Left);
    const bool held = frame.left.actor == object.actor && frame.right.actor == object.actor;
    // The grip that just holds the empty container: its weight over its friction.
    const double holdLimit = object.mass * Gravity / object.friction;
    switch (m_hold) {
    case Hold::Acquire:
        if (m_left.isIdle()) {
            if (held && t > m_holdStart) {
                m_hold = Hold::Holding;
                m_holdStart = t;
                m_holdPos = world.target(Gripper::Left).pos;
                break;
            }
            const auto pos = world.objectPosition(container);
            const double gripZ = pos[2] + object.upper[2] - 0.02 +
                                 world.padDrop(Gripper::Left, object.upper[1] - object.lower[1]);
            // The grip a practised person chooses for the empty container: 1.56 times what
            // holds it (a safety margin of 36 % of the grip), kept as the grip-to-load ratio
            // for the load it expects.
            m_holdGrip = m_random.normal(46.0, 3.0);
            m_gripPerLoad = m_holdGrip / holdLimit;
            m_left.grip(HandPlan::OpenGrip, 0.1);
            m_left.move({pos[0], pos[1], 0.3}, 0.8);
            m_left.move({pos[0], pos[1], gripZ}, 0.6);
            m_left.grip(m_holdGrip, 0.4);
            m_left.wait(0.3);
            m_left.move({pos[0], pos[1], gripZ + HoldLift}, 0.8);
            m_holdStart = t;
        }
        break;
    case Hold::Holding: {
        // The hand relaxes without noticing: the grip drifts down exponentially from the last
        // grip the person chose, and the wrist sways a few millimetres.
        const double decay =
            std::exp(-(t - m_holdStart) /
                     (m_variant == Variant::DriftingHold ? RelaxTimeConstant : DriftTimeConstant));
        const double kept = m_variant == Variant::DriftingHold ? 0.0 : 1.0 - DriftShare;
        world.setGrip(Gripper::Left, m_holdGrip * (kept + (1.0 - kept) * decay));
        if (m_variant != Variant::DriftingHold && releasesIntoContainer(world)) {
            // Dropping a cube into the container held in the other hand, people raise the
            // grip in anticipation, scaled to the load they expect (Johansson & Westling
            // 1988): here the same grip-to-load ratio for one cube more.
            const SceneObject &cube = world.objects()[size_t(m_carried)];
            m_holdGrip =
                world.grip(Gripper::Left) + m_gripPerLoad * cube.mass * Gravity / object.friction;
            m_holdStart = t;
        }
        Pose target = world.target(Gripper::Left);
        target.pos[0] = m_holdPos[0] + 0.004 * std::sin(2 * Pi * t / 5.0 + m_wobblePhase[0]);
        target.pos[1] = m_holdPos[1] + 0.003 * std::sin(2 * Pi * t / 7.0 + m_wobblePhase[1]);
        world.setTarget(Gripper::Left, target);
        if (!held) {
            m_hold = Hold::Dropped;
            m_droppedAt = t;
            m_left.clear();
            m_left.grip(HandPlan::OpenGrip, 0.15);
            m_left.move({m_holdPos[0], m_holdPos[1], 0.3}, 0.6);
        } else if (int(cubesIn(world).size()) >= Quarters && m_right.isIdle()) {
            // Full: put it down on its base to be emptied, and take it again.
            m_hold = Hold::SetDown;
            m_left.move({m_holdPos[0], m_holdPos[1], m_holdPos[2] - HoldLift}, 0.8);
            m_left.grip(HandPlan::OpenGrip, 0.2);
            m_left.move({m_holdPos[0], m_holdPos[1], 0.3}, 0.6);
        }
        break;
    }
    case Hold::SetDown:
        if (m_left.isIdle()) {
            m_hold = Hold::Acquire;
            m_holdStart = t;
        }
        break;
    case Hold::Dropped: {
        Region home;
        world.region(QStringLiteral("home"), &home);
        const bool back = TaskMonitor::isOnBase(world, container, home);
        if (m_left.isIdle() && back && t - m_droppedAt > TaskMonitor::RespawnPenalty) {
            m_hold = Hold::Acquire;
            m_holdStart = t;
        }
        break;
    }
    }
    m_left.apply(world);
}

std::vector<int> ScriptedOperator::cubesIn(const World &world) const
{
    // What the eyes see in the container: cubes within its walls, above its floor.
    const int container = world.objectIndex(QStringLiteral("container"));
    const SceneObject &walls = world.objects()[size_t(container)];
    const auto pos = world.objectPosition(container);
    std::vector<int> cubes;
    for (size_t i = 0; i < world.objects().size(); ++i) {
        const auto p = world.objectPosition(int(i));
        if (int(i) != container && !world.objects()[i].broken &&
            std::abs(p[0] - pos[0]) < walls.upper[0] && std::abs(p[1] - pos[1]) < walls.upper[1] &&
            p[2] > pos[2] && p[2] < pos[2] + walls.upper[2] + 0.03)
            cubes.push_back(int(i));
    }
    return cubes;
}

bool ScriptedOperator::releasesIntoContainer(const World &world) const
{
    // The picking hand opening above the container: a cube is about to land in it.
    if (!m_rightOpens || m_carried < 0)
        return false;
    const int container = world.objectIndex(QStringLiteral("container"));
    const auto above = world.objectPosition(container);
    const auto hand = world.gripperPose(Gripper::Right).pos;
    return std::hypot(hand[0] - above[0], hand[1] - above[1]) <
           world.objects()[size_t(container)].upper[0];
}

bool ScriptedOperator::looksAt(Gripper hand, double t) const
{
    if (m_task == Task::BoxAndBlock)
        return hand == Gripper::Right;
    // Watching the picking hand, with a half-second glance at the holding hand every 4.5 s
    // (and eyes on it while it takes the container).
    const bool glance = std::fmod(t, 4.5) < 0.5 || m_hold != Hold::Holding;
    return hand == Gripper::Left ? glance : !glance;
}

void ScriptedOperator::feel(Gripper hand, const Feeling &feeling, double t)
{
    if (!m_reactive)
        return;
    const bool sees = looksAt(hand, t);
    const std::array<double, 4> levels{
        std::max(feeling.confirmation, sees ? feeling.shownConfirmation : 0.0),
        std::max(feeling.warning, sees ? feeling.shownWarning : 0.0),
        feeling.pressure >= EnoughPressure ? 1.0 : 0.0,
        feeling.pressure >= TooMuchPressure ? 1.0 : 0.0};
    HandState &state = m_hands[size_t(hand)];
    for (size_t cue = 0; cue < levels.size(); ++cue) {
        if (levels[cue] < Perception::Noticeable)
            continue;
        if (t - state.lastFelt[cue] > Perception::PulseGap)
            m_percepts.push_back({t + m_reactionTime, hand, Cue(cue)});
        state.lastFelt[cue] = t;
    }
}

void ScriptedOperator::react(World &world, const Percept &percept)
{
    const double grip = world.grip(percept.hand);
    if (grip <= 0)
        return; // nothing in hand
    HandPlan &plan = percept.hand == Gripper::Right ? m_right : m_left;
    switch (percept.cue) {
    case Cue::Confirmation:
    case Cue::Pressure:
        // Enough: stop closing here.
        if (plan.isGripping())
            plan.regrip(grip, 0.0);
        break;
    case Cue::Warning:
        if (m_task == Task::BimanualSorting && percept.hand == Gripper::Left) {
            // The holding hand is warned of a slip, whatever it is doing with the container:
            // grip as for the load it sees (the container and the cubes in it), at least a
            // step firmer; a hold's drift starts over.
            const int container = world.objectIndex(QStringLiteral("container"));
            const SceneObject &object = world.objects()[size_t(container)];
            double load = object.mass;
            for (int cube : cubesIn(world))
                load += world.objects()[size_t(cube)].mass;
            m_holdGrip =
                std::max(m_gripPerLoad * load * Gravity / object.friction, grip + RegripStep);
            m_holdStart = world.time();
            if (m_hold != Hold::Holding)
                plan.regrip(m_holdGrip, 0.1);
            break;
        }
        plan.regrip(0.7 * grip, 0.15);
        break;
    case Cue::HighPressure:
        plan.regrip(0.7 * grip, 0.15);
        break;
    }
}

std::unique_ptr<Operator> ScriptedOperator::create(const QString &name, const World &world,
                                                   std::uint64_t seed, double reactionTime,
                                                   QString *error)
{
    Region region;
    Task task = Task::BoxAndBlock;
    if (world.objectIndex(QStringLiteral("container")) >= 0 && world.hasGripper(Gripper::Left) &&
        world.region(QStringLiteral("home"), &region)) {
        task = Task::BimanualSorting;
    } else if (!world.region(QStringLiteral("place"), &region)) {
        *error = QStringLiteral("%1: the %2 operator needs sites 'pick' and 'place' (or a "
                                "'container' and a 'home' site; see sim/README.md)")
                     .arg(world.sceneName(), name);
        return nullptr;
    }
    if (!world.region(QStringLiteral("pick"), &region) || !world.hasGripper(Gripper::Right)) {
        *error = QStringLiteral("%1: the %2 operator needs a right gripper and a 'pick' site")
                     .arg(world.sceneName(), name);
        return nullptr;
    }
    const auto variant = name == QLatin1String("fast_squeeze")    ? Variant::FastSqueeze
                         : name == QLatin1String("drifting_hold") ? Variant::DriftingHold
                                                                  : Variant::Normal;
    return std::make_unique<ScriptedOperator>(task, seed, name == QLatin1String("reactive"),
                                              reactionTime, variant);
}

} // namespace semhap
