// SPDX-License-Identifier: MIT
#pragma once

#include "devicemodel.h"
#include "spscring.h"

#include <atomic>
#include <cstdint>
#include <vector>

namespace semhap {

/** A frame as the sound card got it: the values it plays, and when it began to. */
struct RenderedFrame
{
    DeviceFrame frame;    ///< the safe values (channels on no output at rest), caller's `t`
    double latency = 0.0; ///< s from send() to the first sample that carries it, at the DAC
};

/**
 * The sound of a vibrotactile band: each model channel as a sine carrier times its
 * envelope, on one output channel of the card. Envelopes arrive as frames through a
 * lock-free queue; each is reached by a linear ramp over one update period of the model
 * (no steps: no zipper noise), one frame per period, and a backlog beyond what one buffer
 * brings is skipped (latest values win). stop() fades every channel to 0 within 1 ms at
 * the next buffer. render() runs in the audio callback: no lock, no allocation, no wait.
 */
class AudioRenderer
{
public:
    /** Where one model channel plays. */
    struct Channel
    {
        int output = 0;       ///< interleaved output channel, from 0
        double carrier = 0.0; ///< Hz, above 0 and below half the sample rate
    };

    /** Model channel k plays on `channels[k]`; channels past the list stay silent. */
    AudioRenderer(DeviceModelPtr model, double sampleRate, int outputChannels,
                  const std::vector<Channel> &channels);

    /**
     * Queues `safe` (model units, after safety), handed over at `sentAt` (monotonic s).
     * One producer at a time; false when the queue is full (the frame is dropped).
     */
    bool push(const DeviceFrame &safe, double sentAt);
    /** Every channel to rest at the next buffer, dropping what is queued (any thread). */
    void stop(double requestedAt);

    /**
     * Fills `frames` interleaved samples into `out` (the audio callback). `outputDelay`: s
     * from now until the DAC plays the first of them; `now`: monotonic s.
     */
    void render(float *out, unsigned long frames, double outputDelay, double now);
    /** Counts a buffer the card ran out of before render() refilled it (the callback). */
    void countUnderflow() { m_underflows.fetch_add(1, std::memory_order_relaxed); }
    /** Marks the stream ended by itself: the device is gone (PortAudio's thread). */
    void markEnded() { m_ended.store(true, std::memory_order_release); }

    /** The next frame rendered since the last call (one consumer thread). */
    bool takeRendered(RenderedFrame *frame);
    std::uint64_t samplesRendered() const { return m_samples.load(std::memory_order_acquire); }
    /** Frames dropped: the backlog beyond one buffer and pushes into a full queue. */
    std::uint64_t skipped() const;
    std::uint64_t underflows() const { return m_underflows.load(std::memory_order_relaxed); }
    bool ended() const { return m_ended.load(std::memory_order_acquire); }
    /** Every channel has been at rest for a whole buffer since the latest stop, and is. */
    bool isSilent() const;
    double sampleRate() const { return m_rate; }
    int outputChannels() const { return m_outputs; }

private:
    struct Queued
    {
        DeviceFrame frame;
        double sentAt = 0.0;
        std::uint32_t stops = 0; ///< stop() calls before it was pushed: older ones it drops
    };
    struct Voice
    {
        int output = 0;
        double increment = 0.0; ///< phase step per sample (rad)
        double phase = 0.0;
        double envelope = 0.0; ///< amplitude 0..1 now
        double target = 0.0;
        double step = 0.0; ///< envelope change per sample while ramping
    };

    void take(const Queued &queued, unsigned long offset, double outputDelay, double now);
    void rampTo(const DeviceFrame &frame, int samples);
    void synthesize(float *out, unsigned long frames);
    void record(const DeviceFrame &frame, double latency);

    DeviceModelPtr m_model;
    double m_rate;
    int m_outputs;
    int m_period; ///< samples per update period of the model
    int m_fade;   ///< samples of the stop's fade
    std::vector<Voice> m_voices;
    SpscRing<Queued> m_queue;
    Queued m_held;          ///< audio thread: a frame pushed after a stop, popped with the drain
    bool m_holding = false; ///< audio thread: m_held is next
    SpscRing<RenderedFrame> m_rendered;
    // The callback's own state.
    int m_untilNext = 0; ///< samples until the next frame may start its ramp
    int m_rampLeft = 0;
    double m_lastT = 0.0;
    std::uint32_t m_stopsSeen = 0;
    // Shared with the other threads.
    std::atomic<std::uint32_t> m_stops{0};
    std::atomic<double> m_stopAt{0.0};
    std::atomic<std::uint32_t> m_silentAfter{0}; ///< m_stops + 1 when silent since that stop
    std::atomic<std::uint64_t> m_samples{0};
    std::atomic<std::uint64_t> m_backlogSkipped{0};
    std::atomic<std::uint64_t> m_fullSkipped{0};
    std::atomic<std::uint64_t> m_underflows{0};
    std::atomic<bool> m_ended{false};
};

} // namespace semhap
