// SPDX-License-Identifier: MIT
#pragma once

#include "handcommand.h"
#include "liverig.h"
#include "runfeed.h"
#include "runhistory.h"
#include "simrun.h"
#include "sinklist.h"

#include <QObject>
#include <QTimer>

#include <atomic>
#include <memory>
#include <mutex>
#include <thread>

namespace semhap {

class DeviceManager;
class DeviceOutputSink;
class ManualOperator;
class SceneFeed;
class SessionWriter;

/**
 * The studio's running session: a SimRun stepped on its own pipeline thread at a chosen
 * speed of real time — or a live rig's frames received on that thread as they come — its
 * streams handed to the GUI through a RunFeed and drained into the RunHistory at display
 * rate, its device frames sent to the DeviceManager's bound transports. The pipeline never
 * waits for the GUI; the GUI waits for the pipeline only to change the run's set-up (load,
 * reset, rebind), and then only until the current batch of ticks ends.
 */
class SimEngine : public QObject
{
    Q_OBJECT

public:
    explicit SimEngine(QObject *parent = nullptr);
    ~SimEngine() override;

    /**
     * Stops the current run and loads `options` (scene, router, seed, operator); devices of
     * the router without a binding are bound to `virtual:NAME`. Paused afterwards. False
     * with a one-line `error`, keeping the previous run.
     */
    bool load(const RunOptions &options, QString *error);
    /**
     * Stops the current run and listens for a live rig's contact frames instead (File →
     * Listen for a live rig): they go through detectors, router and devices like the
     * simulation's, with plots, log and recording. There is no scene; world() is null.
     * Paused afterwards (paused, the frames are received and dropped). False with a one-line
     * `error` (the port is taken, the router does not load), keeping the previous run.
     */
    bool listen(const LiveRigOptions &options, QString *error);
    /** The source is a live rig, not the simulation. */
    bool isLive() const { return m_rig != nullptr; }
    /** The live rig's counters (zero when not live). */
    LiveRig::Stats liveStats() const;
    /** The live rig's latest rejected datagram and how many so far (empty when not live). */
    QString liveRejection(quint64 *count) const;
    /** The live rig's options, with the port it got when any was asked for. */
    LiveRigOptions liveOptions() const;
    /** `udp:ADDRESS:PORT` of the live rig; empty when not live. */
    QString liveUri() const;
    /**
     * Swaps `graph` in as the running router (the router editor's Apply) without stopping
     * the run: compiled here on the caller's thread, swapped in at a tick boundary. The old
     * router's messages end, its devices are sent to zero; the new router's devices keep
     * matching bindings (else `virtual:NAME`); the history keeps what it has seen. False
     * with the compiler's `error`, keeping the router that runs.
     */
    bool setRouter(const RouterGraph &graph, QString *error);
    /** The graph of the router that runs (valid while loaded). */
    const RouterGraph &routerGraph() const;

    /**
     * Loads the current options again from the start, with the router last applied; a live
     * rig starts listening afresh (detectors and history cleared).
     */
    bool reset(QString *error);
    /** The simulation's options; while live, `router` and `overrides` are the rig's. */
    const RunOptions &options() const { return m_options; }
    /** What routers are compiled for, the simulation's and the live rig's alike. */
    RouterContext routerContext() const { return RouterContext{m_options.reactionTime}; }
    bool isLoaded() const { return m_run != nullptr || m_rig != nullptr; }

    void run();
    void pause();
    bool isRunning() const { return m_running.load(); }
    /** While paused: one display frame's worth of steps (1/60 s of simulated time); not live. */
    void step();

    /** Simulated seconds per real second (1 = real time). */
    double speed() const { return m_speed.load(); }
    void setSpeed(double speed);

    /** Hands the grippers to the user (ManualOperator) or back to the run's own operator. */
    void setManual(bool manual);
    bool isManual() const { return m_manual.load(); }
    /** The user's pose-and-grip input; valid while loaded. */
    ManualOperator *manualOperator() const { return m_manualOperator.get(); }
    /** Each hand's target and grip now, read between two ticks: where a takeover starts. */
    std::array<HandCommand, 2> handCommands();

    /** Binds a router device name to a transport at a tick boundary. */
    bool bindDevice(const QString &name, const QString &uri, QString *error);
    DeviceManager &devices() { return *m_devices; }
    /** Sends zero to every device now, from any thread; works even while the run is busy. */
    void stopAll();

    RunHistory &history() { return m_history; }
    /**
     * Pauses the run and stops feeding the history, which then shows something else (a
     * replay); loading or resetting the run feeds it again.
     */
    void detachHistory();
    /** The scene snapshots the viewport draws; null until loaded. */
    SceneFeed *sceneFeed() const { return m_sceneFeed.get(); }
    /** The loaded world (read it on the GUI thread only while paused); null while live. */
    const World *world() const;

    /** Simulated seconds, or the live rig's latest `t`. */
    double simTime() const { return m_simTime.load(); }
    /** Simulated seconds per wall second over the last second of running. */
    double realtimeFactor() const { return m_realtimeFactor.load(); }
    /** Values the feed dropped because the GUI fell behind. */
    quint64 dropped() const { return m_feed.dropped(); }

    /**
     * Records the running session from the next tick into a new session database at `path`
     * (never overwritten): contact frames, events, device frames and the user's input while
     * driving. Stops by itself on load, reset and a router swap (one router per session).
     * False with a one-line `error`.
     */
    bool startRecording(const QString &path, const QString &notes, QString *error);
    /** Closes the recording's database (its end time stamped); a no-op when not recording. */
    void stopRecording();
    bool isRecording() const { return m_recorder != nullptr; }
    /** The file being recorded to; empty when not recording. */
    QString recordingPath() const;
    /** Values the recording dropped because the disk fell behind. */
    quint64 recordingDropped() const;
    /**
     * A file name for a new recording: `NAME-yyyyMMdd-HHmmss.db` for the user's session
     * name (characters a file name cannot hold become `_`), else named after the scene (or
     * `live`) and the router.
     */
    QString recordingFileName(const QString &name = QString()) const;

signals:
    void loaded();
    void runningChanged(bool running);
    void manualChanged(bool manual);
    /** The run reached its duration. */
    void finished();
    void speedChanged(double speed);
    /** setRouter() swapped the router (options().router names it). */
    void routerChanged();
    /** Recording started or stopped (also when a load or router swap ended it). */
    void recordingChanged(bool recording);

private:
    /** Routes one step's streams: contact frames to the feed, the rest to the devices. */
    class StepSink : public RunSink
    {
    public:
        explicit StepSink(SimEngine &engine) : m_engine(engine) {}
        void onContactFrame(const ContactFrame &frame) override;
        void onEvent(const SemanticEvent &event) override;
        void onDeviceFrame(const DeviceFrame &frame) override;
        void onNodeActivity(const NodeActivity &activity) override;

    private:
        SimEngine &m_engine;
    };

    void bindRouterDevices(const Player &player, QString *error);
    /** The hands the loaded scene has; both for a live rig, which may send either. */
    Hands hands() const;
    std::array<GripperThresholds, 2> shownThresholds();
    Pipeline &pipeline();
    /** load() without the signal. */
    bool start(const RunOptions &options, QString *error);
    /** listen() without the signal. */
    bool startLive(const LiveRigOptions &options, QString *error);
    /** Ends the old run before a new one is installed (both are stopped by then). */
    void stopSource();
    /** Binds devices, history and metrics to the newly installed run or rig. */
    void install();
    void stopThread();
    void startThread();
    void loop();
    void listenLoop();
    /** Sends every device of the running router its idle values, through the readouts. */
    void silenceDevices();
    /** Rebuilds m_outputs after the recorder or the device output changed (setup lock held). */
    void rewire();
    void stepOnce();
    void drain();
    void recordInput(double t);

    RunOptions m_options;
    /** The graph setRouter() applied since the last load: what reset() runs again. */
    std::unique_ptr<RouterGraph> m_appliedGraph;
    std::unique_ptr<DeviceManager> m_devices;
    std::unique_ptr<SimRun> m_run;  ///< the simulation, or
    std::unique_ptr<LiveRig> m_rig; ///< the live rig
    std::unique_ptr<ManualOperator> m_manualOperator;
    std::unique_ptr<SceneFeed> m_sceneFeed;
    std::unique_ptr<DeviceOutputSink> m_output;
    RunFeed m_feed;
    /** Written on the pipeline thread under m_setupMutex; swapped on the GUI thread. */
    std::unique_ptr<SessionWriter> m_recorder;
    /** Where the pipeline's output goes: the recorder, the bands, the feed (rewire()). */
    SinkList m_outputs;
    double m_nextInput = 0.0; ///< pipeline thread: when the user's input is recorded next
    StepSink m_sink{*this};
    RunHistory m_history;
    QTimer m_drainTimer;
    std::thread m_thread;
    std::mutex m_setupMutex; ///< held by the pipeline thread per batch of ticks
    std::atomic<bool> m_quit{false};
    std::atomic<bool> m_running{false};
    bool m_historyAttached = true; ///< GUI thread: the feed goes to the history
    std::atomic<bool> m_manual{false};
    std::atomic<int> m_speedEpoch{0}; ///< bumped on each speed change: the pacing restarts
    int m_generation = 0;             ///< bumped on each load: late metrics are dropped
    double m_nextMetrics = 0.0;       ///< pipeline thread: when metrics go out next
    std::atomic<int> m_pendingSteps{0};
    std::atomic<double> m_speed{1.0};
    std::atomic<double> m_simTime{0.0};
    std::atomic<double> m_realtimeFactor{0.0};
};

} // namespace semhap
