// SPDX-License-Identifier: MIT
#pragma once

#include <QByteArray>
#include <QString>

#include <vector>

namespace semhap {

struct SessionInfo;

/**
 * How a session's time relates to the machine's steady clock: the clock the Lab Streaming
 * Layer stamps samples with (`lsl::local_clock()`, std::chrono::steady_clock, which is
 * CLOCK_MONOTONIC on Linux: seconds since boot). A recording samples the pair (session time,
 * steady clock) at its first contact frame, every Interval seconds of the clock after it and
 * at its end, in the session's metadata; an export puts the session's streams on that clock
 * (docs/science.md).
 */
class SessionClock
{
public:
    /** One pair: a contact frame's session time and the steady clock when it was recorded. */
    struct Sample
    {
        double t = 0.0;
        double steady = 0.0;
    };

    /** Seconds of the steady clock between two samples (LabRecorder's clock offset period). */
    static constexpr double Interval = 5.0;
    /** The metadata key of the samples: a JSON array of [t, steady] pairs, in order. */
    static constexpr const char *MetadataKey = "steady_clock";
    /**
     * How much faster than the clock a session's time may run and still be put on it: a
     * simulation faster than real time cannot be (its times are simulated seconds).
     */
    static constexpr double MaxRateError = 0.01;

    /** The steady clock now, in seconds: what `lsl::local_clock()` would return. */
    static double now();

    /**
     * Reads the samples from a session's metadata. No samples (a session recorded before
     * semhap kept them) is not an error; malformed ones are, as `steady_clock: reason`.
     */
    static bool fromInfo(const SessionInfo &info, SessionClock *clock, QString *error);
    /** The metadata value of `samples`. */
    static QByteArray toJson(const std::vector<Sample> &samples);

    bool isEmpty() const { return m_samples.empty(); }
    const std::vector<Sample> &samples() const { return m_samples; }
    /**
     * Session seconds per second of the clock, first sample to last: 1 at real time, below
     * it when the session paused, above it when a simulation ran faster. 1 with one sample.
     */
    double rate() const;
    /** Whether the session's times can be put on the clock: samples, and rate() ≤ 1 +
     * MaxRateError. */
    bool followsClock() const;
    /**
     * Session time `t` on the steady clock: interpolated between the samples around it, and
     * at the rate of real time before the first and after the last. Needs samples.
     */
    double toSteady(double t) const;

private:
    std::vector<Sample> m_samples; ///< in order of t and of steady
};

} // namespace semhap
