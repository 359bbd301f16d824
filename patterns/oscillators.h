// SPDX-License-Identifier: MIT
#pragma once

#include "waveform.h"

namespace semhap {

// The oscillators share one rule: the phase (in cycles) is an accumulator advanced by
// freq·dt at each sample and kept in the voice's state, never computed as freq·t, so a
// frequency bound to a live parameter changes the period from then on without a jump.

/** offset + amp·sin(2π(phase + phase offset)): a smooth periodic wave. */
class SineWaveform : public Waveform
{
public:
    SineWaveform(Number freq, Number amp, Number offset, Number phase);
    QString type() const override;
    double sample(const WaveformContext &ctx) const override;
    QJsonValue toJson(const ParamTable &params) const override;

protected:
    int ownStateSize() const override { return 1; }

private:
    Number m_freq;
    Number m_amp;
    Number m_offset;
    Number m_phase;
};

/** `high` for the first `duty` of each cycle and `low` for the rest, starting high. */
class SquareWaveform : public Waveform
{
public:
    SquareWaveform(Number freq, Number duty, Number high, Number low);
    QString type() const override;
    double sample(const WaveformContext &ctx) const override;
    QJsonValue toJson(const ParamTable &params) const override;

protected:
    int ownStateSize() const override { return 1; }

private:
    Number m_freq;
    Number m_duty;
    Number m_high;
    Number m_low;
};

/**
 * A pulse of `amp` lasting `width` seconds at the start of each cycle of `rate` Hz, the
 * first at time 0: the width stays in seconds however the rate moves.
 */
class PulsesWaveform : public Waveform
{
public:
    PulsesWaveform(Number rate, Number width, Number amp);
    QString type() const override;
    double sample(const WaveformContext &ctx) const override;
    QJsonValue toJson(const ParamTable &params) const override;

protected:
    int ownStateSize() const override { return 2; } // phase, seconds since the cycle began

private:
    Number m_rate;
    Number m_width;
    Number m_amp;
};

} // namespace semhap
