// SPDX-License-Identifier: MIT
#include "patternauditioner.h"

#include "transport.h"
#include "voice.h"

#include <algorithm>
#include <cmath>

namespace semhap {

namespace {

/** After an end, frames of zero keep going this long so the device settles at rest. */
constexpr double Tail = 0.2;

} // namespace

PatternAuditioner::PatternAuditioner(QObject *parent) : QObject(parent)
{
    m_timer.setTimerType(Qt::PreciseTimer);
    connect(&m_timer, &QTimer::timeout, this, &PatternAuditioner::tick);
}

PatternAuditioner::~PatternAuditioner()
{
    stop();
}

bool PatternAuditioner::begin(const PatternPtr &pattern, const TransportSource &source,
                              double intensity, double endAt, double startTime, QString *reason)
{
    Transport *transport = source ? source() : nullptr;
    if (!pattern || !transport) {
        *reason = tr("There is no device to play on.");
        return false;
    }
    if (!resolvePatternRoutes(*pattern, transport->model(), {}, &m_routes, reason))
        return false;
    const bool wasPlaying = isPlaying();
    m_source = source;
    m_channels = transport->model().channelCount();
    m_voice = std::make_unique<Voice>(pattern);
    m_clock.start();
    m_frames = 0;
    m_idleSince = -1.0;
    m_endAt = endAt;
    m_startTime = startTime;
    m_voice->setParam(ParamTable::Intensity, intensity, 0.0);
    m_voice->begin(0.0);
    // The timer runs at the device's rate, up to 500 Hz (a 2 ms interval).
    m_timer.start(std::max(2, int(std::lround(1000.0 / transport->model().rate()))));
    tick();
    if (!wasPlaying)
        emit playingChanged(true);
    return true;
}

void PatternAuditioner::end()
{
    if (m_voice && isPlaying())
        m_voice->end(now());
}

void PatternAuditioner::stop()
{
    const bool wasPlaying = isPlaying();
    m_timer.stop();
    if (wasPlaying) {
        if (Transport *transport = m_source ? m_source() : nullptr)
            transport->stopAll();
        emit playingChanged(false);
    }
}

void PatternAuditioner::setIntensity(double intensity)
{
    if (m_voice && isPlaying())
        m_voice->setParam(ParamTable::Intensity, intensity, now());
}

bool PatternAuditioner::isActive() const
{
    return isPlaying() && m_voice && m_voice->isActive();
}

double PatternAuditioner::now() const
{
    return double(m_clock.nsecsElapsed()) * 1e-9;
}

void PatternAuditioner::tick()
{
    Transport *transport = m_source ? m_source() : nullptr;
    if (!transport || transport->model().channelCount() != m_channels) {
        stop(); // the device went or changed under us
        return;
    }
    const double t = now();
    // The end the preview shows, at its time rather than at this tick's.
    if (m_endAt >= 0.0 && t >= m_endAt && m_voice->isActive())
        m_voice->end(m_endAt);
    m_voice->advance(t);
    DeviceFrame frame;
    frame.t = m_startTime + t;
    frame.channelCount = m_channels;
    mixVoice(*m_voice, m_routes, transport->model(), frame.values.data());
    transport->send(frame);
    ++m_frames;
    if (!m_voice->isIdle()) {
        m_idleSince = -1.0;
        return;
    }
    if (m_idleSince < 0)
        m_idleSince = t;
    else if (t - m_idleSince >= Tail)
        stop();
}

} // namespace semhap
