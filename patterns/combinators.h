// SPDX-License-Identifier: MIT
#pragma once

#include "signal.h"

#include <vector>

namespace semhap {

/** A signal built from child signals; it hands state slots and resets down to them. */
class CompositeSignal : public Signal
{
public:
    explicit CompositeSignal(std::vector<SignalPtr> children);
    void reset(double *state) const override;
    void assignState(int &next) override;
    /** The children, in the order the JSON lists them. */
    const std::vector<SignalPtr> &children() const { return m_children; }
    /** `{"type": …, "of": [children]}`, the form of the list combinators. */
    QJsonValue toJson(const ParamTable &params) const override;

protected:
    std::vector<SignalPtr> m_children;
};

/** The children added sample by sample: layers, e.g. a pulse train on a base level. */
class SumSignal : public CompositeSignal
{
public:
    using CompositeSignal::CompositeSignal;
    QString type() const override;
    double sample(const SignalContext &ctx) const override;
    /** As long as any child lasts (ended children hold their last value). */
    double duration(const double *params) const override;
};

/** The children multiplied sample by sample: an envelope shaping an oscillator. */
class ProductSignal : public CompositeSignal
{
public:
    using CompositeSignal::CompositeSignal;
    QString type() const override;
    double sample(const SignalContext &ctx) const override;
    /** As long as every child lasts. */
    double duration(const double *params) const override;
};

/**
 * The children one after another, each for its duration, each starting from the previous
 * one's last value; all but the last must be finite.
 */
class SequenceSignal : public CompositeSignal
{
public:
    using CompositeSignal::CompositeSignal;
    QString type() const override;
    double sample(const SignalContext &ctx) const override;
    /** The sum of the children's durations. */
    double duration(const double *params) const override;

protected:
    int ownStateSize() const override { return 3; } // child index, its start, its from
};

/** in·gain/div + offset (the quotient is 0 when div is 0): normalises a raw parameter. */
class ScaleSignal : public CompositeSignal
{
public:
    ScaleSignal(SignalPtr in, Number gain, Number div, Number offset);
    QString type() const override;
    double sample(const SignalContext &ctx) const override;
    double duration(const double *params) const override;
    QJsonValue toJson(const ParamTable &params) const override;

private:
    Number m_gain;
    Number m_div;
    Number m_offset;
};

/** The input clamped to [min, max], keeping a channel inside its device's range. */
class ClipSignal : public CompositeSignal
{
public:
    ClipSignal(SignalPtr in, Number min, Number max);
    QString type() const override;
    double sample(const SignalContext &ctx) const override;
    double duration(const double *params) const override;
    QJsonValue toJson(const ParamTable &params) const override;

private:
    Number m_min;
    Number m_max;
};

} // namespace semhap
