// SPDX-License-Identifier: MIT
#include "liverig.h"

#include "foxglovesource.h"
#include "nametable.h"
#include "routercontext.h"
#include "sessioninfo.h"
#include "topicmap.h"
#include "udpframesource.h"

#include <QCoreApplication>
#include <QEventLoop>

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

void LiveRig::setRouter(std::unique_ptr<Router> router, RunSink &sink)
{
    m_pipeline->setRouter(std::move(router), sink);
}

void LiveRig::reject(const QString &message)
{
    std::lock_guard<std::mutex> lock(m_statsMutex);
    m_stats.lastRejection = message;
    ++m_stats.reasons;
}

bool LiveRig::start(QString *error)
{
    if (!m_options.foxglove.isEmpty()) {
        const QUrl &url = m_options.foxglove;
        if (!url.isValid() || url.host().isEmpty() ||
            (url.scheme() != QLatin1String("ws") && url.scheme() != QLatin1String("wss"))) {
            *error = QStringLiteral("expected a robot's server as ws://HOST:PORT, got '%1'")
                         .arg(url.toString());
            return false;
        }
        TopicMap map;
        LoadError mapError;
        if (!TopicMap::load(m_options.topics, &map, &mapError)) {
            *error = mapError.toString();
            return false;
        }
        // The pipeline thread is not a QThread: an event loop made here gives it the event
        // dispatcher the robot's socket registers with.
        {
            QEventLoop dispatcher;
        }
        m_robot = std::make_unique<FoxgloveSource>(m_options.foxglove, map, m_options.topics);
        m_robot->setSilence(m_options.silence);
        m_robot->setErrorHandler([this](const QString &message) { reject(message); });
        m_robot->start();
        m_fatalTold = false;
        startCounting(m_options.foxglove.port());
        return true;
    }
    auto source = std::make_unique<UdpFrameSource>();
    if (!source->bind(m_options.address, m_options.port, error))
        return false;
    source->setSilence(m_options.silence);
    source->setErrorHandler([this](const QString &message) { reject(message); });
    m_source = std::move(source);
    startCounting(m_source->port());
    return true;
}

void LiveRig::startCounting(int port)
{
    m_clock.start();
    m_windowStart = 0.0;
    m_windowFrames = 0;
    m_held = 0;
    std::lock_guard<std::mutex> lock(m_statsMutex);
    m_stats = LinkStats();
    m_stats.port = port;
    for (auto &seen : m_seenSignals)
        seen.clear();
}

void LiveRig::wait(int msecs)
{
    if (m_robot) {
        m_robot->poll([this](const ContactFrame &frame,
                             double arrival) { m_taken.emplace_back(frame, arrival); },
                      msecs);
        // A robot with none of the map's topics is told once; the rig stays, as a silent one.
        if (!m_robot->fatalError().isEmpty() && !m_fatalTold) {
            m_fatalTold = true;
            reject(m_robot->fatalError());
        }
    } else if (m_source) {
        m_source->waitForDatagrams(msecs);
    }
}

void LiveRig::take(const ContactFrame &frame, double arrival, Sink &sink, bool hold)
{
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
    if (hold) {
        ++m_held;
        return;
    }
    sink.onReceivedFrame(frame, arrival);
    m_pipeline->process(frame, sink);
    m_time = frame.t;
}

RunSource::Outcome LiveRig::advance(Sink &sink, const Budget &budget)
{
    const bool hold = !budget.stillRunning->load();
    if (m_robot) {
        for (const auto &[frame, arrival] : m_taken)
            take(frame, arrival, sink, hold);
        m_taken.clear();
    } else if (m_source) {
        m_source->poll(
            [&](const ContactFrame &frame, double arrival) { take(frame, arrival, sink, hold); });
    } else {
        return Outcome::Going;
    }
    publish(double(m_clock.nsecsElapsed()) * 1e-9);
    if (budget.holdSilence)
        return Outcome::Going;
    const bool silent = m_robot ? m_robot->fellSilent() : m_source->fellSilent();
    if (!silent)
        return Outcome::Going;
    if (m_robot) {
        m_robot->poll(
            [&](const ContactFrame &frame, double arrival) { take(frame, arrival, sink, hold); },
            0);
    }
    m_pipeline->endAll(sink);
    return Outcome::Silent;
}

const ActorTable *LiveRig::actors() const
{
    if (m_robot)
        return &m_robot->actors();
    return m_source ? &m_source->actors() : nullptr;
}

RouterContext LiveRig::routerContext(double reactionTime) const
{
    RouterContext context = RunSource::routerContext(reactionTime);
    for (Gripper gripper : {Gripper::Left, Gripper::Right})
        context.signalNames[size_t(gripper)] = signalNames(gripper);
    return context;
}

SessionInfo LiveRig::sessionInfo() const
{
    SessionInfo info;
    if (m_options.foxglove.isEmpty()) {
        info.extra.insert(QStringLiteral("udp"), address().mid(4));
    } else {
        info.extra.insert(QStringLiteral("foxglove"), address());
        info.extra.insert(QStringLiteral("topics"), m_options.topics);
    }
    return info;
}

bool LiveRig::conflictsWith(const RunSource &running) const
{
    const auto *rig = dynamic_cast<const LiveRig *>(&running);
    return rig && m_options.foxglove.isEmpty() && rig->m_options.foxglove.isEmpty() &&
           m_options.port != 0 && m_options.port == rig->linkStats()->port &&
           m_options.address == rig->m_options.address;
}

QString LiveRig::sceneNote() const
{
    return QCoreApplication::translate("semhap::LiveRig",
                                       "Live rig on %1\nThe rig draws its own scene.")
        .arg(address());
}

void LiveRig::shutdown()
{
    m_source.reset();
    m_robot.reset();
    m_taken.clear();
}

void LiveRig::publish(double now)
{
    std::lock_guard<std::mutex> lock(m_statsMutex);
    if (m_robot) {
        const FoxgloveSource::Stats &robot = m_robot->stats();
        m_stats.datagrams = quint64(robot.messages + robot.rejected);
        m_stats.frames = quint64(robot.frames);
        m_stats.rejected = quint64(robot.rejected);
    } else {
        const UdpFrameSource::Stats &source = m_source->stats();
        m_stats.datagrams = source.datagrams;
        m_stats.frames = source.frames;
        m_stats.rejected = source.rejected;
        m_stats.oversize = source.oversize;
    }
    m_stats.held = m_held;
    // The window closes on the clock, not on frames, so a silent rig shows 0 frames/s.
    if (now - m_windowStart >= Window) {
        m_stats.framesPerSecond = double(m_windowFrames) / (now - m_windowStart);
        m_stats.jitter = m_windowFrames > 0 ? m_delayMax - m_delayMin : 0.0;
        m_windowStart = now;
        m_windowFrames = 0;
    }
}

std::optional<RunSource::LinkStats> LiveRig::linkStats() const
{
    std::lock_guard<std::mutex> lock(m_statsMutex);
    return m_stats;
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

QString LiveRig::address() const
{
    if (!m_options.foxglove.isEmpty())
        return m_options.foxglove.toString();
    return QStringLiteral("udp:%1:%2").arg(m_options.address).arg(linkStats()->port);
}

} // namespace semhap
