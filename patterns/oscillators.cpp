// SPDX-License-Identifier: MIT
#include "oscillators.h"

#include <QJsonObject>

#include <algorithm>
#include <cmath>

namespace semhap {

namespace {

constexpr double TwoPi = 6.283185307179586;

/**
 * Advances a phase accumulator by freq·dt and wraps it into [0, 1). Returns the number of
 * cycle starts crossed; a phase within TimeTolerance·freq of a cycle start counts as
 * having reached it.
 */
double advancePhase(double &phase, double freq, double dt)
{
    phase += std::max(freq, 0.0) * std::max(dt, 0.0);
    const double tolerance = Waveform::TimeTolerance * std::max(freq, 0.0);
    const double wraps = std::floor(phase + tolerance);
    phase = std::max(phase - wraps, 0.0);
    return wraps;
}

} // namespace

SineWaveform::SineWaveform(Number freq, Number amp, Number offset, Number phase)
    : m_freq(std::move(freq)), m_amp(std::move(amp)), m_offset(std::move(offset)),
      m_phase(std::move(phase))
{}

QString SineWaveform::type() const
{
    return QStringLiteral("sine");
}

double SineWaveform::sample(const WaveformContext &ctx) const
{
    double &phase = ctx.state[m_stateOffset];
    advancePhase(phase, m_freq.value(ctx.params), ctx.dt);
    const double angle = TwoPi * (phase + m_phase.value(ctx.params));
    return m_offset.value(ctx.params) + m_amp.value(ctx.params) * std::sin(angle);
}

QJsonValue SineWaveform::toJson(const ParamTable &params) const
{
    QJsonObject o{{QStringLiteral("type"), type()},
                  {QStringLiteral("freq"), m_freq.toJson(params)}};
    insertNumber(o, QStringLiteral("amp"), m_amp, params, 1.0);
    insertNumber(o, QStringLiteral("offset"), m_offset, params, 0.0);
    insertNumber(o, QStringLiteral("phase"), m_phase, params, 0.0);
    return o;
}

SquareWaveform::SquareWaveform(Number freq, Number duty, Number high, Number low)
    : m_freq(std::move(freq)), m_duty(std::move(duty)), m_high(std::move(high)),
      m_low(std::move(low))
{}

QString SquareWaveform::type() const
{
    return QStringLiteral("square");
}

double SquareWaveform::sample(const WaveformContext &ctx) const
{
    double &phase = ctx.state[m_stateOffset];
    const double freq = m_freq.value(ctx.params);
    advancePhase(phase, freq, ctx.dt);
    const double duty = std::clamp(m_duty.value(ctx.params), 0.0, 1.0);
    const bool high = phase + Waveform::TimeTolerance * std::max(freq, 0.0) < duty;
    return high ? m_high.value(ctx.params) : m_low.value(ctx.params);
}

QJsonValue SquareWaveform::toJson(const ParamTable &params) const
{
    QJsonObject o{{QStringLiteral("type"), type()},
                  {QStringLiteral("freq"), m_freq.toJson(params)}};
    insertNumber(o, QStringLiteral("duty"), m_duty, params, 0.5);
    insertNumber(o, QStringLiteral("high"), m_high, params, 1.0);
    insertNumber(o, QStringLiteral("low"), m_low, params, 0.0);
    return o;
}

PulsesWaveform::PulsesWaveform(Number rate, Number width, Number amp)
    : m_rate(std::move(rate)), m_width(std::move(width)), m_amp(std::move(amp))
{}

QString PulsesWaveform::type() const
{
    return QStringLiteral("pulses");
}

double PulsesWaveform::sample(const WaveformContext &ctx) const
{
    double &phase = ctx.state[m_stateOffset];
    double &sinceStart = ctx.state[m_stateOffset + 1];
    const double rate = std::max(m_rate.value(ctx.params), 0.0);
    sinceStart += std::max(ctx.dt, 0.0);
    if (advancePhase(phase, rate, ctx.dt) > 0.0) {
        // The cycle began between two samples, `phase` cycles ago at this rate.
        sinceStart = phase / rate;
    }
    const double width = std::max(m_width.value(ctx.params), 0.0);
    return sinceStart + Waveform::TimeTolerance < width ? m_amp.value(ctx.params) : 0.0;
}

QJsonValue PulsesWaveform::toJson(const ParamTable &params) const
{
    QJsonObject o{{QStringLiteral("type"), type()},
                  {QStringLiteral("rate"), m_rate.toJson(params)},
                  {QStringLiteral("width"), m_width.toJson(params)}};
    insertNumber(o, QStringLiteral("amp"), m_amp, params, 1.0);
    return o;
}

} // namespace semhap
