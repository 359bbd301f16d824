// SPDX-License-Identifier: MIT
#pragma once

#include "frameassembler.h"
#include "topicdecoder.h"
#include "topicmap.h"

#include <QElapsedTimer>
#include <QObject>
#include <QUrl>

#include <functional>
#include <map>
#include <memory>

class QWebSocket;

namespace semhap {

/**
 * A robot followed live over the Foxglove WebSocket protocol (`foxglove.websocket.v1`, as
 * foxglove_bridge serves it): it subscribes to the channels of the map's topics as they are
 * advertised, decodes each message by its advertised schema, and makes contact frames as
 * the topic map says, the same way a recording is read (FrameAssembler). It reconnects when
 * the robot's server goes away, and tells when the robot has fallen silent.
 */
class FoxgloveSource : public QObject
{
    Q_OBJECT

public:
    using FrameHandler = std::function<void(const ContactFrame &frame, double arrival)>;
    using ErrorHandler = std::function<void(const QString &line)>;

    /** How long a robot may advertise none of the map's topics before that is an error (ms). */
    static constexpr int AdvertiseGrace = 3000;
    /** How long to wait before connecting again after a close (ms). */
    static constexpr int ReconnectDelay = 500;

    struct Stats
    {
        long long messages = 0; ///< decoded, on mapped topics
        long long frames = 0;   ///< handed on
        long long rejected = 0; ///< messages that did not decode
        int connections = 0;    ///< connections made, the first included
    };

    FoxgloveSource(const QUrl &url, const TopicMap &map, const QString &mapPath,
                   QObject *parent = nullptr);
    ~FoxgloveSource() override;

    /** Connects, and keeps connecting after every close. */
    void start();
    /**
     * Runs the event loop up to `msecs`, then hands each frame made to `handler`, with its
     * arrival on a steady clock since start() (s); how many.
     */
    int poll(const FrameHandler &handler, int msecs);

    void setSilence(double seconds) { m_silence = seconds; }
    double silence() const { return m_silence; }
    /** True once, when no message came for silence() seconds after one did. */
    bool fellSilent();
    /** Milliseconds until silence would fall, or -1 when it cannot (none came yet). */
    qint64 msecsToSilence() const;

    /** A fault that ends following: no mapped topic advertised. Empty while all is well. */
    QString fatalError() const { return m_fatal; }
    void setErrorHandler(ErrorHandler handler) { m_onError = std::move(handler); }
    const Stats &stats() const { return m_stats; }
    /** Where frames' t count from: whole seconds since the epoch; -1 before a message. */
    std::int64_t epoch() const { return m_epoch; }
    const ActorTable &actors() const { return m_actors; }
    QString describe() const { return m_url.toString(); }

private:
    struct Channel
    {
        int topic = -1; ///< the assembler's
        TopicDecoder::Description description;
        std::unique_ptr<TopicDecoder> decoder; ///< made at its first message
    };

    void connectNow();
    void onText(const QString &text);
    void onBinary(const QByteArray &bytes);
    void subscribe(const QJsonArray &channels);
    void report(const QString &line);

    QUrl m_url;
    QString m_mapPath;
    TopicMap m_map;
    ActorTable m_actors;
    std::unique_ptr<FrameAssembler> m_assembler;
    std::unique_ptr<QWebSocket> m_socket;
    std::map<std::uint32_t, Channel> m_subscriptions; ///< by subscription id
    std::uint32_t m_nextSubscription = 1;
    QStringList m_advertised;
    QElapsedTimer m_clock;        ///< since start(): arrivals
    QElapsedTimer m_sinceConnect; ///< for the advertise grace
    qint64 m_lastMessage = -1;    ///< m_clock ms
    bool m_silent = true;
    double m_silence = 0.25;
    std::int64_t m_epoch = -1;
    std::vector<double> m_values;
    QString m_fatal;
    ErrorHandler m_onError;
    Stats m_stats;
    bool m_stopping = false;
};

} // namespace semhap
