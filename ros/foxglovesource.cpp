// SPDX-License-Identifier: MIT
#include "foxglovesource.h"

#include "jsonreader.h"

#include <QCoreApplication>
#include <QEventLoop>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtEndian>
#include <QTimer>
#include <QWebSocket>
#include <QWebSocketHandshakeOptions>

#include <cmath>

namespace semhap {

namespace {

const QLatin1String Subprotocol("foxglove.websocket.v1");
constexpr std::uint8_t MessageData = 0x01;

} // namespace

FoxgloveSource::FoxgloveSource(const QUrl &url, const TopicMap &map, const QString &mapPath,
                               QObject *parent)
    : QObject(parent), m_url(url), m_mapPath(mapPath), m_map(map),
      m_assembler(std::make_unique<FrameAssembler>(map, m_actors))
{}

FoxgloveSource::~FoxgloveSource()
{
    m_stopping = true;
    if (m_socket)
        m_socket->abort();
}

void FoxgloveSource::report(const QString &line)
{
    if (m_onError)
        m_onError(line);
}

void FoxgloveSource::start()
{
    m_clock.start();
    connectNow();
}

void FoxgloveSource::connectNow()
{
    m_socket = std::make_unique<QWebSocket>();
    m_subscriptions.clear();
    m_advertised.clear();
    QWebSocketHandshakeOptions options;
    options.setSubprotocols({Subprotocol});
    connect(m_socket.get(), &QWebSocket::connected, this, [this] {
        ++m_stats.connections;
        m_sinceConnect.start();
    });
    connect(m_socket.get(), &QWebSocket::textMessageReceived, this, &FoxgloveSource::onText);
    connect(m_socket.get(), &QWebSocket::binaryMessageReceived, this, &FoxgloveSource::onBinary);
    connect(m_socket.get(), &QWebSocket::disconnected, this, [this] {
        if (m_stopping || !m_fatal.isEmpty())
            return;
        // The robot restarted or the network dropped: try again, and again.
        QTimer::singleShot(ReconnectDelay, this, [this] {
            if (!m_stopping)
                connectNow();
        });
    });
    m_socket->open(QNetworkRequest(m_url), options);
}

void FoxgloveSource::onText(const QString &text)
{
    const QJsonObject message = QJsonDocument::fromJson(text.toUtf8()).object();
    const QString op = message.value(QLatin1String("op")).toString();
    if (op == QLatin1String("advertise"))
        subscribe(message.value(QLatin1String("channels")).toArray());
    else if (op == QLatin1String("status") && message.value(QLatin1String("level")).toInt() >= 2)
        report(QStringLiteral("%1: the robot says: %2")
                   .arg(describe(), message.value(QLatin1String("message")).toString()));
}

void FoxgloveSource::subscribe(const QJsonArray &channels)
{
    QJsonArray subscriptions;
    for (const QJsonValue &value : channels) {
        const QJsonObject c = value.toObject();
        const QString topic = c.value(QLatin1String("topic")).toString();
        m_advertised << topic;
        const int index = m_assembler->topicIndex(topic);
        if (index < 0)
            continue;
        Channel channel;
        channel.topic = index;
        const QString encoding = c.value(QLatin1String("encoding")).toString();
        // foxglove_bridge names the schema encoding; older servers leave ros2msg implied.
        const QString schemaEncoding =
            c.value(QLatin1String("schemaEncoding"))
                .toString(encoding == QLatin1String("cdr") ? QStringLiteral("ros2msg")
                                                           : QString());
        channel.description = {topic, c.value(QLatin1String("schemaName")).toString(),
                               schemaEncoding,
                               c.value(QLatin1String("schema")).toString().toUtf8(), encoding};
        const std::uint32_t id = m_nextSubscription++;
        subscriptions.append(
            QJsonObject{{QStringLiteral("id"), qint64(id)},
                        {QStringLiteral("channelId"), c.value(QLatin1String("id"))}});
        m_subscriptions.emplace(id, std::move(channel));
    }
    if (!subscriptions.isEmpty())
        m_socket->sendTextMessage(QString::fromUtf8(
            QJsonDocument(QJsonObject{{QStringLiteral("op"), QStringLiteral("subscribe")},
                                      {QStringLiteral("subscriptions"), subscriptions}})
                .toJson(QJsonDocument::Compact)));
}

void FoxgloveSource::onBinary(const QByteArray &bytes)
{
    if (bytes.size() < 13 || std::uint8_t(bytes[0]) != MessageData)
        return; // time, service and asset replies: nothing semhap asked for
    const auto id = qFromLittleEndian<std::uint32_t>(bytes.constData() + 1);
    const auto stamp = qFromLittleEndian<std::uint64_t>(bytes.constData() + 5);
    const auto it = m_subscriptions.find(id);
    if (it == m_subscriptions.end())
        return;
    Channel &channel = it->second;
    if (m_epoch < 0)
        m_epoch = std::int64_t(stamp / 1000000000u);
    QString why;
    if (!channel.decoder) {
        // Compiled at its first message, so that times are read from the epoch.
        auto decoder = std::make_unique<TopicDecoder>();
        decoder->setEpoch(m_epoch);
        const std::vector<TopicDecoder::Want> &wants = m_assembler->wants(channel.topic);
        const bool compiled = decoder->compile(channel.description, wants, &why);
        if (!compiled) {
            m_fatal = QStringLiteral("%1: %2: %3").arg(m_mapPath, describe(), why);
            m_socket->close();
            return;
        }
        m_values.resize(std::max(m_values.size(), size_t(decoder->valueCount())));
        channel.decoder = std::move(decoder);
    }
    if (!channel.decoder->decode(bytes.constData() + 13, size_t(bytes.size() - 13),
                                 m_values.data(), &why)) {
        ++m_stats.rejected;
        report(QStringLiteral("%1: %2: %3").arg(describe(), channel.description.topic, why));
        return;
    }
    ++m_stats.messages;
    m_lastMessage = m_clock.elapsed();
    m_silent = false;
    const double logTime = double(std::int64_t(stamp) - m_epoch * 1000000000) * 1e-9;
    m_assembler->take(channel.topic, logTime, m_values.data());
}

int FoxgloveSource::poll(const FrameHandler &handler, int msecs)
{
    QEventLoop loop;
    QTimer::singleShot(std::max(0, msecs), &loop, &QEventLoop::quit);
    loop.exec();
    if (m_fatal.isEmpty() && m_socket && m_socket->state() == QAbstractSocket::ConnectedState &&
        m_sinceConnect.isValid() && m_sinceConnect.elapsed() > AdvertiseGrace &&
        m_subscriptions.empty()) {
        QStringList topics = m_advertised;
        topics.sort();
        m_fatal = QStringLiteral("%1: %2 advertises none of the map's topics (%3); it has: %4")
                      .arg(m_mapPath, describe(), m_assembler->topics().join(QStringLiteral(", ")),
                           topics.isEmpty() ? QStringLiteral("none")
                                            : topics.join(QStringLiteral(", ")));
        m_socket->close();
    }
    int n = 0;
    ContactFrame frame;
    const double arrival = double(m_clock.elapsed()) * 1e-3;
    while (m_assembler->next(&frame)) {
        handler(frame, arrival);
        ++n;
    }
    m_stats.frames += n;
    return n;
}

bool FoxgloveSource::fellSilent()
{
    if (m_silent || m_lastMessage < 0 ||
        m_clock.elapsed() - m_lastMessage < qint64(m_silence * 1000))
        return false;
    m_silent = true;
    // What waited for a silent topic is made now; the next message starts afresh.
    m_assembler->finish();
    return true;
}

qint64 FoxgloveSource::msecsToSilence() const
{
    if (m_silent || m_lastMessage < 0)
        return -1;
    return std::max<qint64>(0, m_lastMessage + qint64(m_silence * 1000) - m_clock.elapsed());
}

} // namespace semhap
