// SPDX-License-Identifier: MIT
// Gamepads through their real input path: SDL's virtual joysticks are plugged in, moved and
// unplugged while GamepadInput polls SDL, and the hand drive and the simulation follow:
// sticks at their deflection, dead zones that leave the operator alone, an analogue grip,
// buttons, remapping, hot-plug, and a person's pick-and-place over the partition.
#include "driveoperator.h"
#include "gamepadinput.h"
#include "handdrive.h"
#include "world.h"

#include <QSignalSpy>
#include <QTest>

#include <SDL.h>

#include <QSet>

#include <cmath>

using namespace semhap;

namespace {

/** An SDL virtual game controller with every standard axis and button. */
class VirtualPad
{
public:
    VirtualPad()
    {
        SDL_VirtualJoystickDesc desc;
        SDL_zero(desc);
        desc.version = SDL_VIRTUAL_JOYSTICK_DESC_VERSION;
        desc.type = SDL_JOYSTICK_TYPE_GAMECONTROLLER;
        desc.naxes = SDL_CONTROLLER_AXIS_MAX;
        desc.nbuttons = SDL_CONTROLLER_BUTTON_MAX;
        desc.axis_mask = (1u << SDL_CONTROLLER_AXIS_MAX) - 1;
        desc.button_mask = (1u << SDL_CONTROLLER_BUTTON_MAX) - 1;
        desc.name = "semhap virtual pad";
        m_index = SDL_JoystickAttachVirtualEx(&desc);
        if (m_index < 0)
            qFatal("cannot attach a virtual joystick: %s", SDL_GetError());
        m_joystick = SDL_JoystickOpen(m_index);
        // Triggers rest at the bottom of the joystick's range.
        setAxis(SDL_CONTROLLER_AXIS_TRIGGERLEFT, -1.0);
        setAxis(SDL_CONTROLLER_AXIS_TRIGGERRIGHT, -1.0);
    }
    ~VirtualPad() { unplug(); }

    /** A stick axis in [-1, 1]; a trigger from -1 (released) to 1 (pulled). */
    void setAxis(SDL_GameControllerAxis axis, double value)
    {
        SDL_JoystickSetVirtualAxis(m_joystick, axis, Sint16(std::lround(value * 32767)));
    }
    /** A trigger pulled by `fraction` of its travel. */
    void setTrigger(SDL_GameControllerAxis axis, double fraction)
    {
        setAxis(axis, 2 * fraction - 1);
    }
    void setButton(SDL_GameControllerButton button, bool down)
    {
        SDL_JoystickSetVirtualButton(m_joystick, button, down ? 1 : 0);
    }
    void unplug()
    {
        if (!m_joystick)
            return;
        const SDL_JoystickID id = SDL_JoystickInstanceID(m_joystick);
        SDL_JoystickClose(m_joystick);
        m_joystick = nullptr;
        for (int i = 0; i < SDL_NumJoysticks(); ++i) {
            if (SDL_JoystickGetDeviceInstanceID(i) == id)
                SDL_JoystickDetachVirtual(i);
        }
    }

private:
    int m_index = -1;
    SDL_Joystick *m_joystick = nullptr;
};

} // namespace

class TestGamepad : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase();
    void init();
    void cleanup();
    void mappingRoundTrips();
    void badMappingsAreLocated_data();
    void badMappingsAreLocated();
    void sticksDriveAtTheirDeflection();
    void deadZoneLeavesTheOperatorAlone();
    void triggerGripsInProportion();
    void buttonsDoTheirActions();
    void remappedControlsDrive();
    void unpluggingStopsTheWrist();
    void pickAndPlaceOverThePartition();

private:
    /** Polls the pad, then integrates `seconds` of drive and physics, tick by tick. */
    void run(double seconds);

    std::unique_ptr<World> m_world;
    /** The largest force on the right fingertips (N, both) since it was last reset. */
    double m_peak = 0.0;
    std::unique_ptr<DriveOperator> m_operator;
    std::unique_ptr<HandDrive> m_drive;
    std::unique_ptr<GamepadInput> m_input;
    std::unique_ptr<VirtualPad> m_pad;
};

void TestGamepad::initTestCase()
{
    SDL_SetHint(SDL_HINT_NO_SIGNAL_HANDLERS, "1");
    QVERIFY2(SDL_InitSubSystem(SDL_INIT_GAMECONTROLLER) == 0, SDL_GetError());
}

void TestGamepad::cleanupTestCase()
{
    SDL_QuitSubSystem(SDL_INIT_GAMECONTROLLER);
}

void TestGamepad::init()
{
    QString error;
    m_world = World::load("box_and_block", SceneOptions{4, {}}, &error);
    QVERIFY2(m_world, qPrintable(error));
    m_operator = std::make_unique<DriveOperator>();
    m_drive = std::make_unique<HandDrive>();
    m_drive->setOperator(m_operator.get());
    m_drive->setWorld(m_world.get());
    m_pad = std::make_unique<VirtualPad>();
    m_input = std::make_unique<GamepadInput>();
    m_input->setDrive(m_drive.get());
    QVERIFY2(m_input->start(), qPrintable(m_input->errorString()));
    QCOMPARE(m_input->controllers(), QStringList{"semhap virtual pad"});
}

void TestGamepad::cleanup()
{
    m_input.reset();
    m_pad.reset();
    m_drive.reset();
}

void TestGamepad::run(double seconds)
{
    const int stepsPerTick = int(std::lround(1.0 / 60 / m_world->timestep()));
    for (int tick = 0; tick < int(std::lround(seconds * 60)); ++tick) {
        m_input->poll();
        m_drive->advance(1.0 / 60);
        for (int k = 0; k < stepsPerTick; ++k) {
            m_operator->act(*m_world);
            m_world->step();
            m_peak = std::max(m_peak, m_world->frame(Gripper::Right).totalForce());
        }
    }
}

void TestGamepad::mappingRoundTrips()
{
    GamepadMapping mapping = GamepadMapping::defaults();
    mapping.motions[GamepadMapping::Turn] = "leftshoulder+rightshoulder";
    mapping.actions[GamepadMapping::NextCamera] = QString();
    mapping.deadZone = 0.25;
    QString error;
    const std::optional<GamepadMapping> back =
        GamepadMapping::fromString(mapping.toString(), &error);
    QVERIFY2(back, qPrintable(error));
    QVERIFY(*back == mapping);
    // Keys left out keep their defaults.
    QVERIFY(*GamepadMapping::fromString("grip=lefttrigger", &error) != GamepadMapping::defaults());
    QCOMPARE(GamepadMapping::fromString("", &error)->motions, GamepadMapping::defaults().motions);
}

void TestGamepad::badMappingsAreLocated_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("error");
    QTest::newRow("unknown axis") << "turn=rightz"
                                  << "key 'turn': unknown control 'rightz'";
    QTest::newRow("button for a motion") << "up=a"
                                         << "key 'up': unknown control 'a'";
    QTest::newRow("axis for an action") << "handback=leftx"
                                        << "key 'handback': unknown button 'leftx'";
    QTest::newRow("unknown key") << "jump=a"
                                 << "key 'jump': unknown key";
    QTest::newRow("no value") << "forward"
                              << "key 'forward': expected key=value";
    QTest::newRow("dead zone") << "deadzone=1.5"
                               << "key 'deadzone': expected a number from 0 to 0.9";
}

void TestGamepad::badMappingsAreLocated()
{
    QFETCH(QString, text);
    QFETCH(QString, error);
    QString message;
    QVERIFY(!GamepadMapping::fromString(text, &message));
    QCOMPARE(message, error);
}

void TestGamepad::sticksDriveAtTheirDeflection()
{
    QSignalSpy started(m_drive.get(), &HandDrive::driveStarted);
    m_drive->setViewAzimuth(0.0); // forward is +x, right is -y
    const Pose before = m_world->target(Gripper::Right);
    m_pad->setAxis(SDL_CONTROLLER_AXIS_LEFTY, -1.0);  // left stick pushed away: forward
    m_pad->setAxis(SDL_CONTROLLER_AXIS_RIGHTY, -0.5); // right stick half up
    run(0.5);
    QCOMPARE(started.count(), 1);
    QCOMPARE(m_input->activeController(), QString("semhap virtual pad"));
    m_pad->setAxis(SDL_CONTROLLER_AXIS_LEFTY, 0.0);
    m_pad->setAxis(SDL_CONTROLLER_AXIS_RIGHTY, 0.0);
    run(0.2); // released: the wrist stops
    const Pose after = m_world->target(Gripper::Right);
    const double speed = m_drive->speed();
    // Half a second of full deflection (the flick's first tick included) …
    QVERIFY2(std::abs((after.pos[0] - before.pos[0]) - speed * (0.5 + 1.0 / 60)) < 0.003,
             qPrintable(QString::number(after.pos[0] - before.pos[0])));
    // … and of half deflection past the dead zone: (0.5 - 0.15) / 0.85 of full speed.
    const double half = (0.5 - 0.15) / 0.85;
    QVERIFY2(std::abs((after.pos[2] - before.pos[2]) - half * speed * (0.5 + 1.0 / 60)) < 0.003,
             qPrintable(QString::number(after.pos[2] - before.pos[2])));
    QVERIFY(std::abs(after.pos[1] - before.pos[1]) < 1e-9);
}

void TestGamepad::deadZoneLeavesTheOperatorAlone()
{
    QSignalSpy started(m_drive.get(), &HandDrive::driveStarted);
    m_pad->setAxis(SDL_CONTROLLER_AXIS_LEFTX, 0.12); // a worn stick resting off-centre
    m_pad->setAxis(SDL_CONTROLLER_AXIS_RIGHTY, -0.1);
    run(0.5);
    QCOMPARE(started.count(), 0);
    QVERIFY(!m_drive->isDriving());
}

void TestGamepad::triggerGripsInProportion()
{
    m_pad->setTrigger(SDL_CONTROLLER_AXIS_TRIGGERRIGHT, 0.5);
    run(0.5);
    QVERIFY(m_drive->isDriving());
    QVERIFY(m_drive->isClosed(Gripper::Right));
    // The drive's command (closing on nothing, the simulation's guarded close holds the
    // fingers to their approach force; tests/handdrive).
    const double setpoint = m_drive->gripSetpoint(Gripper::Right);
    const auto grip = [&] { return m_drive->command(Gripper::Right)->grip; };
    QVERIFY2(std::abs(grip() - 0.5 * setpoint) < 0.01 * setpoint,
             qPrintable(QString::number(grip())));
    m_pad->setTrigger(SDL_CONTROLLER_AXIS_TRIGGERRIGHT, 1.0);
    run(0.5);
    QVERIFY(std::abs(grip() - setpoint) < 0.01 * setpoint);
    m_pad->setTrigger(SDL_CONTROLLER_AXIS_TRIGGERRIGHT, 0.0);
    run(0.5);
    QVERIFY(!m_drive->isClosed(Gripper::Right));
    QCOMPARE(m_world->grip(Gripper::Right), HandDrive::OpenGrip);
}

void TestGamepad::buttonsDoTheirActions()
{
    QSignalSpy triggered(m_input.get(), &GamepadInput::triggered);
    auto tap = [&](SDL_GameControllerButton button) {
        m_pad->setButton(button, true);
        run(0.05);
        m_pad->setButton(button, false);
        run(0.05);
    };
    tap(SDL_CONTROLLER_BUTTON_A);
    QVERIFY(m_drive->isDriving());
    const bool closed = m_drive->isClosed(Gripper::Right);
    tap(SDL_CONTROLLER_BUTTON_A);
    QCOMPARE(m_drive->isClosed(Gripper::Right), !closed);
    const double grip = m_drive->gripSetpoint(Gripper::Right);
    tap(SDL_CONTROLLER_BUTTON_DPAD_UP);
    QCOMPARE(m_drive->gripSetpoint(Gripper::Right), grip + HandDrive::GripStep);
    tap(SDL_CONTROLLER_BUTTON_DPAD_DOWN);
    QCOMPARE(m_drive->gripSetpoint(Gripper::Right), grip);
    // One hand in this scene: Y has no other hand to switch to.
    tap(SDL_CONTROLLER_BUTTON_Y);
    QCOMPARE(m_drive->activeHand(), Gripper::Right);
    // The window's actions are announced, not done here.
    tap(SDL_CONTROLLER_BUTTON_B);
    tap(SDL_CONTROLLER_BUTTON_X);
    QCOMPARE(triggered.count(), 2);
    QCOMPARE(triggered.at(0).at(0).value<GamepadMapping::Action>(), GamepadMapping::HandBack);
    QCOMPARE(triggered.at(1).at(0).value<GamepadMapping::Action>(), GamepadMapping::NextCamera);
}

void TestGamepad::remappedControlsDrive()
{
    GamepadMapping mapping = GamepadMapping::defaults();
    mapping.motions[GamepadMapping::Up] = "dpdown+dpup";
    mapping.actions[GamepadMapping::GripStronger] = QString();
    mapping.actions[GamepadMapping::GripWeaker] = QString();
    mapping.motions[GamepadMapping::Grip] = "lefttrigger";
    m_input->setMapping(mapping);
    const double z = m_world->target(Gripper::Right).pos[2];
    m_pad->setButton(SDL_CONTROLLER_BUTTON_DPAD_UP, true);
    run(0.3);
    m_pad->setButton(SDL_CONTROLLER_BUTTON_DPAD_UP, false);
    run(0.1);
    QVERIFY(m_world->target(Gripper::Right).pos[2] > z + 0.03);
    // The right trigger no longer grips; the left one does.
    m_pad->setTrigger(SDL_CONTROLLER_AXIS_TRIGGERRIGHT, 1.0);
    run(0.3);
    QVERIFY(!m_drive->isClosed(Gripper::Right));
    m_pad->setTrigger(SDL_CONTROLLER_AXIS_TRIGGERLEFT, 1.0);
    run(0.3);
    QVERIFY(m_drive->isClosed(Gripper::Right));
}

void TestGamepad::unpluggingStopsTheWrist()
{
    QSignalSpy changed(m_input.get(), &GamepadInput::controllersChanged);
    m_pad->setAxis(SDL_CONTROLLER_AXIS_LEFTX, 1.0);
    run(0.2);
    QVERIFY(m_drive->isDriving());
    m_pad->unplug();
    run(0.1);
    QCOMPARE(changed.count(), 1);
    QVERIFY(m_input->controllers().isEmpty());
    QVERIFY(m_input->activeController().isEmpty());
    const Pose stopped = m_world->target(Gripper::Right);
    run(0.5);
    QCOMPARE(m_world->target(Gripper::Right).pos, stopped.pos);
    // Plugged in again: it drives again.
    m_pad = std::make_unique<VirtualPad>();
    run(0.1);
    QCOMPARE(changed.count(), 2);
    m_pad->setAxis(SDL_CONTROLLER_AXIS_LEFTX, 1.0);
    run(0.2);
    QVERIFY(m_world->target(Gripper::Right).pos != stopped.pos);
}

void TestGamepad::pickAndPlaceOverThePartition()
{
    // A scripted person with a gamepad moves cubes from the pick side over the partition,
    // through the real input path: they look at the scene ten times a second (where the
    // cube, the wrist target and its floor are), push the sticks in proportion to what is
    // left to go, hold "down" until the guarded move stops the fingers, pull the trigger,
    // lift, carry, lower until the guard stops again, and let go. The camera looks across
    // the jaws (along +x): forward is +x, right is -y.
    m_drive->setViewAzimuth(0.0);
    const double travel = 0.25; // wrist height to carry at: clears the partition
    const double limit = 60.0;  // simulated seconds
    const double start = m_world->time();
    enum Phase
    {
        Approach,
        Descend,
        Grip,
        Lift,
        Carry,
        Lower,
        Release,
        Rise
    } phase = Approach;
    int cube = -1;
    double phaseStart = start;
    QList<double> transferTimes;
    QSet<int> placed;
    int breaks = 0;
    auto setPhase = [&](Phase next) {
        phase = next;
        phaseStart = m_world->time();
    };
    auto steer = [&](const std::array<double, 3> &goal) {
        // Full deflection 3 cm or more away, in proportion closer in (past the dead zone).
        const Pose target = m_drive->command(Gripper::Right)->target;
        auto stick = [](double error) {
            const double want = std::clamp(error / 0.03, -1.0, 1.0);
            return std::abs(want) < 0.02 ? 0.0 : std::copysign(0.15 + 0.85 * std::abs(want), want);
        };
        m_pad->setAxis(SDL_CONTROLLER_AXIS_LEFTY, -stick(goal[0] - target.pos[0]));
        m_pad->setAxis(SDL_CONTROLLER_AXIS_LEFTX, -stick(goal[1] - target.pos[1]));
        m_pad->setAxis(SDL_CONTROLLER_AXIS_RIGHTY, -stick(goal[2] - target.pos[2]));
        return std::hypot(goal[0] - target.pos[0], goal[1] - target.pos[1]) < 0.004 &&
               std::abs(goal[2] - target.pos[2]) < 0.004;
    };
    while (m_world->time() - start < limit && placed.size() < 3) {
        run(0.1);
        breaks = 0;
        for (const SceneObject &object : m_world->objects())
            breaks += object.broken ? 1 : 0;
        const double now = m_world->time();
        const DriveStatus status = m_drive->status(Gripper::Right);
        const Pose target = m_drive->command(Gripper::Right)->target;
        switch (phase) {
        case Approach: {
            // The nearest whole cube still on the pick side.
            cube = -1;
            double nearest = 1e9;
            for (int i = 0; i < int(m_world->objects().size()); ++i) {
                const auto p = m_world->objectPosition(i);
                const double distance = std::hypot(p[0] - target.pos[0], p[1] - target.pos[1]);
                if (!m_world->objects()[size_t(i)].broken && p[0] < -0.02 && distance < nearest) {
                    nearest = distance;
                    cube = i;
                }
            }
            QVERIFY2(cube >= 0, "no cube left on the pick side");
            const auto p = m_world->objectPosition(cube);
            if (steer({p[0], p[1], travel}))
                setPhase(Descend);
            break;
        }
        case Descend: {
            const auto p = m_world->objectPosition(cube);
            steer({p[0], p[1], target.pos[2]});
            m_pad->setAxis(SDL_CONTROLLER_AXIS_RIGHTY, 1.0); // "down", held
            if (status.floor) {
                m_pad->setAxis(SDL_CONTROLLER_AXIS_RIGHTY, 0.0);
                setPhase(Grip);
            }
            break;
        }
        case Grip:
            steer(target.pos);
            m_pad->setTrigger(SDL_CONTROLLER_AXIS_TRIGGERRIGHT, 1.0);
            if (now - phaseStart > 0.5)
                setPhase(Lift);
            break;
        case Lift:
            if (steer({target.pos[0], target.pos[1], travel})) {
                m_peak = 0.0;
                setPhase(Carry);
            }
            break;
        case Carry:
            if (steer({0.15, 0.0, travel}))
                setPhase(Lower);
            break;
        case Lower:
            steer({0.15, 0.0, target.pos[2]});
            m_pad->setAxis(SDL_CONTROLLER_AXIS_RIGHTY, 1.0);
            if (status.floor) {
                m_pad->setAxis(SDL_CONTROLLER_AXIS_RIGHTY, 0.0);
                setPhase(Release);
            }
            break;
        case Release:
            steer(target.pos);
            m_pad->setTrigger(SDL_CONTROLLER_AXIS_TRIGGERRIGHT, 0.0);
            if (now - phaseStart > 0.4)
                setPhase(Rise);
            break;
        case Rise:
            if (steer({target.pos[0], target.pos[1], travel})) {
                // Carried and set down with what the trigger commands, never a knock.
                const double bound = 1.5 * m_drive->gripSetpoint(Gripper::Right);
                QVERIFY2(m_peak <= bound, qPrintable(QString("carry: %1 N").arg(m_peak)));
                const auto p = m_world->objectPosition(cube);
                if (p[0] > 0.01 && !placed.contains(cube)) {
                    placed.insert(cube);
                    transferTimes << now - start;
                }
                setPhase(Approach);
            }
            break;
        }
    }
    QStringList times;
    for (double t : transferTimes)
        times << QString::number(t, 'f', 1);
    qInfo("gamepad pick-and-place: %d transfers in %.1f s (at %s s), %d broken",
          int(transferTimes.size()), m_world->time() - start, qPrintable(times.join(", ")),
          breaks);
    QVERIFY(!transferTimes.isEmpty());
    QCOMPARE(breaks, 0);
}

QTEST_MAIN(TestGamepad)
#include "tst_gamepad.moc"
