// SPDX-License-Identifier: MIT
#include "liverig.h"

#include "nametable.h"
#include "udpframesource.h"

#include <algorithm>

namespace semhap {

namespace {

/** Seconds the frame rate and jitter are measured over. */
constexpr double Window = 1.0;

} // namespace

LiveRig::LiveRig(const LiveRigOptions &options, std::unique_ptr<Router> router)
    : m_options(options), m_pipeline(std::make_unique<Pipeline>(std::move(router)))
{}

LiveRig::~LiveRig() = default;

void LiveRig::setRouter(std::unique_ptr<Router> router, PipelineSink &sink)
{
    m_pipeline->setRouter(std::move(router), sink);
}

bool LiveRig::open(QString *error)
{
    auto source = std::make_unique<UdpFrameSource>();
    if (!source->bind(m_options.address, m_options.port, error))
        return false;
    source->setSilence(m_options.silence);
    source->setErrorHandler([this](const QString &message) {
        std::lock_guard<std::mutex> lock(m_statsMutex);
        m_lastRejection = message;
        ++m_rejections;
    });
    m_source = std::move(source);
    m_clock.start();
    m_windowStart = 0.0;
    m_windowFrames = 0;
    m_held = 0;
    std::lock_guard<std::mutex> lock(m_statsMutex);
    m_stats = Stats();
    m_stats.port = m_source->port();
    for (auto &seen : m_seenSignals)
        seen.clear();
    return true;
}

bool LiveRig::wait(int msecs)
{
    return m_source && m_source->waitForDatagrams(msecs);
}

void LiveRig::poll(const FrameHandler &process, bool hold)
{
    if (!m_source)
        return;
    m_source->poll([&](const ContactFrame &frame, double arrival) {
        const double delay = arrival - frame.t;
        if (m_windowFrames == 0) {
            m_delayMin = delay;
            m_delayMax = delay;
        } else {
            m_delayMin = std::min(m_delayMin, delay);
            m_delayMax = std::max(m_delayMax, delay);
        }
        ++m_windowFrames;
        noteSignals(frame);
        if (hold)
            ++m_held;
        else
            process(frame, arrival);
    });
    publish(double(m_clock.nsecsElapsed()) * 1e-9);
}

bool LiveRig::endIfSilent(PipelineSink &sink)
{
    if (!m_source || !m_source->fellSilent())
        return false;
    m_pipeline->endAll(sink);
    return true;
}

const ActorTable &LiveRig::actors() const
{
    return m_source->actors();
}

void LiveRig::close()
{
    m_source.reset();
}

void LiveRig::publish(double now)
{
    const UdpFrameSource::Stats &source = m_source->stats();
    std::lock_guard<std::mutex> lock(m_statsMutex);
    m_stats.datagrams = source.datagrams;
    m_stats.frames = source.frames;
    m_stats.rejected = source.rejected;
    m_stats.oversize = source.oversize;
    m_stats.held = m_held;
    // The window closes on the clock, not on frames, so a silent rig shows 0 frames/s.
    if (now - m_windowStart >= Window) {
        m_stats.framesPerSecond = double(m_windowFrames) / (now - m_windowStart);
        m_stats.jitter = m_windowFrames > 0 ? m_delayMax - m_delayMin : 0.0;
        m_windowStart = now;
        m_windowFrames = 0;
    }
}

LiveRig::Stats LiveRig::stats() const
{
    std::lock_guard<std::mutex> lock(m_statsMutex);
    return m_stats;
}

QString LiveRig::lastRejection(quint64 *count) const
{
    std::lock_guard<std::mutex> lock(m_statsMutex);
    if (count)
        *count = m_rejections;
    return m_lastRejection;
}

void LiveRig::noteSignals(const ContactFrame &frame)
{
    // Only this thread appends: reading without the lock is safe here.
    const std::vector<int> &seen = m_seenSignals[size_t(frame.gripper)];
    for (const SignalValue &signal : frame.signalValues) {
        if (std::find(seen.begin(), seen.end(), signal.id) != seen.end())
            continue;
        std::lock_guard<std::mutex> lock(m_statsMutex);
        m_seenSignals[size_t(frame.gripper)].push_back(signal.id);
    }
}

QStringList LiveRig::signalNames(Gripper gripper) const
{
    std::lock_guard<std::mutex> lock(m_statsMutex);
    QStringList names;
    for (int id : m_seenSignals[size_t(gripper)])
        names.append(semhap::signalNames().name(id));
    return names;
}

QString LiveRig::uri() const
{
    return QStringLiteral("udp:%1:%2").arg(m_options.address).arg(stats().port);
}

} // namespace semhap
