// SPDX-License-Identifier: MIT
#include "patternauditioner.h"

#include "transport.h"
#include "voice.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace semhap {

namespace {

/** After an end, frames of zero keep going this long so the device settles at rest. */
constexpr double Tail = 0.2;
/** How often the GUI thread looks at the audition (ms): idle, rebound. */
constexpr int WatchInterval = 20;
/** The highest rate rendered (Hz): a frame every 2 ms. */
constexpr double MaxRate = 500.0;

} // namespace

PatternAuditioner::PatternAuditioner(QObject *parent) : QObject(parent)
{
    m_watch.setInterval(WatchInterval);
    connect(&m_watch, &QTimer::timeout, this, &PatternAuditioner::watch);
}

PatternAuditioner::~PatternAuditioner()
{
    stop();
}

bool PatternAuditioner::begin(const PatternPtr &pattern, const TransportSource &source,
                              double intensity, double endAt, double startTime, QString *reason)
{
    std::shared_ptr<Transport> transport = source ? source() : nullptr;
    if (!pattern || !transport) {
        *reason = tr("There is no device to play on.");
        return false;
    }
    std::vector<PlayerInput::Route> routes;
    if (!resolvePatternRoutes(*pattern, transport->model(), {}, &routes, reason))
        return false;
    const bool wasPlaying = isPlaying();
    join(); // a restart: the old voice's thread goes first
    m_transport = std::move(transport);
    m_source = source;
    m_routes = std::move(routes);
    m_channels = m_transport->model().channelCount();
    m_voice = std::make_unique<Voice>(pattern);
    m_clock.start();
    m_frames = 0;
    m_idleSince = -1.0;
    m_endAt = endAt;
    m_startTime = startTime;
    m_voice->setParam(ParamTable::Intensity, intensity, 0.0);
    m_voice->begin(0.0);
    m_quit = false;
    const double period = 1.0 / std::min(m_transport->model().rate(), MaxRate);
    m_thread = std::thread([this, period] { render(period); });
    m_watch.start();
    if (!wasPlaying)
        emit playingChanged(true);
    return true;
}

void PatternAuditioner::end()
{
    std::lock_guard<std::mutex> lock(m_voiceMutex);
    if (m_voice && isPlaying())
        m_voice->end(now());
}

void PatternAuditioner::stop()
{
    const bool wasPlaying = isPlaying();
    m_watch.stop();
    const std::shared_ptr<Transport> transport = m_transport;
    join();
    if (wasPlaying) {
        if (transport)
            transport->stopAll();
        emit playingChanged(false);
    }
}

void PatternAuditioner::join()
{
    m_quit = true;
    if (m_thread.joinable())
        m_thread.join();
    m_transport.reset();
}

void PatternAuditioner::setIntensity(double intensity)
{
    std::lock_guard<std::mutex> lock(m_voiceMutex);
    if (m_voice && isPlaying())
        m_voice->setParam(ParamTable::Intensity, intensity, now());
}

bool PatternAuditioner::isActive() const
{
    std::lock_guard<std::mutex> lock(m_voiceMutex);
    return isPlaying() && m_voice && m_voice->isActive();
}

double PatternAuditioner::now() const
{
    return double(m_clock.nsecsElapsed()) * 1e-9;
}

void PatternAuditioner::render(double period)
{
    using Clock = std::chrono::steady_clock;
    const auto step =
        std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(period));
    Clock::time_point next = Clock::now();
    while (!m_quit.load()) {
        DeviceFrame frame;
        {
            std::lock_guard<std::mutex> lock(m_voiceMutex);
            const double t = now();
            // The end the preview shows, at its time rather than at this frame's.
            if (m_endAt >= 0.0 && t >= m_endAt && m_voice->isActive())
                m_voice->end(m_endAt);
            m_voice->advance(t);
            frame.t = m_startTime + t;
            frame.channelCount = m_channels;
            mixVoice(*m_voice, m_routes, m_transport->model(), frame.values.data());
            if (!m_voice->isIdle())
                m_idleSince = -1.0;
            else if (m_idleSince < 0)
                m_idleSince = t;
        }
        m_transport->send(frame);
        ++m_frames;
        // On the device's clock; a thread held up for longer than a frame goes on from now
        // rather than sending the frames it missed in a burst.
        next += step;
        const Clock::time_point current = Clock::now();
        if (next < current)
            next = current;
        std::this_thread::sleep_until(next);
    }
}

void PatternAuditioner::watch()
{
    if (!isPlaying())
        return;
    // The device went or changed under us: the transport the thread holds is not its any
    // more (closed, and freed once the thread lets go).
    const std::shared_ptr<Transport> bound = m_source ? m_source() : nullptr;
    if (bound != m_transport || bound->model().channelCount() != m_channels) {
        stop();
        return;
    }
    double idleSince = -1.0;
    {
        std::lock_guard<std::mutex> lock(m_voiceMutex);
        idleSince = m_idleSince;
    }
    if (idleSince >= 0 && now() - idleSince >= Tail)
        stop();
}

} // namespace semhap
