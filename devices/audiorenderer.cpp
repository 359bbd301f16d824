// SPDX-License-Identifier: MIT
#include "audiorenderer.h"

#include <algorithm>
#include <cmath>

namespace semhap {

namespace {

constexpr double TwoPi = 6.283185307179586;
constexpr double FadeSeconds = 0.001;
constexpr std::size_t QueueFrames = 64;
// Drained every 10 ms: a second of 1 kHz frames is room for a drain that ran late.
constexpr std::size_t RenderedFrames = 1024;

} // namespace

AudioRenderer::AudioRenderer(DeviceModelPtr model, double sampleRate, int outputChannels,
                             const std::vector<Channel> &channels)
    : m_model(std::move(model)), m_rate(sampleRate), m_outputs(outputChannels),
      m_period(std::max(1, int(std::lround(sampleRate / m_model->rate())))),
      m_fade(std::max(1, int(std::lround(sampleRate * FadeSeconds)))), m_queue(QueueFrames),
      m_rendered(RenderedFrames)
{
    const size_t count = std::min(channels.size(), size_t(m_model->channelCount()));
    for (size_t c = 0; c < count; ++c) {
        Voice voice;
        voice.output = channels[c].output;
        voice.increment = TwoPi * channels[c].carrier / sampleRate;
        m_voices.push_back(voice);
    }
}

bool AudioRenderer::push(const DeviceFrame &safe, double sentAt)
{
    if (m_queue.push({safe, sentAt, m_stops.load(std::memory_order_acquire)}))
        return true;
    m_fullSkipped.fetch_add(1, std::memory_order_relaxed);
    return false;
}

void AudioRenderer::stop(double requestedAt)
{
    m_stopAt.store(requestedAt, std::memory_order_relaxed);
    m_stops.fetch_add(1, std::memory_order_release);
}

std::uint64_t AudioRenderer::skipped() const
{
    return m_backlogSkipped.load(std::memory_order_relaxed) +
           m_fullSkipped.load(std::memory_order_relaxed);
}

bool AudioRenderer::isSilent() const
{
    return m_silentAfter.load(std::memory_order_acquire) ==
           m_stops.load(std::memory_order_acquire) + 1;
}

bool AudioRenderer::takeRendered(RenderedFrame *frame)
{
    return m_rendered.pop(frame);
}

void AudioRenderer::render(float *out, unsigned long frames, double outputDelay, double now)
{
    std::fill(out, out + frames * unsigned(m_outputs), 0.0f);
    const bool restingBefore =
        m_rampLeft == 0 && std::all_of(m_voices.begin(), m_voices.end(),
                                       [](const Voice &v) { return v.envelope == 0.0; });
    bool tookFrame = false;
    const std::uint32_t stops = m_stops.load(std::memory_order_acquire);
    if (stops != m_stopsSeen) {
        m_stopsSeen = stops;
        // What was queued before the stop goes; a frame sent after it is played next.
        Queued queued;
        m_holding = false;
        while (m_queue.pop(&queued)) {
            if (queued.stops == stops) {
                m_held = queued;
                m_holding = true;
            }
        }
        const DeviceFrame rest = m_model->restFrame(m_lastT);
        rampTo(rest, m_fade);
        m_untilNext = 0;
        // `now` was read as the callback began: a stop asked since plays at this buffer's
        // start, no earlier (the difference would read negative).
        record(rest, std::max(0.0, now - m_stopAt.load(std::memory_order_relaxed)) + outputDelay);
    }
    // What one buffer brings at the model's rate; more than that waiting is late.
    const std::size_t backlog = frames / unsigned(m_period) + 2;
    unsigned long done = 0;
    while (done < frames) {
        if (m_untilNext == 0) {
            Queued next;
            for (std::size_t waiting = m_queue.size(); waiting > backlog; --waiting) {
                m_queue.pop(&next);
                m_backlogSkipped.fetch_add(1, std::memory_order_relaxed);
            }
            if (m_holding) {
                m_holding = false;
                take(m_held, done, outputDelay, now);
                tookFrame = true;
            } else if (m_queue.pop(&next)) {
                take(next, done, outputDelay, now);
                tookFrame = true;
            }
        }
        unsigned long run = frames - done;
        if (m_untilNext > 0)
            run = std::min(run, static_cast<unsigned long>(m_untilNext));
        synthesize(out + done * unsigned(m_outputs), run);
        done += run;
        if (m_untilNext > 0)
            m_untilNext -= int(run);
    }
    if (tookFrame)
        m_silentAfter.store(0, std::memory_order_release);
    else if (restingBefore)
        m_silentAfter.store(stops + 1, std::memory_order_release);
    m_samples.fetch_add(frames, std::memory_order_release);
}

void AudioRenderer::take(const Queued &queued, unsigned long offset, double outputDelay,
                         double now)
{
    DeviceFrame frame = queued.frame;
    // A channel on no output is not played: at rest, as far as anyone can feel.
    for (int c = int(m_voices.size()); c < frame.channelCount; ++c)
        frame.values[size_t(c)] = m_model->channels()[size_t(c)].min;
    m_lastT = frame.t;
    rampTo(frame, m_period);
    m_untilNext = m_period;
    record(frame, std::max(0.0, now - queued.sentAt) + outputDelay + double(offset) / m_rate);
}

void AudioRenderer::rampTo(const DeviceFrame &frame, int samples)
{
    for (size_t c = 0; c < m_voices.size(); ++c) {
        const ChannelSpec &spec = m_model->channels()[c];
        const double range = spec.max - spec.min;
        const double value = int(c) < frame.channelCount ? frame.values[c] : spec.min;
        Voice &voice = m_voices[c];
        voice.target = range > 0.0 ? std::clamp((value - spec.min) / range, 0.0, 1.0) : 0.0;
        voice.step = (voice.target - voice.envelope) / samples;
    }
    m_rampLeft = samples;
}

void AudioRenderer::synthesize(float *out, unsigned long frames)
{
    for (unsigned long s = 0; s < frames; ++s) {
        const bool ramping = m_rampLeft > 0;
        float *sample = out + s * unsigned(m_outputs);
        for (Voice &voice : m_voices) {
            if (ramping)
                voice.envelope = m_rampLeft == 1 ? voice.target : voice.envelope + voice.step;
            sample[voice.output] = float(voice.envelope * std::sin(voice.phase));
            voice.phase += voice.increment;
            if (voice.phase >= TwoPi)
                voice.phase -= TwoPi;
        }
        if (ramping)
            --m_rampLeft;
    }
}

void AudioRenderer::record(const DeviceFrame &frame, double latency)
{
    // A full log ring means nobody drained it for a second: the readout misses a frame,
    // the sound does not.
    m_rendered.push({frame, latency});
}

} // namespace semhap
