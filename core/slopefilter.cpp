// SPDX-License-Identifier: MIT
#include "slopefilter.h"

#include <cmath>

namespace semhap {

double SlopeFilter::update(double value, double t)
{
    if (!m_started) {
        m_started = true;
        m_value = value;
        m_t = t;
        return m_slope;
    }
    const double dt = t - m_t;
    if (dt <= 0.0)
        return m_slope;
    const double raw = (value - m_value) / dt;
    // The exact step response of the low-pass over dt, so irregular ticks weigh right.
    const double weight = m_tau > 0.0 ? 1.0 - std::exp(-dt / m_tau) : 1.0;
    m_slope += weight * (raw - m_slope);
    m_value = value;
    m_t = t;
    return m_slope;
}

} // namespace semhap
