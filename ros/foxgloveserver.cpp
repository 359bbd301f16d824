// SPDX-License-Identifier: MIT
#include "foxgloveserver.h"

#include <QElapsedTimer>
#include <QEventLoop>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QMutex>
#include <QtEndian>
#include <QThread>
#include <QTimer>
#include <QWebSocket>
#include <QWebSocketServer>

#include <algorithm>
#include <atomic>
#include <deque>
#include <map>
#include <vector>

namespace semhap {

namespace {

const QLatin1String Subprotocol("foxglove.websocket.v1");
constexpr std::uint8_t MessageData = 0x01;
/** Bytes a client's socket may hold unwritten before its queue waits. */
constexpr qint64 InFlight = 1 << 20;
/** How often a slow client is told it lost messages (ms). */
constexpr qint64 DropReport = 1000;
/** Messages published and not yet taken by the server's thread: only a starved one has many. */
constexpr size_t Pending = 1 << 16;
/**
 * How often the server's thread takes what was published (ms). Polled, not woken per
 * message: publishing is then a push under a lock, with no system call on the pipeline's
 * thread, and the sockets get their messages in batches.
 */
constexpr int DrainInterval = 5;

struct Channel
{
    QString topic, schemaName;
    QByteArray schema;
};

struct Message
{
    int channel;
    std::uint64_t ns;
    QByteArray payload;
};

QString compact(const QJsonObject &object)
{
    return QString::fromUtf8(QJsonDocument(object).toJson(QJsonDocument::Compact));
}

QJsonObject advertisement(int id, const Channel &c)
{
    return {{QStringLiteral("id"), id},
            {QStringLiteral("topic"), c.topic},
            {QStringLiteral("encoding"), QStringLiteral("cdr")},
            {QStringLiteral("schemaName"), c.schemaName},
            {QStringLiteral("schema"), QString::fromUtf8(c.schema)},
            {QStringLiteral("schemaEncoding"), QStringLiteral("ros2msg")}};
}

} // namespace

/** What the publishing thread and the server's thread share, under one mutex. */
struct FoxgloveServer::Shared
{
    mutable QMutex mutex;
    std::vector<Channel> channels;
    std::deque<Message> pending;
    bool closed = false; ///< the worker is going or gone: nothing more is taken
    int queueLimit = DefaultQueue;
    long long published = 0;
    long long lost = 0; ///< before the server's thread took them: starved, or closed
    Stats served;       ///< the server's thread's counts, as of its last drain
};

/** The server's side, on its own thread: the sockets, the subscriptions, the queues. */
class FoxgloveServer::Worker : public QObject
{
public:
    Worker(const QString &name, std::shared_ptr<Shared> shared)
        : m_name(name), m_shared(std::move(shared))
    {}

    bool listen(const QHostAddress &address, quint16 port, QString *error, quint16 *bound)
    {
        m_server =
            new QWebSocketServer(QStringLiteral("semhap"), QWebSocketServer::NonSecureMode, this);
        m_server->setSupportedSubprotocols({Subprotocol});
        if (!m_server->listen(address, port)) {
            *error = m_server->errorString();
            return false;
        }
        *bound = m_server->serverPort();
        connect(m_server, &QWebSocketServer::newConnection, this, &Worker::accept);
        connect(&m_drain, &QTimer::timeout, this, &Worker::drain);
        m_drain.start(DrainInterval);
        return true;
    }

    /** Takes what was published and added since the last call, and sends it on. */
    void drain()
    {
        std::deque<Message> messages;
        std::vector<Channel> channels;
        {
            QMutexLocker lock(&m_shared->mutex);
            messages.swap(m_shared->pending);
            channels.assign(m_shared->channels.begin() + long(m_advertised),
                            m_shared->channels.end());
        }
        if (!channels.empty()) {
            QJsonArray list;
            for (const Channel &c : channels)
                list.append(advertisement(int(m_advertised++), c));
            const QString text = compact({{QStringLiteral("op"), QStringLiteral("advertise")},
                                          {QStringLiteral("channels"), list}});
            for (auto &[socket, client] : m_clients)
                socket->sendTextMessage(text);
        }
        for (Message &m : messages) {
            for (auto &[socket, client] : m_clients) {
                const auto sub = client.subscriptions.find(m.channel);
                if (sub == client.subscriptions.end())
                    continue;
                client.queue.push_back({sub->second, m.ns, m.payload});
                if (int(client.queue.size()) > m_queueLimit) {
                    client.queue.pop_front();
                    ++client.dropped;
                    ++m_stats.dropped;
                }
            }
        }
        for (auto &[socket, client] : m_clients)
            pump(socket, client);
        share();
    }

    void setQueueLimit(int messages) { m_queueLimit = messages; }

    /** Hands each client what is waiting for it and closes, waiting up to Goodbye ms. */
    void close()
    {
        drain();
        if (m_server)
            m_server->close();
        // Closing may tell of a disconnect at once, which takes the client out of the map.
        std::vector<QWebSocket *> sockets;
        for (auto &[socket, client] : m_clients) {
            pump(socket, client, true);
            sockets.push_back(socket);
        }
        for (QWebSocket *socket : sockets) {
            socket->flush();
            socket->close();
        }
        QEventLoop loop;
        QTimer::singleShot(Goodbye, &loop, &QEventLoop::quit);
        QTimer poll;
        connect(&poll, &QTimer::timeout, &loop, [this, &loop] {
            if (m_clients.empty())
                loop.quit();
        });
        poll.start(10);
        if (!m_clients.empty())
            loop.exec();
        m_drain.stop();
        share();
    }

private:
    struct Queued
    {
        std::uint32_t subscription;
        std::uint64_t ns;
        QByteArray payload;
    };
    struct Client
    {
        std::map<int, std::uint32_t> subscriptions; ///< channel → the client's subscription id
        std::deque<Queued> queue;
        qint64 inFlight = 0;    ///< handed to the socket, not yet written
        long long dropped = 0;  ///< since the client was last told
        QElapsedTimer lastTold; ///< when it was
    };

    void accept()
    {
        while (QWebSocket *socket = m_server->nextPendingConnection()) {
            socket->setParent(this);
            m_clients.emplace(socket, Client());
            ++m_stats.connections;
            connect(socket, &QWebSocket::textMessageReceived, this,
                    [this, socket](const QString &text) { onText(socket, text); });
            connect(socket, &QWebSocket::bytesWritten, this, [this, socket](qint64 bytes) {
                const auto it = m_clients.find(socket);
                if (it == m_clients.end())
                    return;
                it->second.inFlight = std::max<qint64>(0, it->second.inFlight - bytes);
                pump(socket, it->second);
            });
            connect(socket, &QWebSocket::disconnected, this, [this, socket] {
                m_clients.erase(socket);
                socket->deleteLater();
            });
            socket->sendTextMessage(compact({{QStringLiteral("op"), QStringLiteral("serverInfo")},
                                             {QStringLiteral("name"), m_name},
                                             {QStringLiteral("capabilities"), QJsonArray()},
                                             {QStringLiteral("supportedEncodings"), QJsonArray()},
                                             {QStringLiteral("metadata"), QJsonObject()}}));
            QJsonArray list;
            // Only the channels this thread has announced: the rest come with the next drain.
            std::vector<Channel> known;
            {
                QMutexLocker lock(&m_shared->mutex);
                known.assign(m_shared->channels.begin(),
                             m_shared->channels.begin() + long(m_advertised));
            }
            for (size_t id = 0; id < known.size(); ++id)
                list.append(advertisement(int(id), known[id]));
            if (!list.isEmpty())
                socket->sendTextMessage(
                    compact({{QStringLiteral("op"), QStringLiteral("advertise")},
                             {QStringLiteral("channels"), list}}));
        }
    }

    /** Makes the counts as they are now what stats() tells. */
    void share()
    {
        m_stats.clients = int(m_clients.size());
        m_stats.subscriptions = 0;
        m_stats.outstanding = 0;
        for (const auto &[socket, client] : m_clients) {
            m_stats.subscriptions += int(client.subscriptions.size());
            m_stats.outstanding += client.inFlight;
        }
        QMutexLocker lock(&m_shared->mutex);
        m_shared->served = m_stats;
    }

    void status(QWebSocket *socket, int level, const QString &message)
    {
        socket->sendTextMessage(compact({{QStringLiteral("op"), QStringLiteral("status")},
                                         {QStringLiteral("level"), level},
                                         {QStringLiteral("message"), message}}));
    }

    void onText(QWebSocket *socket, const QString &text)
    {
        const auto it = m_clients.find(socket);
        if (it == m_clients.end())
            return;
        Client &client = it->second;
        const QJsonObject message = QJsonDocument::fromJson(text.toUtf8()).object();
        const QString op = message.value(QLatin1String("op")).toString();
        if (op == QLatin1String("subscribe")) {
            for (const QJsonValue &value :
                 message.value(QLatin1String("subscriptions")).toArray()) {
                const QJsonObject s = value.toObject();
                const int channel = s.value(QLatin1String("channelId")).toInt(-1);
                const qint64 id = s.value(QLatin1String("id")).toInteger(-1);
                if (channel < 0 || channel >= int(m_advertised) || id < 0 || id > UINT32_MAX) {
                    status(socket, 2,
                           QStringLiteral("semhap: no channel %1 to subscribe to").arg(channel));
                    continue;
                }
                client.subscriptions[channel] = std::uint32_t(id);
            }
        } else if (op == QLatin1String("unsubscribe")) {
            for (const QJsonValue &value :
                 message.value(QLatin1String("subscriptionIds")).toArray()) {
                const qint64 id = value.toInteger(-1);
                for (auto s = client.subscriptions.begin(); s != client.subscriptions.end();) {
                    if (qint64(s->second) == id)
                        s = client.subscriptions.erase(s);
                    else
                        ++s;
                }
                // What waits for that subscription is no longer wanted.
                client.queue.erase(
                    std::remove_if(client.queue.begin(), client.queue.end(),
                                   [id](const Queued &q) { return qint64(q.subscription) == id; }),
                    client.queue.end());
            }
        } else if (!op.isEmpty()) {
            status(socket, 1, QStringLiteral("semhap: %1 is not served").arg(op));
        }
    }

    /** Sends from `client`'s queue while its socket has room, or all of it. */
    void pump(QWebSocket *socket, Client &client, bool all = false)
    {
        while (!client.queue.empty() && (all || client.inFlight < InFlight)) {
            const Queued &q = client.queue.front();
            QByteArray frame(13 + q.payload.size(), Qt::Uninitialized);
            frame[0] = char(MessageData);
            qToLittleEndian(q.subscription, frame.data() + 1);
            qToLittleEndian(q.ns, frame.data() + 5);
            std::copy(q.payload.begin(), q.payload.end(), frame.begin() + 13);
            client.inFlight += socket->sendBinaryMessage(frame);
            client.queue.pop_front();
            ++m_stats.sent;
        }
        if (client.dropped > 0 &&
            (!client.lastTold.isValid() || client.lastTold.elapsed() >= DropReport)) {
            status(socket, 1,
                   QStringLiteral("semhap: this client reads too slowly: dropped its %1 oldest "
                                  "message(s)")
                       .arg(client.dropped));
            client.dropped = 0;
            client.lastTold.start();
        }
    }

    QString m_name;
    std::shared_ptr<Shared> m_shared;
    QWebSocketServer *m_server = nullptr;
    std::map<QWebSocket *, Client> m_clients;
    size_t m_advertised = 0; ///< channels told to the clients
    int m_queueLimit = DefaultQueue;
    QTimer m_drain{this};
    Stats m_stats; ///< sent and dropped from the clients' queues; the rest by share()
};

FoxgloveServer::FoxgloveServer(const QString &name)
    : m_shared(std::make_shared<Shared>()), m_thread(std::make_unique<QThread>())
{
    m_thread->setObjectName(QStringLiteral("semhap-foxglove"));
    m_worker = new Worker(name, m_shared);
    m_worker->moveToThread(m_thread.get());
    QObject::connect(m_thread.get(), &QThread::finished, m_worker, &QObject::deleteLater);
    m_thread->start();
}

FoxgloveServer::~FoxgloveServer()
{
    close();
}

void FoxgloveServer::close()
{
    {
        QMutexLocker lock(&m_shared->mutex);
        if (m_shared->closed)
            return;
        m_shared->closed = true;
    }
    QMetaObject::invokeMethod(
        m_worker, [w = m_worker] { w->close(); }, Qt::BlockingQueuedConnection);
    m_thread->quit();
    m_thread->wait();
}

bool FoxgloveServer::listen(const QHostAddress &address, quint16 port, QString *error)
{
    bool ok = false;
    quint16 bound = 0;
    int limit = DefaultQueue;
    {
        QMutexLocker lock(&m_shared->mutex);
        limit = m_shared->queueLimit;
    }
    QMetaObject::invokeMethod(
        m_worker,
        [&] {
            m_worker->setQueueLimit(limit);
            ok = m_worker->listen(address, port, error, &bound);
        },
        Qt::BlockingQueuedConnection);
    if (ok) {
        m_address = address;
        m_port = bound;
    }
    return ok;
}

quint16 FoxgloveServer::port() const
{
    return m_port;
}

QString FoxgloveServer::url() const
{
    const QString host = m_address.protocol() == QAbstractSocket::IPv6Protocol
                             ? QStringLiteral("[%1]").arg(m_address.toString())
                             : m_address.toString();
    return QStringLiteral("ws://%1:%2").arg(host).arg(m_port);
}

void FoxgloveServer::setQueueLimit(int messages)
{
    QMutexLocker lock(&m_shared->mutex);
    m_shared->queueLimit = std::max(1, messages);
}

int FoxgloveServer::addChannel(const QString &topic, const QString &schemaName,
                               const QByteArray &schema)
{
    QMutexLocker lock(&m_shared->mutex);
    for (size_t id = 0; id < m_shared->channels.size(); ++id) {
        const Channel &c = m_shared->channels[id];
        if (c.topic == topic && c.schemaName == schemaName)
            return int(id);
    }
    m_shared->channels.push_back({topic, schemaName, schema});
    return int(m_shared->channels.size() - 1);
}

void FoxgloveServer::publish(int channel, std::uint64_t ns, QByteArrayView payload)
{
    QMutexLocker lock(&m_shared->mutex);
    ++m_shared->published;
    if (m_shared->closed) {
        ++m_shared->lost;
        return;
    }
    m_shared->pending.push_back({channel, ns, payload.toByteArray()});
    // The server's thread starved (a machine far too busy): the publisher still never waits.
    if (m_shared->pending.size() > Pending) {
        m_shared->pending.pop_front();
        ++m_shared->lost;
    }
}

FoxgloveServer::Stats FoxgloveServer::stats() const
{
    QMutexLocker lock(&m_shared->mutex);
    Stats stats = m_shared->served;
    stats.published = m_shared->published;
    stats.dropped += m_shared->lost;
    return stats;
}

} // namespace semhap
