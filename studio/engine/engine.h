// SPDX-License-Identifier: MIT
#pragma once

#include "driveoperator.h"
#include "foxgloveserver.h"
#include "liverig.h"
#include "runfeed.h"
#include "runhistory.h"
#include "sentfeed.h"
#include "sessionreplay.h"
#include "simrun.h"
#include "sinklist.h"

#include <QObject>
#include <QTimer>

#include <algorithm>
#include <atomic>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

namespace semhap {

class DeviceManager;
class DeviceOutputSink;
class FoxglovePublisher;
class SessionWriter;

/**
 * The studio's running session, without widgets: one RunSource at a time — a simulation
 * stepped on the pipeline thread at a chosen speed of real time, a live rig's frames
 * received on that thread as they come, or a recorded session scrubbed from the GUI — its
 * streams in the RunHistory every panel reads, its device frames sent to the DeviceManager's
 * bound transports, and what those sent (SentFeed) in the history too. The pipeline never
 * waits for the GUI; the GUI waits for the pipeline only to change the run's set-up (load,
 * reset, rebind) or to pause, and then only until the current batch of ticks ends.
 */
class Engine : public QObject
{
    Q_OBJECT

public:
    explicit Engine(QObject *parent = nullptr);
    ~Engine() override;

    /**
     * Stops the current run and loads `options` (scene, router, seed, operator); devices of
     * the router without a binding are bound to `virtual:NAME`. Paused afterwards. False
     * with a one-line `error`, keeping the previous run.
     */
    bool load(const RunOptions &options, QString *error);
    /**
     * Opens the recorded session at `path` as the source (File → Open session): the
     * history shows it from its start, the replay() is scrubbed from the GUI, setRouter()
     * re-routes it. The run that was there is kept behind it, paused as it was — its
     * simulation or rig, router, bindings, driving and history — with its recording ended
     * and its devices sent to rest; closeReplay() brings it back, reset() starts it again.
     * False with a one-line `error`, keeping what runs.
     */
    bool openReplay(const QString &path, QString *error);
    /**
     * Closes the replay and brings back the run it replaced where it was: the same time,
     * world, driving and history (plots and log), paused. With no run behind it (a replay
     * opened first), loads the options from the start. False with a one-line `error`.
     */
    bool closeReplay(QString *error);
    /**
     * Stops the current run and listens for a live rig's contact frames instead (File →
     * Listen for a live rig): they go through detectors, router and devices like the
     * simulation's, with plots, log and recording. There is no scene; world() is null.
     * Paused afterwards (paused, the frames are received and dropped). False with a one-line
     * `error` (the port is taken, the router does not load), keeping the previous run.
     */
    bool listen(const LiveRigOptions &options, QString *error);
    /**
     * Runs `source` in place of what runs (load() and listen() come here with theirs): it is
     * opened on a new pipeline thread and, once open, installed like a simulation — router
     * devices bound, history started — paused. `restart` makes it again from its start for
     * reset(). False with the source's one-line `error`, keeping what runs (unless the source
     * conflicted with it: then the options() load again).
     */
    bool startSource(std::unique_ptr<RunSource> source, std::function<bool(QString *)> restart,
                     QString *error);
    /** What runs now; null before the first load. */
    RunSource *source() const { return m_source; }
    /**
     * The simulation or live rig: the source, or what a replay keeps behind it (the run to
     * come back to). Null when there is none.
     */
    RunSource *streamingSource() const;
    /** The source streams frames that arrive from outside, at their own pace (a live rig). */
    bool isLive() const { return m_source && m_source->isStreaming() && !m_source->isPaced(); }
    /** The source is a recorded session. */
    bool isReplaying() const { return m_source == &m_replay; }
    /** The recorded session, scrubbed by the replay bar (open while isReplaying()). */
    SessionReplay &replay() { return m_replay; }
    /** The streaming source's link counters (zero when it has no link). */
    RunSource::LinkStats liveStats() const;
    /** The streaming source is the live rig listen() started (the one a replay keeps, too). */
    bool isListening() const { return m_live.has_value(); }
    /** The live rig's options, with the port it got when any was asked for (listen()). */
    LiveRigOptions liveOptions() const;
    /** Where the streaming source's frames come from (`udp:ADDRESS:PORT`); empty when it makes
     * them. */
    QString liveUri() const;
    /**
     * Swaps `graph` in as the running router (the router editor's Apply) without stopping
     * the run: compiled here on the caller's thread, swapped in at a tick boundary. The old
     * router's messages end, its devices are sent to zero; the new router's devices keep
     * matching bindings (else `virtual:NAME`); the history keeps what it has seen. A replay
     * is re-routed instead (SessionReplay::reroute). False with the compiler's `error`,
     * keeping the router that runs.
     */
    bool setRouter(const RouterGraph &graph, QString *error);
    /** The graph of the streamingSource()'s router (valid while there is one). */
    const RouterGraph &routerGraph() const;
    /**
     * A user pattern file was renamed (the designer moved it): an applied router's nodes that
     * play it name it where it is now, so reset() and the saved workspace still load.
     */
    void followRenamedPattern(const QString &from, const QString &to);
    /**
     * The preset or file the router shown is named after: options().router, or during a
     * replay the one its events come from (SessionReplay::routerSource).
     */
    QString routerSource() const;
    /**
     * Whether the streamingSource()'s router routes differently from the preset or file
     * options().router names (routesAs()): an edit applied from the editor.
     */
    bool isRunRouterEdited() const;
    /**
     * Whether the router shown routes differently from the one routerSource() names: the
     * run's edit, or during a replay its recorded or re-routing router's (`C3*` in the
     * toolbar).
     */
    bool isRouterEdited() const;

    /**
     * Loads the current options again from the start, with the router last applied; a live
     * rig starts listening afresh (detectors and history cleared); a replay closes and the
     * simulation or rig it replaced starts again from the start.
     */
    bool reset(QString *error);
    /**
     * Lets the loaded simulation run `seconds` from its start (a study's trial) without
     * changing options(): the next load or reset runs options().duration again.
     */
    void setDuration(double seconds);
    /** The simulation's options; while live, `router` and `overrides` are the rig's. */
    const RunOptions &options() const { return m_options; }
    /**
     * What routers are compiled for: the reaction time and, for the simulation, the signals
     * its scene declares (a signal node naming another is refused); for a live rig, the
     * signals its frames carried so far (offered, not checked); during a replay, the
     * recorded session's context.
     */
    RouterContext routerContext() const;
    bool isLoaded() const { return m_source != nullptr; }

    void run();
    /** Stops the run; no tick runs after it returns (it waits for the current batch). */
    void pause();
    bool isRunning() const { return m_running.load(); }
    /** While paused: one display frame's worth of steps (1/60 s of simulated time); a simulation
     * only. */
    void step();

    /** Simulated seconds per real second (1 = real time). */
    double speed() const { return m_speed.load(); }
    void setSpeed(double speed);

    /**
     * Hands the grippers to the user (DriveOperator) or back to the run's own operator; a
     * simulation only.
     */
    void setDriving(bool driving);
    bool isDriving() const { return m_driving.load(); }
    /** The user's pose-and-grip input; null unless a simulation is loaded. */
    DriveOperator *driveOperator() const;
    /** Each hand's target and grip now, read between two ticks: where driving starts. */
    std::array<std::optional<HandCommand>, 2> handCommands();

    /** Binds a router device name to a transport at a tick boundary. */
    bool bindDevice(const QString &name, const QString &uri, QString *error);
    DeviceManager &devices() { return *m_devices; }
    const DeviceManager &devices() const { return *m_devices; }
    /**
     * Pauses and sends every device zero now (the bands before anything waits for the
     * pipeline thread); the history, so the meters and plots, shows the rest values the
     * transports sent, at once, and the recording each device's idle values. GUI thread.
     */
    void stopAll();

    RunHistory &history() { return m_history; }
    /**
     * The simulation's task metrics now, read between two ticks: fresher than the history's,
     * which come every quarter of a simulated second. Empty for a live rig or a replay.
     */
    QJsonObject metrics();
    /** The source's scene snapshots the viewport draws; null when it has no scene. */
    SceneFeed *sceneFeed() const { return m_source ? m_source->sceneFeed() : nullptr; }
    /**
     * The source's world (a simulation's: read it on the GUI thread only while paused);
     * null when it has none.
     */
    const World *world() const { return m_source ? m_source->world() : nullptr; }

    /** Simulated seconds, the live rig's latest `t`, or the replay's time shown. */
    double simTime() const;
    /**
     * The latest time the readouts show: the run's, or an audition's drawn on past a paused
     * run. Where a new audition's frames begin (docs/studio.md, Audition). GUI thread.
     */
    double readoutTime() const { return std::max(simTime(), m_history.now()); }
    /** Simulated seconds per wall second over the last second of running. */
    double realtimeFactor() const { return m_realtimeFactor.load(); }
    /** Values the feeds dropped (or transports overwrote) because the GUI fell behind. */
    quint64 dropped() const { return m_feed.dropped() + m_sentFeed.lost(); }

    /**
     * Records the running session from the next tick into a new session database at `path`
     * (never overwritten): contact frames, events, device frames and the user's input while
     * driving. Stops by itself on load, reset and a router swap (one router per session).
     * `tags` go into the session's metadata beside the run's (a study's participant,
     * condition, phase, trial). False with a one-line `error`.
     */
    bool startRecording(const QString &path, const QString &notes, QString *error,
                        const QMap<QString, QString> &tags = {});
    /** Closes the recording's database (its end time stamped); a no-op when not recording. */
    void stopRecording();
    bool isRecording() const { return m_recorder != nullptr; }
    /** The file being recorded to; empty when not recording. */
    QString recordingPath() const;
    /** Values the recording dropped because the disk fell behind. */
    quint64 recordingDropped() const;
    /**
     * A path in `folder` for a new recording that no file has: `NAME-yyyyMMdd-HHmmss.db` for
     * the user's session name (characters a file name cannot hold become `_`), else named
     * after the scene (or `live`) and the router; `-2`, `-3`, … before `.db` when a recording
     * of that second is there already.
     */
    QString newRecordingPath(const QString &folder, const QString &name = QString()) const;

    /**
     * Serves the running session to Foxglove (File → Preferences, Publish to Foxglove): a
     * FoxgloveServer on `address`:`port` (0: any free one) publishes every contact frame,
     * event and band frame of the simulation or live rig as it runs, on the topics of an
     * MCAP export (docs/ros.md). Replaced when called again. False with a one-line `error`.
     */
    bool startPublishing(const QHostAddress &address, quint16 port, QString *error);
    /** Closes the Foxglove server, its viewers served what waited for them. */
    void stopPublishing();
    bool isPublishing() const { return m_foxglove != nullptr; }
    /** ws://ADDRESS:PORT of the Foxglove server; empty when not publishing. */
    QString publishingUrl() const;
    /** The Foxglove server's counts (zero when not publishing). */
    FoxgloveServer::Stats publishingStats() const;

signals:
    /** The source is about to be replaced or freed: let go of its world and scene feed. */
    void sourceAboutToChange();
    /** A source was loaded, listened to, opened or reset (source() says which). */
    void sourceChanged();
    void runningChanged(bool running);
    void drivingChanged(bool driving);
    /** The run reached its duration. */
    void finished();
    void speedChanged(double speed);
    /** setRouter() swapped the router (options().router names it). */
    void routerChanged();
    /** Recording started or stopped (also when a load or router swap ended it). */
    void recordingChanged(bool recording);

private:
    /** Routes a source's streams: contact frames to the feed, the rest to the outputs. */
    class StepSink : public RunSource::Sink
    {
    public:
        explicit StepSink(Engine &engine) : m_engine(engine) {}
        void onContactFrame(const ContactFrame &frame) override;
        void onReceivedFrame(const ContactFrame &frame, double arrival) override;
        void onEvent(const SemanticEvent &event) override;
        void onDeviceFrame(const DeviceFrame &frame) override;
        void onNodeActivity(const NodeActivity &activity) override;
        SessionWriter *recorder() override { return m_engine.m_recorder.get(); }

    private:
        Engine &m_engine;
    };

    void bindRouterDevices(const Player &player, QString *error);
    std::array<GripperThresholds, 2> shownThresholds();
    /** The streaming source's pipeline (a simulation's or a rig's). */
    Pipeline &pipeline();
    /** load() without the signal. */
    bool start(const RunOptions &options, QString *error);
    /** listen() without the signal. */
    bool startLive(const LiveRigOptions &options, QString *error);
    /** Stops and frees a streaming source before another is installed; a replay stays. */
    void stopStreaming();
    /** Ends whatever runs before a new source is installed. */
    void stopSource();
    /** Pauses the run a replay is about to replace and sets its history aside. */
    void keepRun();
    /** Binds devices, history and metrics to the newly installed run or rig. */
    void install();
    void stopThread();
    /** Pipeline thread: advances `source` at its pace, or as its frames come, until quit. */
    void loop(RunSource &source);
    /** Pipeline thread: the task's metrics to the GUI every MetricsPeriod of the source's time. */
    void sendMetrics(const RunSource &source);
    /** Sends every device of the running router its idle values, into `sink`. */
    void silenceDevices(PipelineSink &sink);
    /** The running router's device names, by index: what the SentFeed reads. */
    QStringList deviceNames();
    /**
     * Rebuilds m_outputs, and the publisher for the router that runs, after the recorder,
     * the device output, the router or the publishing changed (setup lock held).
     */
    void rewire();
    /**
     * Pipeline thread: a contact frame of the source, into the recording (with its arrival
     * time, NaN when simulated), the publisher and the feed.
     */
    void takeFrame(const ContactFrame &frame, double arrival);
    void drain();

    RunOptions m_options;
    /** The graph setRouter() applied since the last load: what reset() runs again. */
    std::unique_ptr<RouterGraph> m_appliedGraph;
    std::unique_ptr<DeviceManager> m_devices;
    RunHistory m_history;
    /** The streaming source: what runs, or what a replay keeps behind it. */
    std::unique_ptr<RunSource> m_run;
    /** How the streaming source is made again from its start (reset()). */
    std::function<bool(QString *)> m_restart;
    /** What listen() asked for, while its rig is the streaming source. */
    std::optional<LiveRigOptions> m_live;
    SessionReplay m_replay{m_history};
    /** m_run or &m_replay: what the windows show. */
    RunSource *m_source = nullptr;
    /** The history of the run kept behind a replay, and whether the user drove it. */
    RunHistory m_keptHistory;
    bool m_keptDriving = false;
    std::unique_ptr<DeviceOutputSink> m_output;
    RunFeed m_feed;
    SentFeed m_sentFeed; ///< GUI thread; rebound under m_setupMutex with every binding
    /** Written on the pipeline thread under m_setupMutex; swapped on the GUI thread. */
    std::unique_ptr<SessionWriter> m_recorder;
    /** Serving Foxglove: the server, and the publisher of the streaming source (rewire()). */
    std::unique_ptr<FoxgloveServer> m_foxglove;
    std::unique_ptr<FoxglovePublisher> m_publisher;
    /** Where the pipeline's output goes: the recorder, the bands, the feed, the publisher. */
    SinkList m_outputs;
    StepSink m_sink{*this};
    QTimer m_drainTimer;
    std::thread m_thread;
    std::mutex m_setupMutex; ///< held by the pipeline thread per batch of ticks
    std::atomic<bool> m_quit{false};
    std::atomic<bool> m_running{false};
    std::atomic<bool> m_driving{false};
    /** A run waits behind a replay: a rig's silence leaves the devices alone until it closes. */
    std::atomic<bool> m_runKept{false};
    std::atomic<int> m_speedEpoch{0}; ///< bumped on each speed change: the pacing restarts
    int m_generation = 0;             ///< bumped on each load: late metrics are dropped
    double m_nextMetrics = 0.0;       ///< pipeline thread: when metrics go out next
    std::atomic<int> m_pendingSteps{0};
    std::atomic<double> m_speed{1.0};
    std::atomic<double> m_simTime{0.0};
    std::atomic<double> m_realtimeFactor{0.0};
};

} // namespace semhap
