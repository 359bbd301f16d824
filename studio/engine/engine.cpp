// SPDX-License-Identifier: MIT
#include "engine.h"

#include "devicemanager.h"
#include "deviceoutputsink.h"
#include "deviceuri.h"
#include "foxglovepublisher.h"
#include "sessionwriter.h"
#include "simulationsource.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QFileInfo>
#include <QRegularExpression>

#include <chrono>
#include <cmath>
#include <future>

namespace semhap {

namespace {

using Clock = std::chrono::steady_clock;

/** Display frames per second the step() button advances by. */
constexpr double StepRate = 60.0;
/** Task metrics go to the GUI this often (simulated seconds). */
constexpr double MetricsPeriod = 0.25;
/** The most simulated time one batch catches up before pacing gives up and restarts (s). */
constexpr double MaxLag = 0.2;
/** How long a source that is not paced waits for its link before looking at quit (ms). */
constexpr int WaitSlice = 5;

double seconds(Clock::duration d)
{
    return std::chrono::duration<double>(d).count();
}

} // namespace

void Engine::StepSink::onContactFrame(const ContactFrame &frame)
{
    m_engine.takeFrame(frame, qQNaN());
}

void Engine::StepSink::onReceivedFrame(const ContactFrame &frame, double arrival)
{
    m_engine.takeFrame(frame, arrival);
}

void Engine::takeFrame(const ContactFrame &frame, double arrival)
{
    if (m_recorder)
        m_recorder->recordContactFrame(frame, arrival);
    if (m_publisher)
        m_publisher->onContactFrame(frame);
    m_feed.push(frame);
}

void Engine::StepSink::onEvent(const SemanticEvent &event)
{
    m_engine.m_outputs.onEvent(event);
}

void Engine::StepSink::onDeviceFrame(const DeviceFrame &frame)
{
    m_engine.m_outputs.onDeviceFrame(frame);
}

void Engine::StepSink::onNodeActivity(const NodeActivity &activity)
{
    m_engine.m_outputs.onNodeActivity(activity);
}

void Engine::rewire()
{
    // The recording first: it keeps what the router asked for; then the bands, whose sent
    // frames are the readouts' device frames (m_sentFeed); then the feed, for the rest.
    m_publisher.reset();
    Pipeline *running = m_source ? m_source->pipeline() : nullptr;
    if (m_foxglove && running && m_run->actors()) {
        // Stamped on the wall clock: the run's t now is now.
        const std::int64_t origin =
            QDateTime::currentMSecsSinceEpoch() * 1000000 - std::llround(m_simTime.load() * 1e9);
        m_publisher = std::make_unique<FoxglovePublisher>(*m_foxglove, running->router(),
                                                          *m_run->actors(), origin);
        const Hands hands = m_source->hands();
        for (const Gripper g : {Gripper::Left, Gripper::Right}) {
            if (hands[size_t(g)])
                m_publisher->advertise(g);
        }
    }
    m_outputs = SinkList{m_recorder.get(), m_output.get(), &m_feed, m_publisher.get()};
}

bool Engine::startPublishing(const QHostAddress &address, quint16 port, QString *error)
{
    auto server = std::make_unique<FoxgloveServer>(QStringLiteral("semhap studio"));
    if (!server->listen(address, port, error))
        return false;
    std::unique_ptr<FoxgloveServer> old;
    {
        std::lock_guard<std::mutex> lock(m_setupMutex);
        old = std::move(m_foxglove);
        m_foxglove = std::move(server);
        rewire();
    }
    return true; // `old` closes here, off the pipeline's lock
}

void Engine::stopPublishing()
{
    std::unique_ptr<FoxgloveServer> old;
    {
        std::lock_guard<std::mutex> lock(m_setupMutex);
        old = std::move(m_foxglove);
        rewire();
    }
}

QString Engine::publishingUrl() const
{
    return m_foxglove ? m_foxglove->url() : QString();
}

FoxgloveServer::Stats Engine::publishingStats() const
{
    return m_foxglove ? m_foxglove->stats() : FoxgloveServer::Stats();
}

Engine::Engine(QObject *parent) : QObject(parent), m_devices(std::make_unique<DeviceManager>())
{
    m_drainTimer.setInterval(16);
    connect(&m_drainTimer, &QTimer::timeout, this, &Engine::drain);
    m_drainTimer.start();
}

Engine::~Engine()
{
    stopThread();
    if (m_recorder)
        m_recorder->finish();
    m_devices->stopAll();
}

bool Engine::load(const RunOptions &options, QString *error)
{
    if (!start(options, error))
        return false;
    emit sourceChanged();
    return true;
}

bool Engine::start(const RunOptions &options, QString *error)
{
    std::unique_ptr<SimRun> run = SimRun::create(options, error);
    if (!run)
        return false;
    if (!startSource(
            std::make_unique<SimulationSource>(std::move(run)),
            [this](QString *restartError) { return start(m_options, restartError); }, error))
        return false;
    m_options = options;
    return true;
}

bool Engine::startSource(std::unique_ptr<RunSource> source, std::function<bool(QString *)> restart,
                         QString *error)
{
    // A source that needs what the running one holds (its port) has it let go of first.
    const bool conflicts = m_run && source->conflictsWith(*m_run);
    if (conflicts) {
        emit sourceAboutToChange();
        stopSource();
    }
    // What a source reads belongs to the thread that reads it, so the new pipeline thread
    // opens it; it runs only once the old run has stopped and the new one is installed, and
    // the old run goes on untouched when the source cannot open.
    QString openError;
    std::promise<bool> opened;
    std::future<bool> openResult = opened.get_future();
    std::promise<bool> go;
    std::thread thread([this, &openError, opening = source.get(), opened = std::move(opened),
                        goAhead = go.get_future()]() mutable {
        const bool ok = opening->start(&openError);
        opened.set_value(ok); // openError is the caller's again from here
        if (!ok)
            return;
        if (goAhead.get())
            loop(*opening);
        opening->shutdown();
    });
    if (!openResult.get()) {
        thread.join();
        *error = openError;
        if (conflicts) {
            // Nothing is left to go back to: the simulation comes back instead.
            QString simError;
            start(m_options, &simError);
        }
        return false;
    }
    emit sourceAboutToChange();
    stopSource();
    m_run = std::move(source);
    m_source = m_run.get();
    m_restart = std::move(restart);
    m_live.reset();
    install();
    m_quit = false;
    m_thread = std::move(thread);
    go.set_value(true);
    return true;
}

bool Engine::openReplay(const QString &path, QString *error)
{
    if (!m_replay.open(path, error))
        return false;
    emit sourceAboutToChange();
    if (!isReplaying() && m_source)
        keepRun();
    m_source = &m_replay;
    ++m_generation; // the run's late metrics are not the replay's
    m_replay.begin();
    emit sourceChanged();
    return true;
}

void Engine::keepRun()
{
    pause();
    stopRecording();
    m_keptDriving = m_driving.load();
    setDriving(false);
    {
        // The bands rest while the replay owns the readouts; the run sends again when it
        // runs again.
        std::lock_guard<std::mutex> lock(m_setupMutex);
        silenceDevices(m_outputs);
        m_runKept = true;
    }
    drain(); // everything the run sent, rest values too, is in its history
    m_keptHistory.setKeepSeconds(m_history.keepSeconds());
    m_keptHistory.assign(m_history);
}

bool Engine::closeReplay(QString *error)
{
    if (!isReplaying())
        return true;
    RunSource *run = streamingSource();
    if (!run)
        return reset(error);
    emit sourceAboutToChange();
    m_replay.close();
    m_source = run;
    m_history.assign(m_keptHistory);
    m_keptHistory.start({}, {}, {});
    // What the bands were sent during the replay (an audition) is not the run's.
    m_sentFeed.start(deviceNames(), *m_devices);
    // The paused run's own, fresher than the last it sent the GUI.
    if (const QJsonObject runMetrics = metrics(); !runMetrics.isEmpty())
        m_history.setMetrics(runMetrics);
    m_runKept = false; // a rig that fell silent meanwhile ends its messages now
    emit sourceChanged();
    setDriving(m_keptDriving);
    return true;
}

bool Engine::listen(const LiveRigOptions &options, QString *error)
{
    const int generation = m_generation;
    const bool listening = startLive(options, error);
    if (listening || m_generation != generation)
        emit sourceChanged(); // when the rig could not reopen its port, the simulation came back
    return listening;
}

RouterContext Engine::routerContext() const
{
    if (isReplaying())
        return m_replay.info().routerContext;
    if (m_run)
        return m_run->routerContext(m_options.reactionTime);
    RouterContext context;
    context.reactionTime = m_options.reactionTime;
    return context;
}

bool Engine::startLive(const LiveRigOptions &options, QString *error)
{
    LoadError loadError;
    // A rig says nothing in advance of the signals it sends.
    RouterContext context;
    context.reactionTime = m_options.reactionTime;
    std::unique_ptr<Router> router =
        loadRouter(options.router, options.overrides, &loadError, context);
    if (!router) {
        *error = loadError.toString();
        return false;
    }
    if (!startSource(
            std::make_unique<LiveRig>(options, std::move(router)),
            [this](QString *restartError) { return startLive(liveOptions(), restartError); },
            error))
        return false;
    m_live = options;
    m_options.router = options.router;
    m_options.overrides = options.overrides;
    return true;
}

void Engine::stopStreaming()
{
    stopThread();
    m_runKept = false;
    stopRecording();
    if (m_running.exchange(false))
        emit runningChanged(false);
    m_output.reset();
    rewire();
    m_source = isReplaying() ? m_source : nullptr;
    m_run.reset();
    m_live.reset();
}

RunSource *Engine::streamingSource() const
{
    return m_run.get();
}

void Engine::stopSource()
{
    stopStreaming();
    if (isReplaying()) {
        m_source = nullptr;
        m_replay.close();
        m_keptHistory.start({}, {}, {}); // the run it kept is gone
    }
}

void Engine::install()
{
    ++m_generation;
    m_appliedGraph.reset();
    const Player &player = pipeline().router().player();
    QString bindError;
    bindRouterDevices(player, &bindError);
    m_output = std::make_unique<DeviceOutputSink>(player, *m_devices);
    rewire();
    setDriving(false);
    m_simTime = m_run->time();
    m_realtimeFactor = 0.0;
    m_nextMetrics = 0.0;
    m_pendingSteps = 0;

    m_feed.discard(); // whatever the old run left in the feed is not the new run's
    m_history.start(liveDevicesOf(pipeline().router(), m_source->hands()), shownThresholds(),
                    pipeline().router().nodeIds());
    m_sentFeed.start(deviceNames(), *m_devices);
    m_history.setMetrics(m_run->metrics()); // empty without a task (a live rig)
}

Pipeline &Engine::pipeline()
{
    return *m_source->pipeline();
}

double Engine::simTime() const
{
    return isReplaying() ? m_replay.time() : m_simTime.load();
}

DriveOperator *Engine::driveOperator() const
{
    return m_run ? m_run->driveOperator() : nullptr;
}

RunSource::LinkStats Engine::liveStats() const
{
    const std::optional<RunSource::LinkStats> stats = m_run ? m_run->linkStats() : std::nullopt;
    return stats.value_or(RunSource::LinkStats());
}

LiveRigOptions Engine::liveOptions() const
{
    if (!m_live)
        return LiveRigOptions();
    LiveRigOptions options = *m_live;
    options.port = liveStats().port;
    return options;
}

QString Engine::liveUri() const
{
    return m_run ? m_run->address() : QString();
}

void Engine::bindRouterDevices(const Player &player, QString *error)
{
    // The router's devices keep a band the user bound to them when the model still fits;
    // the others play on virtual devices, which show in the studio like real ones.
    for (int d = 0; d < player.deviceCount(); ++d) {
        const QString &name = player.deviceName(d);
        const DeviceModel &model = player.deviceModel(d);
        const auto bound = m_devices->status();
        const bool keep = std::any_of(bound.begin(), bound.end(), [&](const BoundDevice &b) {
            return b.name == name && b.model == model.name();
        });
        if (!keep)
            m_devices->bind(name, DeviceUri::virtualFor(name),
                            std::make_shared<const DeviceModel>(model), error);
    }
}

bool Engine::setRouter(const RouterGraph &graph, QString *error)
{
    if (!isLoaded()) {
        *error = tr("nothing is loaded");
        return false;
    }
    if (isReplaying())
        return m_replay.reroute(graph, error);
    LoadError loadError;
    std::unique_ptr<SessionWriter> recording;
    std::unique_ptr<Router> router = Router::compile(graph, &loadError, routerContext());
    if (!router) {
        *error = loadError.toString();
        return false;
    }
    {
        std::lock_guard<std::mutex> lock(m_setupMutex);
        // The old router's devices fall silent now; a device the new router keeps goes on
        // with the new router's frames from the next tick.
        silenceDevices(m_outputs);
        m_run->setRouter(std::move(router), m_sink);
        // What the old router's devices were sent is read with its numbering, before a
        // rebinding frees a transport.
        m_sentFeed.drainInto(m_history);
        // The old router's closing events went into the recording; the new router is
        // another session.
        recording = std::move(m_recorder);
        rewire();
        const Player &player = pipeline().router().player();
        QString bindError;
        bindRouterDevices(player, &bindError);
        m_output = std::make_unique<DeviceOutputSink>(player, *m_devices);
        rewire();
        m_sentFeed.rebind(deviceNames(), *m_devices);
        // What the old router sent is read with its numbering, before the history switches;
        // the feed is drained on this thread only, so nothing newer slips in before that.
        m_feed.drainInto(m_history);
    }
    m_history.commit();
    if (recording) {
        recording->finish();
        emit recordingChanged(false);
    }
    m_history.setRouter(liveDevicesOf(pipeline().router(), m_source->hands()), shownThresholds(),
                        pipeline().router().nodeIds());
    m_appliedGraph = std::make_unique<RouterGraph>(graph);
    // A graph from a file or preset is named by it; an untitled one runs over the last.
    if (!graph.file.isEmpty())
        m_options.router = graph.file;
    m_options.overrides.clear();
    emit routerChanged();
    return true;
}

const RouterGraph &Engine::routerGraph() const
{
    // An applied graph is what runs (or waits behind a replay), with renamed pattern files
    // followed.
    if (m_appliedGraph)
        return *m_appliedGraph;
    return streamingSource()->pipeline()->router().graph();
}

QString Engine::routerSource() const
{
    return isReplaying() ? m_replay.routerSource() : m_options.router;
}

bool Engine::isRunRouterEdited() const
{
    // Only an applied graph can differ from what options().router loads.
    return m_appliedGraph && streamingSource() &&
           !routesAs(streamingSource()->pipeline()->router(), m_options.router);
}

void Engine::followRenamedPattern(const QString &from, const QString &to)
{
    // The running router holds the pattern already; what reset() and the workspace use must
    // name the file where it is now.
    if (m_appliedGraph)
        m_appliedGraph->followRenamedFile(from, to);
}

bool Engine::isRouterEdited() const
{
    return isReplaying() ? m_replay.isRouterEdited() : isRunRouterEdited();
}

std::array<GripperThresholds, 2> Engine::shownThresholds()
{
    return thresholdsOf(pipeline().router(), m_source->hands());
}

bool Engine::reset(QString *error)
{
    const bool wasRunning = isRunning();
    // The rig that listens, or that a replay keeps behind it, listens afresh on its port.
    std::unique_ptr<RouterGraph> applied = std::move(m_appliedGraph);
    // A copy: the restart puts the new source's in its place.
    const std::function<bool(QString *)> restart = m_restart;
    const bool started = m_run && restart ? restart(error) : start(m_options, error);
    if (!started)
        return false;
    if (applied && !setRouter(*applied, error))
        return false;
    emit sourceChanged();
    if (wasRunning)
        run();
    return true;
}

void Engine::run()
{
    if (!isLoaded() || !m_source->isStreaming() || m_source->isDone() || m_running.exchange(true))
        return;
    emit runningChanged(true);
}

void Engine::pause()
{
    if (!m_running.exchange(false))
        return;
    // The step under way ends first (a batch looks at m_running before each step): nothing
    // the run sends follows a pause (an audition).
    {
        std::lock_guard<std::mutex> lock(m_setupMutex);
    }
    emit runningChanged(false);
}

void Engine::step()
{
    if (!m_run || !m_run->isPaced() || isReplaying() || isRunning())
        return;
    const int steps = int(std::lround(1.0 / StepRate / m_run->timestep()));
    m_pendingSteps.fetch_add(std::max(1, steps));
}

void Engine::setSpeed(double speed)
{
    speed = std::clamp(speed, 0.01, 100.0);
    if (speed == m_speed.load())
        return;
    m_speed = speed;
    ++m_speedEpoch;
    emit speedChanged(speed);
}

void Engine::setDriving(bool driving)
{
    driving = driving && driveOperator() && !isReplaying();
    if (m_driving.exchange(driving) != driving)
        emit drivingChanged(driving);
}

bool Engine::bindDevice(const QString &name, const QString &uri, QString *error)
{
    if (!isLoaded() || !m_source->pipeline()) {
        *error = tr("nothing runs that sends to devices");
        return false;
    }
    const Player &player = pipeline().router().player();
    const int device = player.deviceIndex(name);
    if (device < 0) {
        *error = tr("the router has no device '%1'").arg(name);
        return false;
    }
    // At a tick boundary: the output sink and the sent feed hold the transports.
    std::lock_guard<std::mutex> lock(m_setupMutex);
    m_sentFeed.drainInto(m_history); // what the transport being replaced sent
    if (!m_devices->bind(name, uri,
                         std::make_shared<const DeviceModel>(player.deviceModel(device)), error))
        return false;
    m_output = std::make_unique<DeviceOutputSink>(player, *m_devices);
    rewire();
    m_sentFeed.rebind(deviceNames(), *m_devices);
    return true;
}

void Engine::setDuration(double seconds)
{
    if (!m_run)
        return;
    std::lock_guard<std::mutex> lock(m_setupMutex);
    m_run->setDuration(seconds);
}

std::array<std::optional<HandCommand>, 2> Engine::handCommands()
{
    if (!driveOperator() || !m_run->world())
        return {};
    std::lock_guard<std::mutex> lock(m_setupMutex);
    return currentCommands(*m_run->world());
}

void Engine::stopAll()
{
    // The bands first: they go to zero before anything here waits for the pipeline thread.
    const bool wasRunning = m_running.exchange(false);
    m_devices->stopAll();
    {
        // The step under way ends (a batch looks at m_running before each step); what it
        // sent after the stop is sent to rest again.
        std::lock_guard<std::mutex> lock(m_setupMutex);
        m_devices->stopAll();
        // The readouts show the rest values the transports sent; the recording, which keeps
        // what the router asked for, shows the stop too.
        if (m_source && m_source->pipeline() && m_recorder)
            silenceDevices(*m_recorder);
    }
    if (wasRunning)
        emit runningChanged(false);
    drain();
}

void Engine::drain()
{
    if (!m_source || !m_source->isStreaming())
        return; // a replay fills the history itself
    m_feed.drainInto(m_history);
    m_sentFeed.drainInto(m_history);
    m_history.commit();
}

void Engine::stopThread()
{
    if (!m_thread.joinable())
        return;
    m_quit = true;
    m_thread.join();
}

void Engine::loop(RunSource &source)
{
    const bool paced = source.isPaced();
    const double dt = source.timestep();
    Clock::time_point anchorWall = Clock::now();
    double anchorSim = source.time();
    int epoch = m_speedEpoch.load();
    bool wasRunning = false;
    Clock::time_point rateWall = anchorWall;
    double rateSim = anchorSim;

    while (!m_quit.load()) {
        const bool running = m_running.load();
        const Clock::time_point now = Clock::now();
        RunSource::Budget budget;
        budget.running = running;
        budget.stillRunning = &m_running;
        budget.driving = m_driving.load(std::memory_order_relaxed);
        budget.holdSilence = m_runKept.load();
        bool ready = true;
        if (paced) {
            if (running) {
                if (!wasRunning || epoch != m_speedEpoch.load()) {
                    epoch = m_speedEpoch.load();
                    anchorWall = now;
                    anchorSim = source.time();
                }
                const double target = anchorSim + m_speed.load() * seconds(now - anchorWall);
                budget.steps = std::lround(std::floor((target - source.time()) / dt));
                if (double(budget.steps) * dt > MaxLag) {
                    // Slower than asked: run flat out from here instead of chasing the past.
                    budget.steps = std::lround(MaxLag / dt);
                    anchorWall = now;
                    anchorSim = source.time() + double(budget.steps) * dt;
                }
            } else {
                budget.steps = m_pendingSteps.exchange(0);
            }
            wasRunning = running;
            ready = budget.steps > 0;
            if (!ready)
                source.wait(1);
        } else {
            source.wait(WaitSlice);
        }

        // A run ends in a batch of steps; read under the lock, as setDuration() (a study's
        // trial, from the GUI thread) changes where it ends.
        bool done = false;
        if (ready) {
            std::lock_guard<std::mutex> lock(m_setupMutex);
            if (source.advance(m_sink, budget) == RunSource::Outcome::Silent) {
                silenceDevices(m_outputs);
                m_devices->stopAll();
            }
            m_simTime.store(source.time(), std::memory_order_relaxed);
            sendMetrics(source);
            done = source.isDone();
        }
        if (done && m_running.exchange(false)) {
            QMetaObject::invokeMethod(
                this,
                [this] {
                    emit runningChanged(false);
                    emit finished();
                },
                Qt::QueuedConnection);
        }

        const double wall = seconds(now - rateWall);
        if (wall >= 0.5) {
            m_realtimeFactor = running ? (source.time() - rateSim) / wall : 0.0;
            rateWall = now;
            rateSim = source.time();
        }
    }
}

void Engine::sendMetrics(const RunSource &source)
{
    const double t = source.time();
    if (t < m_nextMetrics)
        return;
    m_nextMetrics = t + MetricsPeriod;
    const QJsonObject metrics = source.metrics();
    if (metrics.isEmpty())
        return; // no task to count
    const int generation = m_generation;
    QMetaObject::invokeMethod(
        this,
        [this, metrics, generation] {
            if (generation == m_generation)
                m_history.setMetrics(metrics);
        },
        Qt::QueuedConnection);
}

void Engine::silenceDevices(PipelineSink &sink)
{
    const Player &player = pipeline().router().player();
    for (int d = 0; d < player.deviceCount(); ++d) {
        DeviceFrame silence = player.deviceModel(d).restFrame(pipeline().now());
        silence.device = d;
        sink.onDeviceFrame(silence);
    }
}

QStringList Engine::deviceNames()
{
    const Player &player = pipeline().router().player();
    QStringList names;
    for (int d = 0; d < player.deviceCount(); ++d)
        names.append(player.deviceName(d));
    return names;
}

QJsonObject Engine::metrics()
{
    if (!m_run || isReplaying())
        return QJsonObject();
    std::lock_guard<std::mutex> lock(m_setupMutex);
    return m_run->metrics();
}

bool Engine::startRecording(const QString &path, const QString &notes, QString *error,
                            const QMap<QString, QString> &tags)
{
    if (!isLoaded() || !m_source->isStreaming()) {
        *error = tr("nothing runs that could be recorded");
        return false;
    }
    stopRecording();
    SessionInfo info = m_run->sessionInfo();
    // Applied from the editor: the graph itself is in the session, its name is not.
    info.routerSource = m_options.router;
    info.overrides = m_options.overrides;
    info.routerContext.reactionTime = m_options.reactionTime;
    info.source = QStringLiteral("studio");
    for (const BoundDevice &device : m_devices->status())
        info.bindings.insert(device.name, device.uri);
    info.semhapVersion = QCoreApplication::applicationVersion();
    info.notes = notes;
    for (auto tag = tags.begin(); tag != tags.end(); ++tag)
        info.extra.insert(tag.key(), tag.value());
    QDir().mkpath(QFileInfo(path).absolutePath());
    std::unique_ptr<SessionWriter> recorder;
    {
        std::lock_guard<std::mutex> lock(m_setupMutex);
        recorder = SessionWriter::create(path, info, pipeline().router(), error);
        if (!recorder)
            return false;
        recorder->setActorTable(m_run->actors());
        m_recorder = std::move(recorder);
        rewire();
        m_run->recordingStarted();
    }
    emit recordingChanged(true);
    return true;
}

void Engine::stopRecording()
{
    std::unique_ptr<SessionWriter> recorder;
    {
        std::lock_guard<std::mutex> lock(m_setupMutex);
        recorder = std::move(m_recorder);
        rewire();
    }
    if (!recorder)
        return;
    recorder->finish();
    emit recordingChanged(false);
}

QString Engine::recordingPath() const
{
    return m_recorder ? m_recorder->path() : QString();
}

quint64 Engine::recordingDropped() const
{
    return m_recorder ? m_recorder->dropped() : 0;
}

QString Engine::newRecordingPath(const QString &folder, const QString &name) const
{
    const QString time = QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-HHmmss"));
    QString stem = name.simplified().left(80);
    static const QRegularExpression unsafe(QStringLiteral(R"([/\\:*?"<>|\x00-\x1f])"));
    stem.replace(unsafe, QStringLiteral("_"));
    if (stem.startsWith(QLatin1Char('.')))
        stem[0] = QLatin1Char('_'); // not a hidden file
    if (stem.isEmpty()) {
        const auto base = [](const QString &file) { return QFileInfo(file).completeBaseName(); };
        stem = (isLive() ? QStringLiteral("live") : base(m_options.scene)) + QLatin1Char('-') +
               base(m_options.router);
    }
    // A recording stopped and started again within a second would name the same file, and
    // a session is never overwritten: starting failed with "already exists".
    const QString first = QStringLiteral("%1/%2-%3").arg(folder, stem, time);
    QString path = first + QStringLiteral(".db");
    for (int n = 2; QFileInfo::exists(path); ++n)
        path = QStringLiteral("%1-%2.db").arg(first).arg(n);
    return path;
}

} // namespace semhap
