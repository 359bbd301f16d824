// SPDX-License-Identifier: MIT
#include "envelopecurve.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace semhap {

EnvelopeCurve::EnvelopeCurve(std::vector<EnvelopePoint> points) : m_points(std::move(points)) {}

void EnvelopeCurve::append(double t, double v)
{
    m_points.push_back({t, v});
}

double EnvelopeCurve::value(double t) const
{
    if (m_points.empty())
        return 0.0;
    // The first point after t; the segment before it holds t (the last of equal times wins).
    const auto after = std::upper_bound(m_points.begin(), m_points.end(), t,
                                        [](double x, const EnvelopePoint &p) { return x < p.t; });
    if (after == m_points.begin())
        return m_points.front().v;
    if (after == m_points.end())
        return m_points.back().v;
    const EnvelopePoint &p0 = *(after - 1);
    const EnvelopePoint &p1 = *after;
    return p0.v + (p1.v - p0.v) * (t - p0.t) / (p1.t - p0.t);
}

double EnvelopeCurve::valueBefore(double t) const
{
    if (m_points.empty())
        return 0.0;
    // The first point at or after t; the segment before it leads up to t.
    const auto at = std::lower_bound(m_points.begin(), m_points.end(), t,
                                     [](const EnvelopePoint &p, double x) { return p.t < x; });
    if (at == m_points.begin())
        return m_points.front().v;
    if (at == m_points.end())
        return m_points.back().v;
    const EnvelopePoint &p0 = *(at - 1);
    const EnvelopePoint &p1 = *at;
    return p0.v + (p1.v - p0.v) * (t - p0.t) / (p1.t - p0.t);
}

double EnvelopeCurve::startTime() const
{
    return m_points.empty() ? 0.0 : m_points.front().t;
}

double EnvelopeCurve::endTime() const
{
    return m_points.empty() ? 0.0 : m_points.back().t;
}

EnvelopeCurve EnvelopeCurve::simplified(double tolerance) const
{
    if (m_points.size() < 3)
        return *this;
    EnvelopeCurve out;
    const auto keep = [&out](const EnvelopePoint &p) { out.m_points.push_back(p); };
    EnvelopePoint anchor = m_points.front();
    keep(anchor);
    // Slopes from the anchor that pass within `tolerance` of every point since.
    double low = -std::numeric_limits<double>::infinity();
    double high = std::numeric_limits<double>::infinity();
    const auto narrow = [&](const EnvelopePoint &p) {
        const double dt = p.t - anchor.t;
        low = std::max(low, (p.v - tolerance - anchor.v) / dt);
        high = std::min(high, (p.v + tolerance - anchor.v) / dt);
    };
    const auto restart = [&](const EnvelopePoint &p) {
        anchor = p;
        low = -std::numeric_limits<double>::infinity();
        high = std::numeric_limits<double>::infinity();
    };
    for (size_t i = 1; i < m_points.size(); ++i) {
        const EnvelopePoint &previous = m_points[i - 1];
        const EnvelopePoint &p = m_points[i];
        if (p.t <= anchor.t || p.t <= previous.t) {
            // A jump: both sides stay.
            if (previous.t != anchor.t || previous.v != anchor.v)
                keep(previous);
            keep(p);
            restart(p);
            continue;
        }
        const double slope = (p.v - anchor.v) / (p.t - anchor.t);
        if (slope < low || slope > high) {
            // No chord from the anchor reaches p: the point before it ends the segment.
            keep(previous);
            restart(previous);
        }
        narrow(p);
    }
    if (out.m_points.back().t != m_points.back().t || out.m_points.back().v != m_points.back().v)
        keep(m_points.back());
    return out;
}

EnvelopeCurve EnvelopeCurve::maximum(std::vector<EnvelopeCurve> curves)
{
    if (curves.empty())
        return EnvelopeCurve();
    const auto louder = [](double a, double b) { return std::max(a, b); };
    while (curves.size() > 1) {
        std::vector<EnvelopeCurve> merged;
        merged.reserve((curves.size() + 1) / 2);
        for (size_t i = 0; i + 1 < curves.size(); i += 2)
            merged.push_back(combine(curves[i], curves[i + 1], 0.0, louder));
        if (curves.size() % 2 == 1)
            merged.push_back(std::move(curves.back()));
        curves = std::move(merged);
    }
    return std::move(curves.front());
}

std::vector<double> EnvelopeCurve::breakpoints(const std::vector<const EnvelopeCurve *> &curves)
{
    std::vector<double> times;
    for (const EnvelopeCurve *curve : curves) {
        for (const EnvelopePoint &p : curve->points())
            times.push_back(p.t);
    }
    std::sort(times.begin(), times.end());
    times.erase(std::unique(times.begin(), times.end()), times.end());
    return times;
}

} // namespace semhap
