// SPDX-License-Identifier: MIT
#pragma once

#include "waveform.h"

#include <vector>

namespace semhap {

/** A waveform built from child waveforms; it hands state slots and resets down to them. */
class CompositeWaveform : public Waveform
{
public:
    explicit CompositeWaveform(std::vector<WaveformPtr> children);
    void reset(double *state) const override;
    void assignState(int &next) override;
    /** The children, in the order the JSON lists them. */
    const std::vector<WaveformPtr> &children() const { return m_children; }
    /** `{"type": …, "of": [children]}`, the form of the list combinators. */
    QJsonValue toJson(const ParamTable &params) const override;

protected:
    std::vector<WaveformPtr> m_children;
};

/** The children added sample by sample: layers, e.g. a pulse train on a base level. */
class SumWaveform : public CompositeWaveform
{
public:
    using CompositeWaveform::CompositeWaveform;
    QString type() const override;
    double sample(const WaveformContext &ctx) const override;
    /** As long as any child lasts (ended children hold their last value). */
    double duration(const double *params) const override;
};

/** The children multiplied sample by sample: an envelope shaping an oscillator. */
class ProductWaveform : public CompositeWaveform
{
public:
    using CompositeWaveform::CompositeWaveform;
    QString type() const override;
    double sample(const WaveformContext &ctx) const override;
    /** As long as every child lasts. */
    double duration(const double *params) const override;
};

/**
 * The children one after another, each for its duration, each starting from the previous
 * one's last value; all but the last must be finite.
 */
class SequenceWaveform : public CompositeWaveform
{
public:
    using CompositeWaveform::CompositeWaveform;
    QString type() const override;
    double sample(const WaveformContext &ctx) const override;
    /** The sum of the children's durations. */
    double duration(const double *params) const override;

protected:
    int ownStateSize() const override { return 3; } // child index, its start, its from
};

/** in·gain/div + offset (the quotient is 0 when div is 0): normalises a raw parameter. */
class ScaleWaveform : public CompositeWaveform
{
public:
    ScaleWaveform(WaveformPtr in, Number gain, Number div, Number offset);
    QString type() const override;
    double sample(const WaveformContext &ctx) const override;
    double duration(const double *params) const override;
    QJsonValue toJson(const ParamTable &params) const override;

private:
    Number m_gain;
    Number m_div;
    Number m_offset;
};

/** The input clamped to [min, max], keeping a channel inside its device's range. */
class ClipWaveform : public CompositeWaveform
{
public:
    ClipWaveform(WaveformPtr in, Number min, Number max);
    QString type() const override;
    double sample(const WaveformContext &ctx) const override;
    double duration(const double *params) const override;
    QJsonValue toJson(const ParamTable &params) const override;

private:
    Number m_min;
    Number m_max;
};

} // namespace semhap
