// SPDX-License-Identifier: MIT
#include "engine.h"

#include "devicemanager.h"
#include "deviceoutputsink.h"
#include "deviceuri.h"
#include "foxglovepublisher.h"
#include "sessionwriter.h"

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
/** The user's commanded pose and grip are recorded this often while driving (s). */
constexpr double InputPeriod = 0.01;
/** The most simulated time one batch catches up before pacing gives up and restarts (s). */
constexpr double MaxLag = 0.2;

double seconds(Clock::duration d)
{
    return std::chrono::duration<double>(d).count();
}

} // namespace

void Engine::StepSink::onContactFrame(const ContactFrame &frame)
{
    m_engine.takeFrame(frame, qQNaN());
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
    if (m_foxglove && running) {
        // Stamped on the wall clock: the run's t now is now.
        const std::int64_t origin =
            QDateTime::currentMSecsSinceEpoch() * 1000000 - std::llround(m_simTime.load() * 1e9);
        m_publisher = std::make_unique<FoxglovePublisher>(
            *m_foxglove, running->router(),
            m_simulation ? m_simulation->run().world().actors() : m_rig->actors(), origin);
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
    emit sourceAboutToChange();
    stopSource();
    m_simulation = std::make_unique<SimulationSource>(std::move(run));
    m_source = m_simulation.get();
    m_options = options;
    install();
    // A first picture before the thread starts: a run loaded or reset while paused shows
    // its scene at once, not a blank viewport until Step or Run.
    m_simulation->sceneFeed()->capture(m_simulation->run().world(), SceneOverlay());
    startThread();
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
    if (m_simulation) // the paused run's own, fresher than the last it sent the GUI
        m_history.setMetrics(metrics());
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
    if (m_simulation)
        return SimRun::routerContext(m_simulation->run().world(), m_options.reactionTime);
    RouterContext context;
    context.reactionTime = m_options.reactionTime;
    for (Gripper gripper : {Gripper::Left, Gripper::Right}) {
        if (m_rig)
            context.signalNames[size_t(gripper)] = m_rig->signalNames(gripper);
    }
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
    // A rig on the same port (a reset) has to let go of it before the new one can open it.
    const bool samePort = m_rig && options.foxglove.isEmpty() &&
                          m_rig->options().foxglove.isEmpty() && options.port != 0 &&
                          options.port == m_rig->stats().port &&
                          options.address == m_rig->options().address;
    if (samePort) {
        emit sourceAboutToChange();
        stopSource();
    }

    // The socket belongs to the thread that reads it, so the new pipeline thread opens it;
    // it starts reading only once the old run has stopped and the new one is installed, and
    // the old run goes on untouched when the port cannot be had.
    auto rig = std::make_unique<LiveRig>(options, std::move(router));
    std::promise<QString> opened;
    std::future<QString> openResult = opened.get_future();
    std::promise<bool> go;
    std::thread thread(
        [this, rig = rig.get(), opened = std::move(opened), start = go.get_future()]() mutable {
            QString openError;
            const bool ok = rig->open(&openError);
            opened.set_value(openError);
            if (!ok)
                return;
            if (start.get())
                listenLoop();
            rig->close();
        });
    *error = openResult.get();
    if (!error->isEmpty()) {
        thread.join();
        if (samePort) {
            // Nothing is left to go back to: the simulation comes back instead.
            QString simError;
            start(m_options, &simError);
        }
        return false;
    }
    emit sourceAboutToChange();
    stopSource();
    m_rig = std::move(rig);
    m_source = m_rig.get();
    m_options.router = options.router;
    m_options.overrides = options.overrides;
    install();
    m_quit = false;
    m_thread = std::move(thread);
    go.set_value(true);
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
    m_simulation.reset();
    m_rig.reset();
}

RunSource *Engine::streamingSource() const
{
    if (m_simulation)
        return m_simulation.get();
    return m_rig.get();
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
    m_simTime = m_simulation ? m_simulation->run().time() : 0.0;
    m_realtimeFactor = 0.0;
    m_nextMetrics = 0.0;
    m_pendingSteps = 0;

    m_feed.discard(); // whatever the old run left in the feed is not the new run's
    m_history.start(liveDevicesOf(pipeline().router(), m_source->hands()), shownThresholds(),
                    pipeline().router().nodeIds());
    m_sentFeed.start(deviceNames(), *m_devices);
    // A live rig has no task to count.
    m_history.setMetrics(m_simulation ? m_simulation->run().metrics() : QJsonObject());
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
    return m_simulation ? &m_simulation->driveOperator() : nullptr;
}

LiveRig::Stats Engine::liveStats() const
{
    return m_rig ? m_rig->stats() : LiveRig::Stats();
}

QString Engine::liveRejection(quint64 *count) const
{
    *count = 0;
    return m_rig ? m_rig->lastRejection(count) : QString();
}

LiveRigOptions Engine::liveOptions() const
{
    if (!m_rig)
        return LiveRigOptions();
    LiveRigOptions options = m_rig->options();
    options.port = m_rig->stats().port;
    return options;
}

QString Engine::liveUri() const
{
    return m_rig ? m_rig->uri() : QString();
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
        if (m_simulation)
            m_simulation->run().setRouter(std::move(router), m_sink);
        else
            m_rig->setRouter(std::move(router), m_sink);
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
    const bool started = m_rig ? startLive(liveOptions(), error) : start(m_options, error);
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
    if (!isLoaded() || !m_source->isStreaming() ||
        (m_simulation && m_simulation->run().isDone()) || m_running.exchange(true))
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
    if (!m_simulation || isReplaying() || isRunning())
        return;
    const int steps = int(std::lround(1.0 / StepRate / m_simulation->run().world().timestep()));
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
    driving = driving && m_simulation && !isReplaying();
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
    if (!m_simulation)
        return;
    std::lock_guard<std::mutex> lock(m_setupMutex);
    m_simulation->run().setDuration(seconds);
}

std::array<std::optional<HandCommand>, 2> Engine::handCommands()
{
    if (!m_simulation)
        return {};
    std::lock_guard<std::mutex> lock(m_setupMutex);
    return currentCommands(m_simulation->run().world());
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

void Engine::startThread()
{
    m_quit = false;
    m_thread = std::thread([this] { loop(); });
}

void Engine::stopThread()
{
    if (!m_thread.joinable())
        return;
    m_quit = true;
    m_thread.join();
}

void Engine::loop()
{
    SimRun &run = m_simulation->run();
    const double dt = run.world().timestep();
    Clock::time_point anchorWall = Clock::now();
    double anchorSim = run.time();
    int epoch = m_speedEpoch.load();
    bool wasRunning = false;
    Clock::time_point rateWall = anchorWall;
    double rateSim = anchorSim;

    while (!m_quit.load()) {
        const bool running = m_running.load();
        const Clock::time_point now = Clock::now();
        long steps = 0;
        if (running) {
            if (!wasRunning || epoch != m_speedEpoch.load()) {
                epoch = m_speedEpoch.load();
                anchorWall = now;
                anchorSim = run.time();
            }
            const double target = anchorSim + m_speed.load() * seconds(now - anchorWall);
            steps = std::lround(std::floor((target - run.time()) / dt));
            if (double(steps) * dt > MaxLag) {
                // Slower than asked: run flat out from here instead of chasing the past.
                steps = std::lround(MaxLag / dt);
                anchorWall = now;
                anchorSim = run.time() + double(steps) * dt;
            }
        } else {
            steps = m_pendingSteps.exchange(0);
        }
        wasRunning = running;

        // A run ends in a batch of steps; read under the lock, as setDuration() (a study's
        // trial, from the GUI thread) changes where it ends.
        bool done = false;
        if (steps > 0) {
            std::lock_guard<std::mutex> lock(m_setupMutex);
            // A pause or a stop-all ends a running batch at the next step, also one that
            // came while this thread waited for the lock.
            for (long k = 0; k < steps && !run.isDone() && (!running || m_running.load()); ++k)
                stepOnce();
            done = run.isDone();
        } else {
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
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
            m_realtimeFactor = running ? (run.time() - rateSim) / wall : 0.0;
            rateWall = now;
            rateSim = run.time();
        }
    }
}

void Engine::listenLoop()
{
    /** How long the thread sleeps on the socket before it looks at m_quit again (ms). */
    constexpr int WaitSlice = 5;
    const LiveRig::FrameHandler process = [this](const ContactFrame &frame, double arrival) {
        takeFrame(frame, arrival);
        m_rig->pipeline()->process(frame, m_sink);
        m_simTime.store(frame.t, std::memory_order_relaxed);
    };
    while (!m_quit.load()) {
        m_rig->wait(WaitSlice);
        // One batch a turn (LiveRig::poll), so a flood cannot keep the set-up locked.
        std::lock_guard<std::mutex> lock(m_setupMutex);
        m_rig->poll(process, !m_running.load());
        // The rig behind a replay keeps its silence for later: an audition or the replay
        // owns the devices until the replay closes.
        if (!m_runKept.load() && m_rig->endIfSilent(m_sink, process, !m_running.load())) {
            silenceDevices(m_outputs);
            m_devices->stopAll();
        }
    }
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

void Engine::stepOnce()
{
    SimRun &run = m_simulation->run();
    const bool driving = m_driving.load(std::memory_order_relaxed);
    run.setDriveOperator(driving ? &m_simulation->driveOperator() : nullptr);
    run.step(m_sink);
    const double t = run.time();
    if (driving && m_recorder && t >= m_nextInput) {
        m_nextInput = t + InputPeriod;
        recordInput(t);
    }
    if (m_recorder)
        run.recordSceneState(*m_recorder);
    m_simTime.store(t, std::memory_order_relaxed);
    SceneFeed &sceneFeed = *m_simulation->sceneFeed();
    if (sceneFeed.wantsCapture()) {
        const Perception &perception = run.perception();
        const Feeling left = perception.feeling(Gripper::Left);
        const Feeling right = perception.feeling(Gripper::Right);
        sceneFeed.capture(run.world(), {left.shownConfirmation, left.shownWarning,
                                        right.shownConfirmation, right.shownWarning});
    }
    if (t >= m_nextMetrics) {
        m_nextMetrics = t + MetricsPeriod;
        const QJsonObject metrics = run.metrics();
        const int generation = m_generation;
        QMetaObject::invokeMethod(
            this,
            [this, metrics, generation] {
                if (generation == m_generation)
                    m_history.setMetrics(metrics);
            },
            Qt::QueuedConnection);
    }
}

QJsonObject Engine::metrics()
{
    if (!m_simulation || isReplaying())
        return QJsonObject();
    std::lock_guard<std::mutex> lock(m_setupMutex);
    return m_simulation->run().metrics();
}

bool Engine::startRecording(const QString &path, const QString &notes, QString *error,
                            const QMap<QString, QString> &tags)
{
    if (!isLoaded() || !m_source->isStreaming()) {
        *error = tr("nothing runs that could be recorded");
        return false;
    }
    stopRecording();
    SessionInfo info;
    if (m_rig) {
        // Like `semhap listen --session`: no scene, operator or seed, the rig's address.
        info.routerSource = m_options.router;
        info.overrides = m_options.overrides;
        info.routerContext.reactionTime = m_options.reactionTime;
        if (m_rig->options().foxglove.isEmpty()) {
            info.extra.insert(QStringLiteral("udp"), liveUri().mid(4));
        } else {
            info.extra.insert(QStringLiteral("foxglove"), liveUri());
            info.extra.insert(QStringLiteral("topics"), m_rig->options().topics);
        }
    } else {
        info = m_simulation->run().sessionInfo();
        // Applied from the editor: the graph itself is in the session, its name is not.
        info.routerSource = m_options.router;
        info.overrides = m_options.overrides;
    }
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
        recorder->setActorTable(m_simulation ? &m_simulation->run().world().actors()
                                             : &m_rig->actors());
        m_recorder = std::move(recorder);
        rewire();
        m_nextInput = 0.0;
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

void Engine::recordInput(double t)
{
    for (std::optional<HandCommand> command : currentCommands(m_simulation->run().world())) {
        if (!command)
            continue;
        command->t = t;
        m_recorder->recordHandCommand(*command);
    }
}

} // namespace semhap
