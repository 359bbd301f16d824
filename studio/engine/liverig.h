// SPDX-License-Identifier: MIT
#pragma once

#include "contactframe.h"
#include "pipeline.h"
#include "runsource.h"
#include "udpframesource.h"

#include <QElapsedTimer>
#include <QString>
#include <QStringList>
#include <QUrl>

#include <array>
#include <atomic>
#include <memory>
#include <mutex>
#include <vector>

namespace semhap {

class ActorTable;
class FoxgloveSource;
class UdpFrameSource;

/** Where the studio listens for a live rig and what it routes the rig's frames with. */
struct LiveRigOptions
{
    /**
     * A robot's Foxglove WebSocket server to follow (ws://HOST:PORT, as foxglove_bridge
     * serves it) through the topic map `topics`; empty: contact frames over UDP on
     * `address`:`port`.
     */
    QUrl foxglove;
    QString topics;
    /** Localhost unless the user opens it to the network (`0.0.0.0`). */
    QString address = QStringLiteral("127.0.0.1");
    /** 9870 is the pose input's: the rig gets the next port. 0: any free port. */
    int port = 9871;
    QString router = QStringLiteral("C3");
    QStringList overrides; ///< NODE.PARAM=VALUE
    /** Seconds without a valid frame after which every message ends and the bands stop. */
    double silence = UdpFrameSource::DefaultSilence;
};

/**
 * The studio's live-rig source: contact frames another program sends over UDP, or a robot's
 * topics followed over the Foxglove WebSocket protocol through a topic map (FoxgloveSource),
 * run through a pipeline the way the simulation's frames are. The socket is opened, read
 * and closed on the engine's pipeline thread; the counters can be read from any thread.
 *
 * The sender's `t` drives the detectors. Link delay is the arrival time (steady clock since
 * the socket opened) minus `t`; its offset is arbitrary, but its spread over a second is the
 * link's jitter, which is what the user wants to see.
 */
class LiveRig : public RunSource
{
public:
    LiveRig(const LiveRigOptions &options, std::unique_ptr<Router> router);
    ~LiveRig() override;

    Pipeline *pipeline() override { return m_pipeline.get(); }
    const LiveRigOptions &options() const { return m_options; }
    /** `udp:ADDRESS:PORT` (the port bound), or the robot's URL. */
    QString address() const override;
    std::optional<LinkStats> linkStats() const override;
    QString sceneNote() const override;

    // Pipeline thread.
    /** Opens the socket (or loads the topic map and connects); false with a one-line `error`. */
    bool start(QString *error) override;
    /**
     * Blocks until a datagram is pending or `msecs` passed. A robot's messages are taken
     * meanwhile, and its frames wait for advance().
     */
    void wait(int msecs) override;
    /**
     * Routes a batch of pending datagrams' valid frames (one batch, so a flood cannot keep
     * the engine's set-up locked), or holds them while not running. When the sender has
     * been silent for UdpFrameSource's silence (once per silence, unless the budget holds
     * silence), ends every active message and says Silent: the caller stops the bands. A
     * robot's frames that waited for the silent topics are made and routed before.
     */
    Outcome advance(Sink &sink, const Budget &budget) override;
    void shutdown() override;
    /** The latest frame's `t`. */
    double time() const override { return m_time; }
    void setRouter(std::unique_ptr<Router> router, RunSink &sink) override;
    /** The reaction time and the signals its frames carried so far (offered, not checked). */
    RouterContext routerContext(double reactionTime) const override;
    const ActorTable *actors() const override;
    /** Like `semhap listen --session`'s: no scene, operator or seed; the rig's address. */
    SessionInfo sessionInfo() const override;
    /** Another rig on the port this one asks for (a reset) has to let go of it first. */
    bool conflictsWith(const RunSource &running) const override;

    // Any thread.
    /**
     * The named signals the gripper's valid frames carried since the rig started listening,
     * in the order first seen: what the router editor's signal picker offers.
     */
    QStringList signalNames(Gripper gripper) const;

private:
    void publish(double now);
    /** Counters, windows and signals from zero, on `port` (the UDP port, or the robot's). */
    void startCounting(int port);
    /** Counts a frame into the rate and jitter, and routes it into `sink`, or holds it. */
    void take(const ContactFrame &frame, double arrival, Sink &sink, bool hold);
    void reject(const QString &message);
    /** Notes the signals of a valid frame that no earlier frame of its gripper carried. */
    void noteSignals(const ContactFrame &frame);

    LiveRigOptions m_options;
    std::unique_ptr<Pipeline> m_pipeline;
    std::unique_ptr<UdpFrameSource> m_source;
    std::unique_ptr<FoxgloveSource> m_robot;
    /** The robot's frames taken in wait(), for advance(). */
    std::vector<std::pair<ContactFrame, double>> m_taken;
    bool m_fatalTold = false;
    double m_time = 0.0;

    // Pipeline thread: the rate and jitter windows.
    QElapsedTimer m_clock;
    quint64 m_held = 0;
    double m_windowStart = 0.0;
    quint64 m_windowFrames = 0;
    double m_delayMin = 0.0;
    double m_delayMax = 0.0;

    mutable std::mutex m_statsMutex;
    LinkStats m_stats;
    /**
     * Per gripper, the signalNames() ids seen: appended under m_statsMutex on the pipeline
     * thread (rarely: only a new name), read under it on any. At most NameTable::Capacity.
     */
    std::array<std::vector<int>, 2> m_seenSignals;
};

} // namespace semhap
