// SPDX-License-Identifier: MIT
#pragma once

namespace semhap {

/**
 * When the viewport may draw its next frame: at most at the display's rate, and seldom
 * enough that drawing takes at most a budget of one core. A frame that costs more CPU (the
 * software OpenGL of a machine without a GPU renders on the processor) makes the next wait
 * longer. Fed what each frame cost; asked whether one is due.
 */
class FramePace
{
public:
    /** The share of one core drawing may take. */
    static constexpr double DefaultBudget = 0.3;
    /** The longest wait between frames (s): the picture still moves. */
    static constexpr double LongestInterval = 0.25;

    explicit FramePace(double displayRate = 60.0, double budget = DefaultBudget);

    /** The display's refresh rate (Hz); the pace never goes faster. */
    void setDisplayRate(double hz);
    /** A frame begun at `started` (s, any steady clock) cost `cpuSeconds` of the process. */
    void frameDrawn(double started, double cpuSeconds);
    /** The time between frames now (s). */
    double interval() const;
    /** Whether a frame may begin at `now`. */
    bool due(double now) const;
    /** What a frame costs, smoothed over the last few (CPU seconds). */
    double frameCost() const { return m_cost; }

private:
    double m_displayInterval;
    double m_budget;
    double m_cost = 0.0;
    double m_last = -1e300;
    bool m_measured = false;
};

} // namespace semhap
