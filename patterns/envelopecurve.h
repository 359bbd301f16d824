// SPDX-License-Identifier: MIT
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

namespace semhap {

/** One breakpoint of an EnvelopeCurve. */
struct EnvelopePoint
{
    double t = 0.0;
    double v = 0.0;
};

/**
 * A piecewise-linear amplitude over time, the common ground of the haptic file formats
 * (AHAP intensity, `.haptic` amplitude) and semhap's keyframes. Points are sorted by time;
 * two points at the same time make a jump. Before the first point and after the last the
 * curve holds their values; an empty curve is 0 everywhere.
 */
class EnvelopeCurve
{
public:
    EnvelopeCurve() = default;
    explicit EnvelopeCurve(std::vector<EnvelopePoint> points);

    const std::vector<EnvelopePoint> &points() const { return m_points; }
    bool isEmpty() const { return m_points.empty(); }
    /** Appends a point; its time must not be before the last one's. */
    void append(double t, double v);

    /** The value at t (right-continuous: at a jump, the value after it). */
    double value(double t) const;
    /** The value just before t (the value before a jump at t). */
    double valueBefore(double t) const;
    double startTime() const;
    double endTime() const;

    /**
     * Drops points that lie within `tolerance` (in value) of the line through their
     * neighbours kept, so a densely sampled curve becomes a few breakpoints again. One pass:
     * each kept point opens a window of the slopes that pass every point since within the
     * tolerance, and the next point is kept when that window closes. Jumps are kept.
     */
    EnvelopeCurve simplified(double tolerance) const;

    /**
     * Combines two curves point by point with `combine(a, b)`: at every breakpoint of
     * either, where they cross, and every `step` seconds where both change (a product of two
     * ramps is not linear; at most MaxStepsPerSegment such points between two breakpoints),
     * keeping jumps. Exact for maxima and minima, which need no `step` (pass 0).
     */
    template<typename F>
    static EnvelopeCurve combine(const EnvelopeCurve &a, const EnvelopeCurve &b, double step,
                                 F combine);
    /**
     * The upper envelope of many curves (the loudest at each instant), merged pairwise so
     * that n curves of a few points each cost n·log n.
     */
    static EnvelopeCurve maximum(std::vector<EnvelopeCurve> curves);

    /** Points sampled at most between two breakpoints by combine(), whatever the step. */
    static constexpr int MaxStepsPerSegment = 1000;

    /** Times of every breakpoint of the given curves, sorted, without duplicates. */
    static std::vector<double> breakpoints(const std::vector<const EnvelopeCurve *> &curves);

private:
    std::vector<EnvelopePoint> m_points;
};

template<typename F>
EnvelopeCurve EnvelopeCurve::combine(const EnvelopeCurve &a, const EnvelopeCurve &b, double step,
                                     F combine)
{
    EnvelopeCurve out;
    const auto add = [&](double t) {
        const double before = combine(a.valueBefore(t), b.valueBefore(t));
        const double after = combine(a.value(t), b.value(t));
        if (std::abs(before - after) > 1e-12 && !out.isEmpty())
            out.append(t, before);
        out.append(t, after);
    };
    const std::vector<double> times = breakpoints({&a, &b});
    for (size_t i = 0; i < times.size(); ++i) {
        add(times[i]);
        if (i + 1 == times.size())
            break;
        // Between two breakpoints both curves are straight lines.
        const double t0 = times[i];
        const double t1 = times[i + 1];
        const double da0 = a.value(t0) - b.value(t0);
        const double da1 = a.valueBefore(t1) - b.valueBefore(t1);
        const bool bothChange =
            a.value(t0) != a.valueBefore(t1) && b.value(t0) != b.valueBefore(t1);
        if (bothChange && step > 0) {
            // A span of hours must not become millions of samples.
            const double spacing = std::max(step, (t1 - t0) / MaxStepsPerSegment);
            for (double t = t0 + spacing; t < t1 - spacing / 2; t += spacing)
                add(t);
        } else if ((da0 < 0 && da1 > 0) || (da0 > 0 && da1 < 0)) {
            add(t0 + (t1 - t0) * da0 / (da0 - da1));
        }
    }
    return out;
}

} // namespace semhap
