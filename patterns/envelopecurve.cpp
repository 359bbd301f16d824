// SPDX-License-Identifier: MIT
#include "envelopecurve.h"

#include <algorithm>
#include <cmath>

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

namespace {

/** How far `p` lies from the chord a–b, in value; on a jump, how far outside it. */
double chordDistance(const EnvelopePoint &a, const EnvelopePoint &b, const EnvelopePoint &p)
{
    if (b.t <= a.t)
        return std::max({0.0, p.v - std::max(a.v, b.v), std::min(a.v, b.v) - p.v});
    return std::abs(p.v - (a.v + (b.v - a.v) * (p.t - a.t) / (b.t - a.t)));
}

void keepFarthest(const std::vector<EnvelopePoint> &points, size_t first, size_t last,
                  double tolerance, std::vector<bool> &keep)
{
    // Iterative, so a curve sampled at a kilohertz for minutes cannot exhaust the stack.
    std::vector<std::pair<size_t, size_t>> spans{{first, last}};
    while (!spans.empty()) {
        const auto [a, b] = spans.back();
        spans.pop_back();
        double worst = -1.0;
        size_t at = a;
        for (size_t i = a + 1; i < b; ++i) {
            const double d = chordDistance(points[a], points[b], points[i]);
            if (d > worst) {
                worst = d;
                at = i;
            }
        }
        if (worst > tolerance) {
            keep[at] = true;
            spans.push_back({a, at});
            spans.push_back({at, b});
        }
    }
}

} // namespace

EnvelopeCurve EnvelopeCurve::simplified(double tolerance) const
{
    if (m_points.size() < 3)
        return *this;
    std::vector<bool> keep(m_points.size(), false);
    keep.front() = keep.back() = true;
    keepFarthest(m_points, 0, m_points.size() - 1, tolerance, keep);
    EnvelopeCurve out;
    for (size_t i = 0; i < m_points.size(); ++i) {
        if (keep[i])
            out.m_points.push_back(m_points[i]);
    }
    return out;
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
