// SPDX-License-Identifier: MIT
#pragma once

#include "pattern.h"

#include <vector>

namespace semhap {

/**
 * One playing instance of a pattern: its lifecycle per track, its live parameter values and
 * its waveform state. All memory is taken in the constructor; begin, end, setParam and
 * advance never allocate, so a voice can sit on the real-time path.
 *
 * Time is absolute (seconds, never decreasing across calls). begin/end/setParam at time t
 * first advance the voice to t, so a parameter change takes effect exactly when it happens
 * and a new segment starts from the value the track had then.
 */
class Voice
{
public:
    enum class Phase
    {
        Idle,
        Attack,
        Sustain,
        Release
    };

    explicit Voice(PatternPtr pattern);

    const Pattern &pattern() const { return *m_pattern; }

    /** Starts (or restarts) the attack at time t, from each track's current value. */
    void begin(double t);
    /** Starts the release at time t; a voice that is idle or releasing is left alone. */
    void end(double t);
    /** Sets live parameter `index` at time t (the voice is advanced to t first). */
    void setParam(int index, double value, double t);
    double param(int index) const { return m_params[size_t(index)]; }
    /** Puts every parameter back to its pattern default. */
    void resetParams();

    /** Samples every track at time t; read the results with value(). */
    void advance(double t);
    /** The value of track `track` at the last advance. */
    double value(int track) const { return m_tracks[size_t(track)].value; }
    int trackCount() const { return int(m_tracks.size()); }

    /** The phase of the voice: the most advanced phase of its tracks (Idle when all are). */
    Phase phase() const;
    bool isIdle() const { return phase() == Phase::Idle; }
    /** True between begin and end. */
    bool isActive() const { return m_active; }

    /** Back to idle with every value 0 and every parameter at its default. */
    void stop();

private:
    struct TrackState
    {
        Phase phase = Phase::Idle;
        double segmentStart = 0.0; ///< absolute time the current segment began
        double from = 0.0;         ///< value when the segment began
        double peak = 0.0;         ///< highest value since the last begin
        double segmentPeak = 0.0;  ///< peak when the segment began (WaveformContext::peak)
        double value = 0.0;        ///< value at the last sample
        int stateOffset = 0;       ///< first state slot of this track
    };

    void advanceTrack(size_t index, double t);
    void startSegment(TrackState &track, const PatternTrack &def, Phase phase, double t);
    /** Samples `waveform` for `track` at `local` seconds into its segment, `dt` after the last. */
    double sampleSegment(TrackState &track, const Waveform &waveform, double local, double dt);
    static const Waveform *segmentWaveform(const PatternTrack &def, Phase phase);

    PatternPtr m_pattern;
    std::vector<TrackState> m_tracks;
    std::vector<double> m_params;
    std::vector<double> m_state;
    double m_lastT = 0.0;
    bool m_started = false;
    bool m_active = false;
};

} // namespace semhap
