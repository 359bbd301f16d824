// SPDX-License-Identifier: MIT
#pragma once

#include "handcommand.h"
#include "operator.h"
#include "world.h"

#include <array>
#include <mutex>
#include <optional>

namespace semhap {

/** What the simulation made of one hand's drive command at its last step. */
struct DriveStatus
{
    bool driven = false; ///< the hand has been given a target
    Pose target;         ///< the wrist target the world was given (after the guard)
    /** The surface straight below the target (m; what the drop line reaches), if any. */
    std::optional<double> surface;
    /**
     * While the fingers or a held object rest on something: the lowest wrist height (m)
     * a target may ask for. A target below it is raised to it (the guarded move).
     */
    std::optional<double> floor;
    /**
     * The grip force (N; negative opens) the gripper was given: the command, or less while
     * the close is guarded. None until the hand has been given a grip.
     */
    std::optional<double> grip;
    /** The grip the hand was commanded (N): what `grip` rises to. */
    double gripCommand = 0.0;
    /** Both pads touch one object (since the close began): the grip rises to the command. */
    bool squeezing = false;
};

/**
 * The pose-and-grip input: whatever drives the grippers from outside — the studio's
 * keyboard, gamepad and 3D mouse, a VR or motion-capture rig over the network — sets each
 * hand's wrist target and grip here, from any thread; act() applies the latest on the
 * simulation thread. A command being written while the simulation steps is applied on the
 * next step: the simulation never waits for the input.
 *
 * A new target is not jumped to: it glides there from the previous one over the time
 * between the two commands (at most MaxGlide), so an input that updates ten times a second
 * (a studio on a slow display, a tracker at a low rate) moves the wrist as smoothly as one
 * at sixty; commands every step are applied as they come.
 *
 * Descents land softly: the target comes down no faster than LandingSpeed plus the gap
 * below (World::clearanceBelow) over LandingTime, so whatever the input's speed, the fingers
 * or a held object meet a surface at LandingSpeed. A blocked wrist is pushed by its weld
 * with about 100 N per millimetre the target is below it, and at speed the target trails
 * the wrist by millimetres: at 0.15 m/s onto the pile the fingertips took 60-280 N in the
 * step they touched, before any guard could act.
 *
 * Closes are guarded too: until both pads touch one object (World::objectBetween), a closing grip
 * is held to the force that closes the fingers at ClosingSpeed; then it rises to the command at
 * SqueezeRate. A hand resting on something lifts off it by LiftOff as it closes and, closed,
 * hovers where nothing pushes (rather than pressing with GuardPush).
 * A finger's speed is its force over its damping, so a grip commanded at 20 N
 * closed at 0.17 m/s and struck a cube with 100-220 N in one step (the fingers dragged
 * over the pile or the table on the way, then let go at once).
 *
 * Moves are guarded: once the fingertips are pushed up by what is under them (the pads on
 * a cube, a held cube set down) while the target is below the wrist, the target stops at a
 * floor that settles where the push is GuardPush. Holding "down" then presses with a few
 * newtons instead of burying the target in a stack (the wrist's weld gives about 100 N per
 * millimetre). Lifting the target GuardRelease above the wrist and the floor ends the guard; when
 * the push goes away (the cube below was taken) the floor descends at GuardApproach until
 * something pushes.
 */
class DriveOperator : public Operator
{
public:
    /** Upward fingertip force (N) from which a move is guarded: more than a cube weighs. */
    static constexpr double GuardForce = 1.5;
    /** The longest a new target takes to be reached (s). */
    static constexpr double MaxGlide = 0.25;
    /** The push (N) a guarded move settles at. */
    static constexpr double GuardPush = 2.5;
    /** How fast the floor follows the push's error (m/s per N): settles in tens of ms. */
    static constexpr double GuardRate = 1e-3;
    /**
     * How far above the wrist (m) a target must be to end the guard: the user lifts. A drive
     * holding its target on an older floor keeps the guard while the floor settles.
     */
    static constexpr double GuardRelease = 0.002;
    /** How long the push may be gone (s) before the guarded target descends again… */
    static constexpr double GuardQuiet = 0.1;
    /** …at this speed (m/s), so that meeting the next surface is gentle. */
    static constexpr double GuardApproach = 0.03;
    /** The speed (m/s) the fingers close at until both pads touch what is between them. */
    static constexpr double ClosingSpeed = 0.05;
    /** How fast (N/s) the grip then rises to the command: 30 N in 0.2 s. */
    static constexpr double SqueezeRate = 150.0;
    /** How far (m) a guarded hand lifts off what it rests on as it closes. */
    static constexpr double LiftOff = 0.002;
    /** The speed (m/s) a descent meets a surface with: 25 N at most on the pile. */
    static constexpr double LandingSpeed = 0.02;
    /** How long (s) a descent takes to close its gap (and slow) near a surface. */
    static constexpr double LandingTime = 0.1;

    QString name() const override { return QStringLiteral("drive"); }
    void act(World &world) override;
    /** Forgets the last drive: its glide, guard and grip state, and its last command. */
    void engage(const World &world) override;

    /** Sets where `hand`'s wrist should be. Thread-safe. */
    void setTarget(Gripper hand, const Pose &target);
    /** Sets `hand`'s total grip force (N; negative opens). Thread-safe. */
    void setGrip(Gripper hand, double force);
    /** Sets what `command` says: its hand's target and grip. Thread-safe. */
    void setCommand(const HandCommand &command);
    /** What the last step made of `hand`'s command. Thread-safe. */
    DriveStatus status(Gripper hand) const;

private:
    /** The guard's floor for `hand` this step (none: the target is free); see the class. */
    std::optional<double> guard(const World &world, Gripper hand, double targetZ);
    /** The grip to apply for `hand`'s `command` this step (the guarded close; see the class). */
    double guardedGrip(const World &world, Gripper hand, double command);

    /** A target's way from the previous command to the newest. */
    struct Glide
    {
        Pose from;
        Pose to;
        double start = 0.0; ///< simulated time the newest command arrived
        double span = 0.0;  ///< how long the way takes: the time since the one before
        bool started = false;
        /** Where the target is at simulated time `t`. */
        Pose at(double t) const;
    };

    /** What one hand was last told; a part never set leaves the world's as it is. */
    struct Update
    {
        std::optional<Pose> target;
        std::optional<double> grip;
    };

    std::mutex m_mutex;
    std::array<Update, 2> m_pending{};
    std::array<Update, 2> m_current{};
    std::array<Glide, 2> m_glide{};
    /** Per hand: the guard's floor while it holds, and how long its push has been gone. */
    std::array<std::optional<double>, 2> m_floor{};
    std::array<double, 2> m_quiet{};
    /** Per hand: both pads have touched an object since the grip began to close. */
    std::array<bool, 2> m_squeezing{};
    /** Per hand: the grip closed since the floor was set, and the pads lifted off. */
    std::array<bool, 2> m_liftedOff{};
    mutable std::mutex m_statusMutex;
    std::array<DriveStatus, 2> m_status{};
};

/**
 * Each hand's target and grip as the world has them now (none for a hand the scene lacks):
 * driving starts there, so the grippers do not jump. Read the world on the thread that
 * steps it, or while it is paused.
 */
std::array<std::optional<HandCommand>, 2> currentCommands(const World &world);

} // namespace semhap
