// SPDX-License-Identifier: MIT
#pragma once

#include "waveform.h"

#include <utility>
#include <vector>

namespace semhap {

/**
 * Where a ramp or keyframe envelope starts: the track's value when the waveform started
 * (`"current"`, the default, so every ramp takes its time from wherever the value is), the
 * track's peak since the last begin (`"peak"`), or a Number.
 */
class StartValue
{
public:
    enum class Kind
    {
        Current,
        Peak,
        Value
    };

    StartValue() = default; ///< `"current"`
    /** Starts from the track's peak, for releases that fall from the highest value reached. */
    static StartValue peak();
    /** Starts from a fixed or parameter-bound value, ignoring where the track is. */
    static StartValue value(Number number);

    /** The start value for this sample's context. */
    double resolve(const WaveformContext &ctx) const;
    Kind kind() const { return m_kind; }
    /** `"current"`, `"peak"` or the Number's JSON form. */
    QJsonValue toJson(const ParamTable &params) const;

private:
    Kind m_kind = Kind::Current;
    Number m_number;
};

/** A constant (or a parameter read through a Number), held forever: a plain sustain. */
class ConstWaveform : public Waveform
{
public:
    explicit ConstWaveform(Number value) : m_value(std::move(value)) {}
    QString type() const override;
    double sample(const WaveformContext &ctx) const override;
    QJsonValue toJson(const ParamTable &params) const override;

private:
    Number m_value;
};

/** A live parameter as a waveform, so a channel can follow a value fed from outside. */
class ParamWaveform : public Waveform
{
public:
    /** `value` must be bound to a parameter; its curve maps the parameter's value. */
    explicit ParamWaveform(Number value) : m_value(std::move(value)) {}
    QString type() const override;
    double sample(const WaveformContext &ctx) const override;
    QJsonValue toJson(const ParamTable &params) const override;

private:
    Number m_value;
};

/** A linear ramp from a start value to `to` over `time` seconds, then held. */
class RampWaveform : public Waveform
{
public:
    RampWaveform(Number to, Number time, StartValue from)
        : m_to(std::move(to)), m_time(std::move(time)), m_from(std::move(from))
    {}
    QString type() const override;
    double sample(const WaveformContext &ctx) const override;
    double duration(const double *params) const override;
    QJsonValue toJson(const ParamTable &params) const override;

private:
    Number m_to;
    Number m_time;
    StartValue m_from;
};

/**
 * A piecewise-linear envelope through (time, value) points with non-decreasing times, held
 * at the last value; before the first point it ramps from its start value at time 0.
 */
class KeyframesWaveform : public Waveform
{
public:
    KeyframesWaveform(std::vector<std::pair<double, double>> points, StartValue from)
        : m_points(std::move(points)), m_from(std::move(from))
    {}
    QString type() const override;
    double sample(const WaveformContext &ctx) const override;
    double duration(const double *params) const override;
    QJsonValue toJson(const ParamTable &params) const override;

private:
    std::vector<std::pair<double, double>> m_points;
    StartValue m_from;
};

} // namespace semhap
