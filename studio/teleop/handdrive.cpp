// SPDX-License-Identifier: MIT
#include "handdrive.h"

#include "driveoperator.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace semhap {

namespace {

constexpr double Pi = 3.14159265358979323846;
constexpr double TickSeconds = 1.0 / 60.0;
// Room around the task's regions, and the wrist's heights: at the lowest the pads (6 cm
// below the wrist) touch the table, at the highest a carried cube clears every stack.
constexpr double Margin = 0.12;
constexpr double LowestWrist = 0.06;
constexpr double HighestWrist = 0.45;
// A long stall (a breakpoint) must not turn into a jump; a slow software-GL frame may.
constexpr double LongestTick = 0.25;
// A trigger must move this much (of its travel) to take the grip: sensor noise does not.
constexpr double GripDeadband = 0.02;

/** What `key` does in the keyboard drive, if anything. */
std::optional<DriveKeyAction> actionOf(int key)
{
    for (const DriveKey &entry : HandDrive::keyTable()) {
        if (entry.key == key)
            return entry.action;
    }
    return std::nullopt;
}

} // namespace

HandDrive::HandDrive(QObject *parent) : QObject(parent)
{
    m_timer.setInterval(int(TickSeconds * 1000));
    m_timer.setTimerType(Qt::PreciseTimer);
    connect(&m_timer, &QTimer::timeout, this, &HandDrive::tick);
}

HandDrive::~HandDrive() = default;

void HandDrive::setWorld(const World *world)
{
    releaseAll();
    m_world = world;
    m_driving = false;
    m_hands = {};
    m_analogueGrip = {};
    if (!world) {
        emit changed();
        return;
    }
    m_hands = currentCommands(*world);
    m_active = m_hands[size_t(Gripper::Right)] ? Gripper::Right : Gripper::Left;

    // The workspace: every region of the task and every hand's start, with room around.
    std::array<double, 3> lower{1e9, 1e9, 0.0};
    std::array<double, 3> upper{-1e9, -1e9, 0.0};
    auto include = [&](const std::array<double, 3> &lo, const std::array<double, 3> &hi) {
        for (size_t axis = 0; axis < 2; ++axis) {
            lower[axis] = std::min(lower[axis], lo[axis]);
            upper[axis] = std::max(upper[axis], hi[axis]);
        }
    };
    for (const char *name : {"pick", "place", "home"}) {
        Region region;
        if (!world->region(QLatin1String(name), &region))
            continue;
        std::array<double, 3> lo{}, hi{};
        for (size_t axis = 0; axis < 3; ++axis) {
            lo[axis] = region.center[axis] - region.half[axis];
            hi[axis] = region.center[axis] + region.half[axis];
        }
        include(lo, hi);
    }
    for (Gripper hand : {Gripper::Left, Gripper::Right}) {
        const std::optional<HandCommand> &command = m_hands[size_t(hand)];
        m_maxGrip[size_t(hand)] = command ? world->maxGrip(hand) : 0.0;
        m_setpoint[size_t(hand)] = std::min(DefaultGrip, m_maxGrip[size_t(hand)]);
        if (command)
            include(command->target.pos, command->target.pos);
    }
    for (size_t axis = 0; axis < 2; ++axis) {
        m_workspace.center[axis] = (lower[axis] + upper[axis]) / 2;
        m_workspace.half[axis] = (upper[axis] - lower[axis]) / 2 + Margin;
    }
    m_workspace.center[2] = (LowestWrist + HighestWrist) / 2;
    m_workspace.half[2] = (HighestWrist - LowestWrist) / 2;
    emit changed();
}

void HandDrive::setStartSource(std::function<std::array<std::optional<HandCommand>, 2>()> source)
{
    m_startSource = std::move(source);
}

bool HandDrive::hasBothHands() const
{
    return m_hands[0] && m_hands[1];
}

const std::vector<DriveKey> &HandDrive::keyTable()
{
    static const std::vector<DriveKey> keys{
        {Qt::Key_W, DriveKeyAction::Away},
        {Qt::Key_S, DriveKeyAction::Toward},
        {Qt::Key_A, DriveKeyAction::Left},
        {Qt::Key_D, DriveKeyAction::Right},
        {Qt::Key_R, DriveKeyAction::Up},
        {Qt::Key_Up, DriveKeyAction::Up},
        {Qt::Key_PageUp, DriveKeyAction::Up},
        {Qt::Key_F, DriveKeyAction::Down},
        {Qt::Key_Down, DriveKeyAction::Down},
        {Qt::Key_PageDown, DriveKeyAction::Down},
        {Qt::Key_Q, DriveKeyAction::TurnLeft},
        {Qt::Key_Left, DriveKeyAction::TurnLeft},
        {Qt::Key_E, DriveKeyAction::TurnRight},
        {Qt::Key_Right, DriveKeyAction::TurnRight},
        {Qt::Key_Space, DriveKeyAction::Grip},
        {Qt::Key_G, DriveKeyAction::Grip},
        {Qt::Key_Plus, DriveKeyAction::MoreForce},
        {Qt::Key_Equal, DriveKeyAction::MoreForce},
        {Qt::Key_Minus, DriveKeyAction::LessForce},
        {Qt::Key_Tab, DriveKeyAction::SwitchHand},
        {Qt::Key_Backtab, DriveKeyAction::SwitchHand},
        {Qt::Key_Shift, DriveKeyAction::Slow},
    };
    return keys;
}

QString HandDrive::actionText(DriveKeyAction action)
{
    switch (action) {
    case DriveKeyAction::Away:
        return tr("Move the wrist away from you");
    case DriveKeyAction::Toward:
        return tr("Move the wrist towards you");
    case DriveKeyAction::Left:
        return tr("Move the wrist to the left");
    case DriveKeyAction::Right:
        return tr("Move the wrist to the right");
    case DriveKeyAction::Up:
        return tr("Raise the wrist");
    case DriveKeyAction::Down:
        return tr("Lower the wrist (it stops on what is below)");
    case DriveKeyAction::TurnLeft:
        return tr("Turn the wrist left");
    case DriveKeyAction::TurnRight:
        return tr("Turn the wrist right");
    case DriveKeyAction::Grip:
        return tr("Close or open the grip");
    case DriveKeyAction::MoreForce:
        return tr("Grip force up a step");
    case DriveKeyAction::LessForce:
        return tr("Grip force down a step");
    case DriveKeyAction::SwitchHand:
        return tr("Switch hand (scenes with two)");
    case DriveKeyAction::Slow:
        return tr("Hold: move at a quarter of the speed");
    }
    return QString();
}

bool HandDrive::press(int key, Qt::KeyboardModifiers modifiers)
{
    const std::optional<DriveKeyAction> action = actionOf(key);
    if (action == DriveKeyAction::Slow) {
        m_slow = true;
        return false;
    }
    m_slow = modifiers.testFlag(Qt::ShiftModifier);
    // Ctrl+R, Ctrl+F, Ctrl+= … are the window's shortcuts: they never take the grippers.
    if (modifiers & (Qt::ControlModifier | Qt::AltModifier | Qt::MetaModifier))
        return false;
    if (!action || !m_world || !m_hands[size_t(m_active)])
        return false;

    switch (*action) {
    case DriveKeyAction::Grip:
        toggleGrip();
        return true;
    case DriveKeyAction::MoreForce:
        adjustGrip(1);
        return true;
    case DriveKeyAction::LessForce:
        adjustGrip(-1);
        return true;
    case DriveKeyAction::SwitchHand:
        if (!hasBothHands())
            return false;
        switchHand();
        return true;
    default:
        break;
    }

    const size_t held = size_t(*action);
    startDrive();
    if (!m_held[held]) {
        m_held[held] = true;
        // A tap shorter than a tick still moves: one tick's worth now.
        const std::array<bool, HeldDriveKeyActions> before = m_held;
        m_held = {};
        m_held[held] = true;
        const DriveRates tap = heldRates();
        m_held = before;
        if (move(tap, TickSeconds)) {
            send(m_active);
            emit changed();
        }
    }
    updateTimer();
    return true;
}

bool HandDrive::release(int key)
{
    const std::optional<DriveKeyAction> action = actionOf(key);
    if (action == DriveKeyAction::Slow) {
        m_slow = false;
        return false;
    }
    if (!action || int(*action) >= HeldDriveKeyActions)
        return false;
    m_held[size_t(*action)] = false;
    updateTimer();
    return true;
}

void HandDrive::releaseAll()
{
    m_held = {};
    m_deviceRates = {};
    m_slow = false;
    updateTimer();
}

void HandDrive::toggleGrip()
{
    const size_t hand = size_t(m_active);
    if (!m_world || !m_hands[hand])
        return;
    startDrive();
    m_analogueGrip[hand].reset();
    m_closed[hand] = !m_closed[hand];
    updateTimer();
    emit changed();
}

void HandDrive::switchHand()
{
    if (!m_world || !hasBothHands())
        return;
    startDrive();
    m_active = m_active == Gripper::Right ? Gripper::Left : Gripper::Right;
    emit changed();
}

void HandDrive::setRates(DriveDevice device, const DriveRates &rates)
{
    DriveRates &was = m_deviceRates[size_t(device)];
    // A device's first report is where its trigger rests, not a move.
    const bool gripMoved =
        rates.grip && was.grip && std::abs(*rates.grip - *was.grip) > GripDeadband;
    const bool wasIdle = was.isIdle();
    std::optional<double> lastGrip = was.grip;
    was = rates;
    // An unchanged trigger keeps its last taken value, so a small drift never takes the grip.
    if (lastGrip && rates.grip && !gripMoved)
        was.grip = lastGrip;
    const size_t hand = size_t(m_active);
    if (!m_world || !m_hands[hand]) {
        was = DriveRates();
        return;
    }
    if (!rates.isIdle() || gripMoved)
        startDrive();
    if (gripMoved && m_driving) {
        m_analogueGrip[hand] = std::clamp(*rates.grip, 0.0, 1.0);
        m_closed[hand] = *m_analogueGrip[hand] > 0.0;
        emit changed();
    }
    if (wasIdle && !rates.isIdle()) {
        // Like a key's tap: a flick shorter than a tick still moves.
        if (move(heldRates(), TickSeconds)) {
            send(m_active);
            emit changed();
        }
    }
    updateTimer();
}

void HandDrive::setSpeed(double metresPerSecond)
{
    m_speed = std::clamp(metresPerSecond, MinSpeed, MaxSpeed);
}

DriveStatus HandDrive::status(Gripper hand) const
{
    return m_operator ? m_operator->status(hand) : DriveStatus();
}

void HandDrive::adjustGrip(int notches)
{
    const size_t hand = size_t(m_active);
    if (!m_world || !m_hands[hand] || notches == 0)
        return;
    startDrive();
    m_setpoint[hand] =
        std::clamp(m_setpoint[hand] + notches * GripStep, GripStep, m_maxGrip[hand]);
    updateTimer();
    emit changed();
}

void HandDrive::endDrive()
{
    releaseAll();
    m_driving = false;
    emit changed();
}

void HandDrive::startDrive()
{
    if (m_driving || !m_world)
        return;
    m_driving = true;
    // Start driving where the hands are now, so nothing jumps. A closed grip ramps from the
    // operator's force to the user's setpoint (the scripted one may squeeze past the break
    // line): the setpoint is the user's, 30 N until they change it.
    m_hands = m_startSource ? m_startSource() : currentCommands(*m_world);
    for (size_t hand = 0; hand < 2; ++hand) {
        if (!m_hands[hand])
            continue;
        m_closed[hand] = m_hands[hand]->grip > 0;
        m_analogueGrip[hand].reset();
        send(Gripper(hand));
    }
    m_clock.start();
    updateTimer();
    emit driveStarted();
}

void HandDrive::tick()
{
    const double seconds = std::min(double(m_clock.restart()) / 1000.0, LongestTick);
    advance(seconds);
}

void HandDrive::advance(double seconds)
{
    if (!m_driving)
        return;
    const bool moved = move(heldRates(), seconds);
    if (moved)
        send(m_active);
    if (ramp(seconds) || moved)
        emit changed();
    updateTimer();
}

DriveRates HandDrive::heldRates() const
{
    auto key = [this](DriveKeyAction action) { return m_held[size_t(action)] ? 1.0 : 0.0; };
    DriveRates sum;
    sum.forward = key(DriveKeyAction::Away) - key(DriveKeyAction::Toward);
    sum.right = key(DriveKeyAction::Right) - key(DriveKeyAction::Left);
    sum.up = key(DriveKeyAction::Up) - key(DriveKeyAction::Down);
    sum.turn = key(DriveKeyAction::TurnLeft) - key(DriveKeyAction::TurnRight);
    for (const DriveRates &device : m_deviceRates) {
        sum.forward += device.forward;
        sum.right += device.right;
        sum.up += device.up;
        sum.turn += device.turn;
        sum.tilt += device.tilt;
        sum.roll += device.roll;
    }
    for (double *rate : {&sum.forward, &sum.right, &sum.up, &sum.turn, &sum.tilt, &sum.roll})
        *rate = std::clamp(*rate, -1.0, 1.0);
    return sum;
}

bool HandDrive::move(const DriveRates &rates, double seconds)
{
    if (rates.isIdle())
        return false;
    HandCommand &hand = *m_hands[size_t(m_active)];
    const double scale = m_speed / DefaultSpeed * (m_slow ? SlowFactor : 1.0);
    const double step = m_speed * seconds * (m_slow ? SlowFactor : 1.0);
    const auto [awayX, awayY] = awayDirection();

    const std::array<double, 3> delta{step * (rates.forward * awayX + rates.right * awayY),
                                      step * (rates.forward * awayY - rates.right * awayX),
                                      step * rates.up};
    // The guard: while the fingers rest on something, the target stays above the floor the
    // simulation reports, so releasing "down" and pressing "up" lifts at once. Landing, the
    // simulation lowers the target slower than the keys did: "up" starts from its target.
    const DriveStatus now = status(m_active);
    for (size_t axis = 0; axis < 3; ++axis) {
        const double lo = m_workspace.center[axis] - m_workspace.half[axis];
        const double hi = m_workspace.center[axis] + m_workspace.half[axis];
        double from = hand.target.pos[axis];
        if (axis == 2 && now.driven && delta[2] > 0)
            from = std::max(from, now.target.pos[2]);
        double next = from + delta[axis];
        if (axis == 2 && now.floor && delta[2] < 0)
            next = std::max(next, *now.floor);
        hand.target.pos[axis] = std::clamp(next, lo, hi);
    }
    const double turnStep = TurnRate * seconds * scale;
    if (rates.turn != 0)
        hand.target = turnedAboutVertical(hand.target, rates.turn * turnStep);
    if (rates.tilt != 0 || rates.roll != 0) {
        // Tilt swings the fingers away (about the viewer's right), roll to the right (about
        // the view's away axis); a step that would lean past MaxTilt is shortened.
        const std::array<double, 3> rightAxis{awayY, -awayX, 0.0};
        const std::array<double, 3> awayAxis{awayX, awayY, 0.0};
        for (double fraction = 1.0; fraction > 1.0 / 64; fraction /= 2) {
            Pose leaned = turnedAbout(hand.target, rightAxis, rates.tilt * turnStep * fraction);
            leaned = turnedAbout(leaned, awayAxis, -rates.roll * turnStep * fraction);
            if (tiltFromVertical(leaned) <= MaxTilt ||
                tiltFromVertical(leaned) < tiltFromVertical(hand.target)) {
                hand.target = leaned;
                break;
            }
        }
    }
    return true;
}

void HandDrive::setViewAzimuth(double degrees)
{
    m_nextViewAzimuth = degrees;
    // Turning the keys under a held one reversed the hand: a Follow view that went round
    // to see it sent it back, and round again.
    if (heldRates().isIdle())
        m_viewAzimuth = degrees;
}

std::array<double, 2> HandDrive::awayDirection() const
{
    // Along the table axes nearest the view: a slanted camera still moves the hand straight.
    const double azimuth = Pi / 2 * std::round(m_viewAzimuth / 90.0);
    return {std::round(std::cos(azimuth)), std::round(std::sin(azimuth))};
}

double HandDrive::gripGoal(size_t hand) const
{
    if (m_analogueGrip[hand])
        return *m_analogueGrip[hand] > 0.0 ? *m_analogueGrip[hand] * m_setpoint[hand] : OpenGrip;
    return m_closed[hand] ? m_setpoint[hand] : OpenGrip;
}

bool HandDrive::ramp(double seconds)
{
    bool changed = false;
    for (size_t index = 0; index < 2; ++index) {
        const double goal = gripGoal(index);
        if (!m_hands[index] || m_hands[index]->grip == goal)
            continue;
        HandCommand &hand = *m_hands[index];
        const double step = GripRate * seconds;
        hand.grip =
            hand.grip < goal ? std::min(goal, hand.grip + step) : std::max(goal, hand.grip - step);
        if (m_operator)
            m_operator->setGrip(Gripper(index), hand.grip);
        changed = true;
    }
    return changed;
}

void HandDrive::send(Gripper hand)
{
    if (!m_operator)
        return;
    m_operator->setCommand(*m_hands[size_t(hand)]);
}

void HandDrive::updateTimer()
{
    const bool moving = !heldRates().isIdle();
    if (!moving)
        m_viewAzimuth = m_nextViewAzimuth;
    bool busy = moving;
    for (size_t hand = 0; hand < 2; ++hand)
        busy = busy || (m_driving && m_hands[hand] && m_hands[hand]->grip != gripGoal(hand));
    if (busy && !m_timer.isActive()) {
        m_clock.restart();
        m_timer.start();
    } else if (!busy) {
        m_timer.stop();
    }
}

} // namespace semhap
