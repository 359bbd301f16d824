// SPDX-License-Identifier: MIT
#include "framepace.h"

#include <algorithm>

namespace semhap {

namespace {

/** How much of the newest frame's cost the smoothed cost takes: a few frames' memory. */
constexpr double Smoothing = 0.2;
/** A frame asked for this much early is on time: the timer that asks ticks no finer. */
constexpr double Slack = 0.002;

} // namespace

FramePace::FramePace(double displayRate, double budget) : m_budget(budget)
{
    setDisplayRate(displayRate);
}

void FramePace::setDisplayRate(double hz)
{
    // A screen that says nothing (0) or something absurd is taken as 60 Hz.
    m_displayInterval = 1.0 / (hz >= 1.0 && hz <= 1000.0 ? hz : 60.0);
}

void FramePace::frameDrawn(double started, double cpuSeconds)
{
    m_last = started;
    const double cost = std::max(0.0, cpuSeconds);
    m_cost = m_measured ? m_cost + Smoothing * (cost - m_cost) : cost;
    m_measured = true;
}

double FramePace::interval() const
{
    return std::clamp(m_cost / m_budget, m_displayInterval,
                      std::max(m_displayInterval, LongestInterval));
}

bool FramePace::due(double now) const
{
    return now - m_last >= interval() - Slack;
}

} // namespace semhap
