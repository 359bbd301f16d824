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
#include <functional>
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
    /** What the rig has seen since it started listening. */
    struct Stats
    {
        quint64 datagrams = 0; ///< received, good or bad (a robot's: its messages)
        quint64 frames = 0;    ///< valid frames
        quint64 rejected = 0;  ///< malformed datagrams and invalid frames
        quint64 oversize = 0;  ///< datagrams over the size limit, not parsed
        quint64 held = 0;      ///< valid frames dropped while paused
        double framesPerSecond = 0.0;
        double jitter = 0.0; ///< spread of arrival minus `t` over the last second (s)
        int port = 0;        ///< the port bound to (useful when 0 was asked for)
    };

    /** Gets each frame to process and its arrival time. */
    using FrameHandler = std::function<void(const ContactFrame &frame, double arrival)>;

    LiveRig(const LiveRigOptions &options, std::unique_ptr<Router> router);
    ~LiveRig() override;

    Kind kind() const override { return Kind::Rig; }
    Pipeline *pipeline() override { return m_pipeline.get(); }

    const LiveRigOptions &options() const { return m_options; }
    /** Swaps the router; the old one's active messages end now, their End events to `sink`. */
    void setRouter(std::unique_ptr<Router> router, PipelineSink &sink);

    // Pipeline thread.
    /** Opens the socket (or loads the topic map and connects); false with a one-line `error`. */
    bool open(QString *error);
    /**
     * Blocks until a datagram is pending or `msecs` passed; true when one is pending. A
     * robot's messages are taken meanwhile, and its frames wait for poll().
     */
    bool wait(int msecs);
    /**
     * Reads a batch of pending datagrams and hands each valid frame to `process`, or, when
     * `hold` is set, drops it and counts it as held.
     */
    void poll(const FrameHandler &process, bool hold);
    /**
     * When the sender has been silent for UdpFrameSource's silence (once per silence), ends
     * every active message, its End events to `sink`, and returns true: the caller stops
     * the bands. A robot's frames that waited for the silent topics are made and handed to
     * `process` (as poll() does, `hold` included) before.
     */
    bool endIfSilent(PipelineSink &sink, const FrameHandler &process, bool hold);
    /** The actors the frames named (sessions record their names). */
    const ActorTable &actors() const;
    void close();

    // Any thread.
    Stats stats() const;
    /** The latest rejection (`udp:PORT: reason`) and how many there were so far. */
    QString lastRejection(quint64 *count = nullptr) const;
    /** The address the user reaches the rig on, `udp:ADDRESS:PORT`, or the robot's URL. */
    QString uri() const;
    /**
     * The named signals the gripper's valid frames carried since the rig started listening,
     * in the order first seen: what the router editor's signal picker offers.
     */
    QStringList signalNames(Gripper gripper) const;

private:
    void publish(double now);
    /** Counters, windows and signals from zero, on `port` (the UDP port, or the robot's). */
    void startCounting(int port);
    /** Counts a frame into the rate and jitter, and processes it, or holds it. */
    void take(const ContactFrame &frame, double arrival, const FrameHandler &process, bool hold);
    void reject(const QString &message);
    /** Notes the signals of a valid frame that no earlier frame of its gripper carried. */
    void noteSignals(const ContactFrame &frame);

    LiveRigOptions m_options;
    std::unique_ptr<Pipeline> m_pipeline;
    std::unique_ptr<UdpFrameSource> m_source;
    std::unique_ptr<FoxgloveSource> m_robot;
    /** The robot's frames taken in wait(), for poll(). */
    std::vector<std::pair<ContactFrame, double>> m_taken;
    bool m_fatalTold = false;

    // Pipeline thread: the rate and jitter windows.
    QElapsedTimer m_clock;
    quint64 m_held = 0;
    double m_windowStart = 0.0;
    quint64 m_windowFrames = 0;
    double m_delayMin = 0.0;
    double m_delayMax = 0.0;

    mutable std::mutex m_statsMutex;
    Stats m_stats;
    QString m_lastRejection;
    quint64 m_rejections = 0;
    /**
     * Per gripper, the signalNames() ids seen: appended under m_statsMutex on the pipeline
     * thread (rarely: only a new name), read under it on any. At most NameTable::Capacity.
     */
    std::array<std::vector<int>, 2> m_seenSignals;
};

} // namespace semhap
