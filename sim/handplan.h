// SPDX-License-Identifier: MIT
#pragma once

#include "world.h"

#include <deque>

namespace semhap {

/**
 * What one hand of an operator is doing: a queue of moves (minimum-jerk, the way people
 * move), grip ramps and waits, each starting from wherever the hand is when it begins.
 * Operators plan by queueing; the plan drives the world's target and grip every step.
 */
class HandPlan
{
public:
    explicit HandPlan(Gripper gripper) : m_gripper(gripper) {}

    /** Moves the wrist to `to` over `seconds` (position only; orientation is kept). */
    void move(const std::array<double, 3> &to, double seconds);
    /** Ramps the total grip force to `force` (N) over `seconds`. */
    void grip(double force, double seconds);
    /** The grip every operator opens the fingers with (N; negative opens). */
    static constexpr double OpenGrip = -20.0;
    void wait(double seconds);
    /** Drops what is queued (a reaction replans). */
    void clear();
    /**
     * Ends a grip ramp that is under way where it is now, and ramps to `force` over
     * `seconds` before the rest of the plan goes on (a reaction to what the hand felt).
     */
    void regrip(double force, double seconds);
    bool isIdle() const { return m_queue.empty(); }
    /** Whether the segment now running is a grip ramp. */
    bool isGripping() const;

    /** Applies the plan at the world's current time, advancing through finished segments. */
    void apply(World &world);

    Gripper gripper() const { return m_gripper; }

private:
    struct Segment
    {
        enum Kind
        {
            Move,
            Grip,
            Wait
        } kind;
        std::array<double, 3> to{};
        double force = 0.0;
        double seconds = 0.0;
        // Filled when the segment starts:
        bool started = false;
        double start = 0.0;
        std::array<double, 3> from{};
        double fromForce = 0.0;
    };

    Gripper m_gripper;
    std::deque<Segment> m_queue;
};

/** Minimum-jerk progress (10s³ − 15s⁴ + 6s⁵) of a movement at fraction s of its time. */
double minimumJerk(double s);

} // namespace semhap
