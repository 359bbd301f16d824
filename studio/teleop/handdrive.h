// SPDX-License-Identifier: MIT
#pragma once

#include "driveoperator.h"

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

#include <array>
#include <functional>
#include <optional>
#include <vector>

namespace semhap {

class DriveOperator;

/** The analogue devices that drive beside the keyboard. */
enum class DriveDevice
{
    Gamepad,
    SpaceMouse,
};
constexpr int DriveDeviceCount = 2;

/**
 * What an analogue device asks of the active hand now: rates in [-1, 1] of the drive's full
 * speeds (dead zones already taken out), in the frame the keyboard's keys use.
 */
struct DriveRates
{
    double forward = 0.0; ///< away from the viewer, along the table axis nearest the view
    double right = 0.0;   ///< to the viewer's right
    double up = 0.0;
    double turn = 0.0; ///< about the vertical, counter-clockwise seen from above
    double tilt = 0.0; ///< the fingers swing away from the viewer
    double roll = 0.0; ///< the fingers swing to the viewer's right
    /**
     * An analogue grip in [0, 1] (a trigger): 0 opens, 1 closes with the hand's grip force.
     * None: the device has no grip control. A value only takes the grip when it changes.
     */
    std::optional<double> grip;

    bool isIdle() const
    {
        return forward == 0 && right == 0 && up == 0 && turn == 0 && tilt == 0 && roll == 0;
    }
};

/** What a key of the keyboard drive does. */
enum class DriveKeyAction
{
    // Held: the active hand moves while the key is down.
    Away,
    Toward,
    Left,
    Right,
    Up,
    Down,
    TurnLeft,
    TurnRight,
    // Pressed.
    Grip,
    MoreForce,
    LessForce,
    SwitchHand,
    Slow, ///< held with the others: they move at HandDrive::SlowFactor of the speed
};
/** How many of DriveKeyAction's first values move the hand while held. */
constexpr int HeldDriveKeyActions = int(DriveKeyAction::TurnRight) + 1;

/** A key of the keyboard drive and what it does. */
struct DriveKey
{
    Qt::Key key;
    DriveKeyAction action;
};

/**
 * The user's rate-controlled teleoperation of the grippers: held keys and the analogue
 * devices (gamepad, 3D mouse; see GamepadInput, SpaceMouseInput) move the active gripper's
 * wrist at rates, integrated at display rate, inside a workspace around the scene's task;
 * a key, a button or a trigger closes or opens the grip through a ramp (a guarded close,
 * never a step). Commands go to a DriveOperator, whose guard the drive follows: a target
 * does not descend below the floor the fingers rest on. No widgets: the viewport forwards
 * its key events here, and tests drive it directly. The key map is in docs/studio.md.
 */
class HandDrive : public QObject
{
    Q_OBJECT

public:
    /** Full wrist speed (m/s) until setSpeed(); Shift moves at SlowFactor of it. */
    static constexpr double DefaultSpeed = 0.15;
    /** The speeds setSpeed() accepts (m/s). */
    static constexpr double MinSpeed = 0.02;
    static constexpr double MaxSpeed = 0.5;
    static constexpr double SlowFactor = 0.25;
    /** Wrist turn and tilt rate at full deflection (rad/s). */
    static constexpr double TurnRate = 1.5;
    /** How far the fingers may lean from pointing straight down (rad): 40°. */
    static constexpr double MaxTilt = 0.7;
    /** How fast the grip command ramps (N/s): a 30 N close takes 0.2 s. */
    static constexpr double GripRate = 150.0;
    /** The force a close ramps to until the user changes it (N), and its step. */
    static constexpr double DefaultGrip = 30.0;
    static constexpr double GripStep = 5.0;
    /** What an open gripper is commanded (N): the fingers spread. */
    static constexpr double OpenGrip = -20.0;

    explicit HandDrive(QObject *parent = nullptr);
    ~HandDrive() override;

    /** Where the commands go (null: nowhere). Not owned. */
    void setOperator(DriveOperator *op) { m_operator = op; }
    /**
     * The scene to drive (null clears): its hands, its workspace and its maximum grip.
     * Disengages: the next input starts from the world's targets again.
     */
    void setWorld(const World *world);

    /**
     * How starting to drive learns where the hands are now. By default it reads the world's
     * targets on the GUI thread, which is safe only while the world is not being stepped;
     * an engine stepping it on another thread hands in a reader that waits for a tick's end.
     */
    void setStartSource(std::function<std::array<std::optional<HandCommand>, 2>()> source);

    /**
     * Every key the keyboard drive answers, in the order the key map lists them: press() and
     * release() go by this table, and Help → Key map shows it. A key held with Ctrl, Alt or
     * Meta is the window's, never the drive's.
     */
    static const std::vector<DriveKey> &keyTable();
    /** What `action` does, translated, for the key map. */
    static QString actionText(DriveKeyAction action);

    /** A key went down; true when it is one of the map's (the caller then eats it). */
    bool press(int key, Qt::KeyboardModifiers modifiers = Qt::NoModifier);
    /** A key came up; true when it is one of the map's. */
    bool release(int key);
    /** Stops every movement, as if all keys came up (focus left the viewport). */
    void releaseAll();
    /** Changes the active hand's grip force by `notches` steps (Ctrl + wheel, +/-). */
    void adjustGrip(int notches);
    /** Closes the active hand if it is open, opens it if closed (Space, a button). */
    void toggleGrip();
    /** Makes the other hand the active one, when the scene has two (Tab, a button). */
    void switchHand();

    /**
     * What `device` asks for now (it sends this whenever it changes, or zeros when it goes
     * away). The first rate or grip change takes the grippers, as a key does; the device's
     * rates add to the keys' and to the other device's.
     */
    void setRates(DriveDevice device, const DriveRates &rates);
    /** The full wrist speed (m/s) at a held key or full deflection; turning scales with it. */
    void setSpeed(double metresPerSecond);
    double speed() const { return m_speed; }
    /** Moves by what the held keys and grip ramps do in `seconds` (the timer's tick). */
    void advance(double seconds);

    /**
     * Takes the grippers where the hands are now (the start source says where), as the first
     * input does, and sends each hand's command: the wrist targets are known, and shown, at
     * once (Drive). Emits driveStarted(); nothing while already driving.
     */
    void startDrive();
    /**
     * Hands control back to the scripted operator: the next input starts driving again from
     * wherever the world's targets are then, and emits driveStarted() again.
     */
    void endDrive();
    bool isDriving() const { return m_driving; }

    Gripper activeHand() const { return m_active; }
    /** Whether Tab has a hand to switch to. */
    bool hasBothHands() const;
    /** What the simulation made of `hand`'s command (the guard, the surface below). */
    DriveStatus status(Gripper hand) const;
    /** What `hand` is being commanded. */
    const std::optional<HandCommand> &command(Gripper hand) const { return m_hands[size_t(hand)]; }
    /** The force `hand` closes to (N). */
    double gripSetpoint(Gripper hand) const { return m_setpoint[size_t(hand)]; }
    bool isClosed(Gripper hand) const { return m_closed[size_t(hand)]; }

    /**
     * The camera's azimuth (degrees, MuJoCo's): W moves away from the viewer along the table
     * axis nearest the view, D moves to the viewer's right. While the hand moves, its
     * directions stay as they were: a view that turns then (Follow going round to see the
     * hand, an orbit) takes effect once every key and stick is let go.
     */
    void setViewAzimuth(double degrees);
    /** The table axis W moves along, as a unit (x, y): the one nearest the view. */
    std::array<double, 2> awayDirection() const;
    /** Where the wrist may go: the task's regions with some room around them. */
    const Region &workspace() const { return m_workspace; }

signals:
    /** The first input after setWorld() or endDrive(): the user takes the grippers. */
    void driveStarted();
    /** The active hand, a target or a grip changed (the HUD redraws). */
    void changed();

private:
    void tick();
    /** The keys' rates and every device's, added up, each in [-1, 1]. */
    DriveRates heldRates() const;
    /** Moves the active hand at `rates` over `seconds`; true if it moved. */
    bool move(const DriveRates &rates, double seconds);
    /** The force `hand`'s grip ramps to now. */
    double gripGoal(size_t hand) const;
    /** Ramps every hand's grip towards its goal; true if a grip changed. */
    bool ramp(double seconds);
    void send(Gripper hand);
    void updateTimer();

    const World *m_world = nullptr;
    std::function<std::array<std::optional<HandCommand>, 2>()> m_startSource;
    DriveOperator *m_operator = nullptr;
    std::array<std::optional<HandCommand>, 2> m_hands{};
    std::array<double, 2> m_setpoint{DefaultGrip, DefaultGrip};
    std::array<bool, 2> m_closed{};
    std::array<double, 2> m_maxGrip{};
    std::array<bool, HeldDriveKeyActions> m_held{}; ///< by DriveKeyAction
    std::array<DriveRates, DriveDeviceCount> m_deviceRates{};
    /** Per hand: the analogue grip in [0, 1] that owns its grip, until a key toggles it. */
    std::array<std::optional<double>, 2> m_analogueGrip{};
    double m_speed = DefaultSpeed;
    Gripper m_active = Gripper::Right;
    Region m_workspace;
    double m_viewAzimuth = 90.0;
    double m_nextViewAzimuth = 90.0; ///< the view's, taken over when the hand stops
    bool m_slow = false;
    bool m_driving = false;
    QTimer m_timer;
    QElapsedTimer m_clock;
};

} // namespace semhap
