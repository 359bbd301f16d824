// SPDX-License-Identifier: MIT
#include "sessionreplay.h"

#include "inputfile.h"
#include "pipeline.h"
#include "router.h"
#include "routergraph.h"
#include "scenefeed.h"
#include "sessionreader.h"
#include "world.h"

#include <QFileInfo>

#include <algorithm>

namespace semhap {

namespace {

/** Collects a re-routing's streams. */
class Collector : public PipelineSink
{
public:
    void onEvent(const SemanticEvent &event) override { events.push_back(event); }
    void onDeviceFrame(const DeviceFrame &frame) override { deviceFrames.push_back(frame); }
    void onNodeActivity(const NodeActivity &change) override { activity.push_back(change); }

    std::vector<SemanticEvent> events;
    std::vector<DeviceFrame> deviceFrames;
    std::vector<NodeActivity> activity;
};

/** Runs `router` over `frames`, collecting what it sends. */
Collector run(std::unique_ptr<Router> router, const std::vector<ContactFrame> &frames)
{
    Pipeline pipeline(std::move(router));
    Collector collector;
    for (const ContactFrame &frame : frames)
        pipeline.process(frame, collector);
    pipeline.flush(collector);
    return collector;
}

/** Appends the values of `values` with `from < t <= to` (sorted by t) to `history`. */
template<typename T>
void appendWindow(const std::vector<T> &values, double from, double to, RunHistory &history)
{
    const auto byTime = [](double t, const T &value) { return t < value.t; };
    auto it = std::upper_bound(values.begin(), values.end(), from, byTime);
    const auto end = std::upper_bound(it, values.end(), to, byTime);
    for (; it != end; ++it)
        history.append(*it);
}

} // namespace

SessionReplay::SessionReplay(RunHistory &history, QObject *parent)
    : QObject(parent), m_history(history)
{}

SessionReplay::~SessionReplay() = default;

bool SessionReplay::open(const QString &path, QString *error)
{
    std::unique_ptr<SessionReader> reader = SessionReader::open(path, error);
    if (!reader)
        return false;
    std::vector<ContactFrame> frames;
    Streams recorded;
    bool read = reader->readContactFrames(
        [&](const ContactFrame &frame, double) {
            frames.push_back(frame);
            return true;
        },
        error);
    read = read && reader->readEvents(
                       [&](const SemanticEvent &event) {
                           recorded.events.push_back(event);
                           return true;
                       },
                       error);
    read = read && reader->readDeviceFrames(
                       [&](const DeviceFrame &frame) {
                           recorded.deviceFrames.push_back(frame);
                           return true;
                       },
                       error);
    if (!read)
        return false;

    // The recorded router names the devices' models and the detectors' thresholds.
    RouterGraph graph;
    LoadError loadError;
    std::unique_ptr<Router> router;
    if (reader->routerGraph(&graph, &loadError))
        router = Router::compile(graph, &loadError, reader->info().routerContext);
    const QString &source = reader->info().routerSource;
    const bool edited =
        router && RouterPresets::names().contains(source) && !routesAs(*router, source);
    // The hands that recorded frames; the router's detectors of another never fired.
    Hands hands{false, false};
    for (const ContactFrame &frame : frames)
        hands[size_t(frame.gripper)] = true;
    for (int d = 0; d < reader->deviceNames().size(); ++d) {
        const QString &name = reader->deviceNames().at(d);
        const int index = router ? router->player().deviceIndex(name) : -1;
        recorded.devices.push_back(
            {name, index >= 0 ? router->player().deviceModel(index).name() : QString(),
             reader->channelNames(d), index >= 0 && isIdleDevice(*router, index, hands)});
    }
    if (router) {
        recorded.thresholds = thresholdsOf(*router, hands);
        // What each node passed on is not recorded; the recorded router, run again over the
        // recorded frames, tells it (a router is deterministic in its frames).
        recorded.activity = run(std::move(router), frames).activity;
    }
    recorded.nodeIds = reader->nodeNames();

    m_path = reader->path();
    m_frames = std::move(frames);
    m_hands = hands;
    m_recorded = std::move(recorded);
    m_start = reader->startTime();
    m_end = reader->endTime();
    m_shown = m_recorded;
    m_rerouted = false;
    m_recordedEdited = edited;
    m_reader = std::move(reader);
    return true;
}

void SessionReplay::begin()
{
    loadScene();
    refill(m_start);
    emit opened();
    emit timeChanged(m_time);
}

qint64 SessionReplay::skippedRows() const
{
    return m_reader ? m_reader->rejectedRows() : 0;
}

void SessionReplay::close()
{
    if (!isOpen())
        return;
    m_path.clear();
    m_frames.clear();
    m_recorded = Streams();
    m_shown = Streams();
    m_sceneFeed.reset();
    m_world.reset();
    m_reader.reset();
    emit closed();
}

void SessionReplay::seek(double t)
{
    if (!isOpen())
        return;
    t = std::clamp(t, m_start, m_end);
    if (t == m_time)
        return;
    if (t > m_time) {
        appendUpTo(m_time, t);
        m_history.commit();
        m_time = t;
        showScene(t);
    } else {
        refill(t);
    }
    emit timeChanged(m_time);
}

bool SessionReplay::reroute(const RouterGraph &graph, QString *error)
{
    // Rerouted for the person who recorded it.
    LoadError loadError;
    std::unique_ptr<Router> router =
        Router::compile(graph, &loadError, m_reader->info().routerContext);
    if (!router) {
        *error = loadError.toString();
        return false;
    }
    // An untitled graph is named, not compared: there is nothing it could be an edit of.
    const bool edited = !graph.file.isEmpty() && !routesAs(*router, graph.file);
    Streams streams;
    streams.devices = liveDevicesOf(*router, m_hands);
    streams.nodeIds = router->nodeIds();
    streams.thresholds = thresholdsOf(*router, m_hands);
    Collector collector = run(std::move(router), m_frames);
    streams.events = std::move(collector.events);
    streams.deviceFrames = std::move(collector.deviceFrames);
    streams.activity = std::move(collector.activity);
    m_shown = std::move(streams);
    m_rerouted = true;
    m_reroutedWith = graph.file.isEmpty() ? graph.name : graph.file;
    m_reroutedEdited = edited;
    refill(m_time);
    emit streamsChanged();
    return true;
}

QString SessionReplay::routerSource() const
{
    if (m_rerouted)
        return m_reroutedWith;
    const SessionInfo &recorded = info();
    if (!recorded.routerSource.isEmpty())
        return recorded.routerSource;
    return recorded.router.value(QLatin1String("name")).toString();
}

QString SessionReplay::routerName() const
{
    const QString source = routerSource();
    const QString name =
        InputFile::namesFile(source) ? QFileInfo(source).completeBaseName() : source;
    return isRouterEdited() ? name + QLatin1Char('*') : name;
}

const SessionInfo &SessionReplay::info() const
{
    static const SessionInfo none;
    return m_reader ? m_reader->info() : none;
}

void SessionReplay::showRecorded()
{
    m_shown = m_recorded;
    m_rerouted = false;
    refill(m_time);
    emit streamsChanged();
}

void SessionReplay::refill(double t)
{
    m_history.start(m_shown.devices, m_shown.thresholds, m_shown.nodeIds);
    m_time = t;
    appendUpTo(t - m_history.keepSeconds(), t);
    m_history.commit();
    showScene(t);
}

void SessionReplay::loadScene()
{
    m_sceneFeed.reset();
    m_world.reset();
    m_sceneTime = qQNaN();
    const SessionInfo &info = m_reader->info();
    if (m_reader->sceneStateCount() == 0) {
        const bool imported = info.source == QLatin1String("import");
        m_sceneNote = !info.scene.isEmpty() ? tr("Replay: no scene state recorded")
                      : imported            ? tr("Replay: a robot's recording has no scene")
                                            : tr("Replay: a live rig's session has no scene");
        return;
    }
    SceneOptions options;
    bool counted = false;
    const int cubes = info.extra.value(QStringLiteral("cubes")).toInt(&counted);
    if (counted)
        options.cubes = cubes;
    options.gripper = info.extra.value(QStringLiteral("gripper"));
    QString error;
    std::unique_ptr<World> world = World::load(info.scene, options, &error);
    SceneState first;
    if (world && m_reader->readSceneState(m_start, &first, &error) &&
        int(first.pose.size()) != world->sceneStateSize())
        error = tr("its scene states do not fit scene %1").arg(info.scene);
    if (!world || !error.isEmpty()) {
        m_sceneNote = tr("Replay: the scene cannot be shown (%1)").arg(error);
        return;
    }
    m_world = std::move(world);
    m_sceneFeed = std::make_unique<SceneFeed>(*m_world);
    m_sceneNote.clear();
}

void SessionReplay::showScene(double t)
{
    if (!m_world)
        return;
    SceneState state;
    QString error;
    if (!m_reader->readSceneState(t, &state, &error) || state.t == m_sceneTime)
        return;
    m_sceneTime = state.t;
    // The first state was checked to fit when the scene loaded; a row that does not is
    // skipped, the picture stays.
    if (!m_world->setSceneState(state.pose))
        return;
    const auto &o = state.overlay;
    m_sceneFeed->capture(*m_world, {o[0], o[1], o[2], o[3]});
}

void SessionReplay::appendUpTo(double from, double to)
{
    appendWindow(m_frames, from, to, m_history);
    appendWindow(m_shown.events, from, to, m_history);
    appendWindow(m_shown.deviceFrames, from, to, m_history);
    appendWindow(m_shown.activity, from, to, m_history);
}

} // namespace semhap
