// SPDX-License-Identifier: MIT
#include "voice.h"

#include <algorithm>

namespace semhap {

Voice::Voice(PatternPtr pattern)
    : m_pattern(std::move(pattern)), m_tracks(m_pattern->tracks().size()),
      m_params(m_pattern->params().defaults()), m_state(size_t(m_pattern->stateSize()), 0.0)
{
    int offset = 0;
    for (size_t i = 0; i < m_tracks.size(); ++i) {
        m_tracks[i].stateOffset = offset;
        offset += m_pattern->tracks()[i].stateSize;
    }
}

const Waveform *Voice::segmentWaveform(const PatternTrack &def, Phase phase)
{
    switch (phase) {
    case Phase::Attack:
        return def.attack.get();
    case Phase::Sustain:
        return def.sustain.get();
    case Phase::Release:
        return def.release.get();
    case Phase::Idle:
        break;
    }
    return nullptr;
}

void Voice::startSegment(TrackState &track, const PatternTrack &def, Phase phase, double t)
{
    track.phase = phase;
    track.segmentStart = t;
    track.segmentPeak = track.peak;
    segmentWaveform(def, phase)->reset(m_state.data() + track.stateOffset);
}

double Voice::sampleSegment(TrackState &track, const Waveform &waveform, double local, double dt)
{
    WaveformContext ctx;
    ctx.t = std::max(local, 0.0);
    ctx.dt = std::max(dt, 0.0);
    ctx.from = track.from;
    ctx.peak = track.segmentPeak;
    ctx.params = m_params.data();
    ctx.state = m_state.data() + track.stateOffset;
    const double value = waveform.sample(ctx);
    track.peak = std::max(track.peak, value);
    return value;
}

void Voice::advanceTrack(size_t index, double t)
{
    TrackState &track = m_tracks[index];
    const PatternTrack &def = m_pattern->tracks()[index];
    double previous = std::max(m_lastT, track.segmentStart);
    while (track.phase != Phase::Idle) {
        const Waveform &waveform = *segmentWaveform(def, track.phase);
        const double local = t - track.segmentStart;
        const double length =
            track.phase == Phase::Sustain ? Waveform::Forever : waveform.duration(m_params.data());
        if (local < length - Waveform::TimeTolerance) {
            track.value = sampleSegment(track, waveform, local, t - previous);
            return;
        }
        // The segment ended between samples: finish it exactly at its end.
        const double end = track.segmentStart + length;
        const double last = sampleSegment(track, waveform, length, end - previous);
        if (track.phase == Phase::Release) {
            track.phase = Phase::Idle;
            break;
        }
        track.from = last;
        startSegment(track, def, Phase::Sustain, end);
        previous = end;
    }
    track.value = 0.0;
}

void Voice::advance(double t)
{
    if (m_started)
        t = std::max(t, m_lastT);
    for (size_t i = 0; i < m_tracks.size(); ++i)
        advanceTrack(i, t);
    m_lastT = t;
    m_started = true;
}

void Voice::begin(double t)
{
    advance(t);
    t = m_lastT;
    m_active = true;
    for (size_t i = 0; i < m_tracks.size(); ++i) {
        TrackState &track = m_tracks[i];
        const PatternTrack &def = m_pattern->tracks()[i];
        // A release that began at this very instant has not moved the track yet: start
        // where it started, so an end and a begin in one tick leave no dip.
        const bool releaseJustBegan = track.phase == Phase::Release && track.segmentStart == t;
        track.from = releaseJustBegan ? track.from : track.value;
        track.peak = track.from;
        startSegment(track, def, def.attack ? Phase::Attack : Phase::Sustain, t);
    }
}

void Voice::end(double t)
{
    if (!m_active)
        return;
    advance(t);
    t = m_lastT;
    m_active = false;
    for (size_t i = 0; i < m_tracks.size(); ++i) {
        TrackState &track = m_tracks[i];
        const PatternTrack &def = m_pattern->tracks()[i];
        if (track.phase == Phase::Idle || track.phase == Phase::Release)
            continue;
        if (!def.release) {
            track.phase = Phase::Idle;
            track.value = 0.0;
            continue;
        }
        track.from = track.value;
        startSegment(track, def, Phase::Release, t);
    }
}

void Voice::setParam(int index, double value, double t)
{
    advance(t);
    m_params[size_t(index)] = value;
}

void Voice::resetParams()
{
    std::copy(m_pattern->params().defaults().begin(), m_pattern->params().defaults().end(),
              m_params.begin());
}

Voice::Phase Voice::phase() const
{
    Phase most = Phase::Idle;
    for (const TrackState &track : m_tracks)
        most = std::max(most, track.phase);
    return most;
}

void Voice::stop()
{
    for (TrackState &track : m_tracks) {
        const int offset = track.stateOffset;
        track = TrackState();
        track.stateOffset = offset;
    }
    resetParams();
    m_active = false;
    m_started = false;
    m_lastT = 0.0;
}

} // namespace semhap
