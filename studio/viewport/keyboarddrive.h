// SPDX-License-Identifier: MIT
#pragma once

#include "driveoperator.h"

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

#include <array>
#include <functional>

namespace semhap {

class DriveOperator;

/**
 * The keyboard's teleoperation: held keys move the active gripper's wrist at a steady
 * speed, integrated at display rate, inside a workspace around the scene's task; a key
 * closes or opens the grip with a ramp (a guarded close, never a step). Commands go to a
 * DriveOperator. No widgets: the viewport forwards its key events here, and tests drive it
 * directly. The key map is in studio/README.md.
 */
class KeyboardDrive : public QObject
{
    Q_OBJECT

public:
    /** Wrist speed with a movement key held (m/s); Shift moves at SlowFactor of it. */
    static constexpr double Speed = 0.15;
    static constexpr double SlowFactor = 0.25;
    /** Wrist turn rate (rad/s). */
    static constexpr double TurnRate = 1.5;
    /** How fast the grip command ramps (N/s): a 30 N close takes 0.2 s. */
    static constexpr double GripRate = 150.0;
    /** The force a close ramps to until the user changes it (N), and its step. */
    static constexpr double DefaultGrip = 30.0;
    static constexpr double GripStep = 5.0;
    /** What an open gripper is commanded (N): the fingers spread. */
    static constexpr double OpenGrip = -20.0;

    explicit KeyboardDrive(QObject *parent = nullptr);
    ~KeyboardDrive() override;

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

    /** A key went down; true when it is one of the map's (the caller then eats it). */
    bool press(int key, Qt::KeyboardModifiers modifiers = Qt::NoModifier);
    /** A key came up; true when it is one of the map's. */
    bool release(int key);
    /** Stops every movement, as if all keys came up (focus left the viewport). */
    void releaseAll();
    /** Changes the active hand's grip force by `notches` steps (Ctrl + wheel, +/-). */
    void adjustGrip(int notches);
    /** Moves by what the held keys and grip ramps do in `seconds` (the timer's tick). */
    void advance(double seconds);

    /**
     * Hands control back to the scripted operator: the next input starts driving again from
     * wherever the world's targets are then, and emits driveStarted() again.
     */
    void endDrive();
    bool isDriving() const { return m_driving; }

    Gripper activeHand() const { return m_active; }
    /** Whether Tab has a hand to switch to. */
    bool hasBothHands() const;
    /** What `hand` is being commanded. */
    const std::optional<HandCommand> &command(Gripper hand) const { return m_hands[size_t(hand)]; }
    /** The force `hand` closes to (N). */
    double gripSetpoint(Gripper hand) const { return m_setpoint[size_t(hand)]; }
    bool isClosed(Gripper hand) const { return m_closed[size_t(hand)]; }

    /**
     * The camera's azimuth (degrees, MuJoCo's): W moves away from the viewer along the table
     * axis nearest the view, D moves to the viewer's right.
     */
    void setViewAzimuth(double degrees) { m_viewAzimuth = degrees; }
    /** Where the wrist may go: the task's regions with some room around them. */
    const Region &workspace() const { return m_workspace; }

signals:
    /** The first input after setWorld() or endDrive(): the user takes the grippers. */
    void driveStarted();
    /** The active hand, a target or a grip changed (the HUD redraws). */
    void changed();

private:
    enum Action
    {
        Away,
        Toward,
        Left,
        Right,
        Up,
        Down,
        TurnLeft,
        TurnRight,
        ActionCount
    };

    void startDrive();
    void tick();
    /** Moves the active hand by what `held` asks for over `seconds`; true if it moved. */
    bool move(const std::array<bool, ActionCount> &held, double seconds);
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
    std::array<bool, ActionCount> m_held{};
    Gripper m_active = Gripper::Right;
    Region m_workspace;
    double m_viewAzimuth = 90.0;
    bool m_slow = false;
    bool m_driving = false;
    QTimer m_timer;
    QElapsedTimer m_clock;
};

} // namespace semhap
