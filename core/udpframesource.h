// SPDX-License-Identifier: MIT
#pragma once

#include "actortable.h"
#include "contactframe.h"
#include "contactframeparser.h"

#include <QByteArray>
#include <QElapsedTimer>
#include <QObject>
#include <QString>

#include <functional>
#include <memory>

class QUdpSocket;

namespace semhap {

/**
 * Receives contact frames from another program over UDP — a game engine, a robot's ROS
 * node, `scripts/send-frames.py` — one frame (spec section 1) per datagram or a JSON array
 * of frames as a batch. Bad datagrams are counted and reported, never fatal; datagrams over
 * MaxDatagramSize are dropped unparsed.
 *
 * It needs no event loop: poll() reads what is pending (at most a batch, so a flood cannot
 * stall the caller) and waitForDatagrams() blocks with a timeout. Where an event loop runs
 * on the object's thread, datagramsPending() says when to poll. The socket lives on the
 * thread that called bind(); use the source from that thread only.
 */
class UdpFrameSource : public QObject
{
    Q_OBJECT

public:
    /** Larger datagrams are rejected: a batch of about 200 frames fits. */
    static constexpr qint64 MaxDatagramSize = 32 * 1024;
    /** A sender quiet this long (s) is gone: what it left active must not go on. */
    static constexpr double DefaultSilence = 0.25;

    /** What the source has seen since bind(). */
    struct Stats
    {
        quint64 datagrams = 0; ///< datagrams received, good or bad
        quint64 frames = 0;    ///< valid frames handed on
        quint64 rejected = 0;  ///< frames or datagrams refused (bad JSON, invalid frame)
        quint64 oversize = 0;  ///< datagrams over MaxDatagramSize, not parsed
    };

    /** Gets each valid frame and its arrival time (s since bind(), steady clock). */
    using FrameHandler = std::function<void(const ContactFrame &frame, double arrival)>;
    /** Gets each rejection as `udp:PORT: reason`. */
    using ErrorHandler = std::function<void(const QString &message)>;

    explicit UdpFrameSource(QObject *parent = nullptr);
    ~UdpFrameSource() override;

    /**
     * Listens on `address` (`127.0.0.1` keeps it on this machine; `0.0.0.0` opens it to the
     * network) and `port` (0: any free one, see port()). False with a one-line `error`.
     */
    bool bind(const QString &address, int port, QString *error);
    /** The port bound to. */
    int port() const;

    /** The frames' parser: its maximum gap. */
    ContactFrameParser &parser() { return m_parser; }
    /** How long without a valid frame makes the sender silent (s; default 0.25). */
    void setSilence(double seconds) { m_silence = seconds; }
    double silence() const { return m_silence; }
    /**
     * True once per silence: no valid frame for silence() since the last one. The caller
     * ends what the sender left active and stops the bands; the parser's clock starts
     * again, as the sender may come back on another.
     */
    bool fellSilent();
    /** Milliseconds until fellSilent() may turn true; -1 when silent or before any frame. */
    qint64 msecsToSilence() const;
    void setErrorHandler(ErrorHandler handler) { m_onError = std::move(handler); }

    /** Reads up to `maxDatagrams` pending datagrams; returns how many frames it handed on. */
    int poll(const FrameHandler &handler, int maxDatagrams = 512);
    /** Blocks until a datagram is pending or `msecs` passed; true when one is pending. */
    bool waitForDatagrams(int msecs);

    const Stats &stats() const { return m_stats; }
    /** The actors the frames named; frames refer to them by id. */
    const ActorTable &actors() const { return m_parser.actors(); }

signals:
    /** Datagrams arrived (event-loop users call poll() from here). */
    void datagramsPending();

private:
    void handle(const QByteArray &datagram, double arrival, const FrameHandler &handler,
                int *frames);
    void reject(const QString &reason);

    std::unique_ptr<QUdpSocket> m_socket;
    ContactFrameParser m_parser;
    QElapsedTimer m_clock;
    QByteArray m_buffer;
    Stats m_stats;
    ErrorHandler m_onError;
    double m_silence = DefaultSilence;
    double m_lastFrame = -1.0; ///< arrival of the last valid frame; -1: none since a silence
};

} // namespace semhap
