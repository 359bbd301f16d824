// SPDX-License-Identifier: MIT
#pragma once

#include <QByteArray>
#include <QHostAddress>
#include <QString>

#include <cstdint>
#include <memory>

namespace semhap {

/**
 * A Foxglove WebSocket server (`foxglove.websocket.v1`) that viewers watch semhap through:
 * it advertises channels, serves subscriptions, and sends each published message to every
 * client subscribed to its channel.
 *
 * It runs on a thread of its own, so publish() never waits for a client: it hands the
 * message over and returns, and the server's thread takes what was published every 5 ms. Each
 * client has a bounded queue; a client that reads more slowly than messages come loses its own
 * oldest ones, and is told so by a warning status (at most once a second). Other clients and the
 * publisher go on as before.
 */
class FoxgloveServer
{
public:
    /** Messages a client may have waiting before its oldest are dropped. */
    static constexpr int DefaultQueue = 16384;
    /** How long the server, going away, waits for its clients to read what is theirs (ms). */
    static constexpr int Goodbye = 2000;

    struct Stats
    {
        int clients = 0;           ///< connected now
        int connections = 0;       ///< ever, the ones closed included
        int subscriptions = 0;     ///< of the clients connected now
        long long published = 0;   ///< handed to publish()
        long long sent = 0;        ///< to a client, over all clients
        long long dropped = 0;     ///< lost: from a slow client's queue, or (a starved or
                                   ///< closed server) before any client's
        long long outstanding = 0; ///< bytes handed to the sockets and not yet written
    };

    /** A server named `name` in the viewers' connection list. */
    explicit FoxgloveServer(const QString &name);
    ~FoxgloveServer();
    FoxgloveServer(const FoxgloveServer &) = delete;
    FoxgloveServer &operator=(const FoxgloveServer &) = delete;

    /** Listens on `address`:`port` (0: any free port); false with `error`. */
    bool listen(const QHostAddress &address, quint16 port, QString *error);
    quint16 port() const;
    /** ws://ADDRESS:PORT, for a viewer's connection dialog. */
    QString url() const;

    /** Sets how many messages each client may have waiting (before listen()). */
    void setQueueLimit(int messages);

    /**
     * A channel of `topic` with messages in CDR of the ROS 2 type `schemaName`
     * (`ros2msg` text `schema`); its id. Clients connected now are told within 5 ms. The
     * same topic and type again is the same channel.
     */
    int addChannel(const QString &topic, const QString &schemaName, const QByteArray &schema);
    /** Sends `payload` on `channel`, stamped `ns` (ns since the epoch). Any thread. */
    void publish(int channel, std::uint64_t ns, QByteArrayView payload);

    /**
     * Sends each client what is waiting for it (up to Goodbye ms) and closes; later
     * messages are dropped. The destructor does it too.
     */
    void close();

    /** The counts as of the server thread's last look (at most 5 ms old). */
    Stats stats() const;

private:
    class Worker;
    struct Shared;
    std::shared_ptr<Shared> m_shared;
    std::unique_ptr<class QThread> m_thread;
    Worker *m_worker = nullptr; ///< lives on m_thread
    QHostAddress m_address;
    quint16 m_port = 0;
};

} // namespace semhap
