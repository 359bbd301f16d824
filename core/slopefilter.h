// SPDX-License-Identifier: MIT
#pragma once

namespace semhap {

/**
 * The slope of a signal (units per second), the difference quotient smoothed by a
 * first-order low-pass of time constant `tau`: on a ramp it settles on the ramp's slope
 * within a few tau; the first sample gives 0. What `derivative`, `predict` and
 * the impact detector share.
 */
class SlopeFilter
{
public:
    explicit SlopeFilter(double tau) : m_tau(tau) {}
    /** Feeds the value at `t` and returns the smoothed slope; a repeated `t` keeps it. */
    double update(double value, double t);

private:
    double m_tau;
    bool m_started = false;
    double m_value = 0.0;
    double m_t = 0.0;
    double m_slope = 0.0;
};

} // namespace semhap
