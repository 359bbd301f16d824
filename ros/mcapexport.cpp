// SPDX-License-Identifier: MIT
#include "mcapexport.h"

#include "cdrwriter.h"
#include "mcapwriter.h"
#include "rostypes.h"
#include "routergraph.h"
#include "semhapmessages.h"
#include "sessionreader.h"

#include <QJsonDocument>

#include <atomic>
#include <cmath>
#include <condition_variable>
#include <map>
#include <mutex>
#include <thread>
#include <vector>

namespace semhap {

namespace {

const QLatin1String Cdr("cdr");
const QLatin1String Ros2Msg("ros2msg");
using M = SemhapMessages;

/**
 * The writer on a thread of its own: the export reads the session and encodes its messages
 * while the writer packs and compresses chunks, so two cores share the work. Messages go
 * over in batches. A channel is made only once the writer has caught up (drain()), so the
 * file is byte for byte what one thread writes.
 */
class WriterThread
{
public:
    explicit WriterThread(McapWriter &mcap) : m_mcap(mcap), m_thread([this] { run(); }) {}
    ~WriterThread() { finish(); }

    /** Queues a message; the writer writes it in order with the others. */
    void add(std::uint16_t channel, std::uint64_t logTime, QByteArrayView data)
    {
        m_front.messages.push_back({channel, logTime, m_front.bytes.size(), size_t(data.size())});
        m_front.bytes.insert(m_front.bytes.end(), data.begin(), data.end());
        if (m_front.messages.size() >= BatchSize)
            hand();
    }
    /** Waits until every message queued is written: then the McapWriter may be used. */
    void drain()
    {
        hand();
        std::unique_lock<std::mutex> lock(m_mutex);
        m_idle.wait(lock, [this] { return !m_busy; });
    }
    /** Writes what is queued and ends the thread. */
    void finish()
    {
        if (!m_thread.joinable())
            return;
        drain();
        {
            std::lock_guard<std::mutex> lock(m_mutex);
            m_stopping = true;
        }
        m_wake.notify_one();
        m_thread.join();
    }
    /** True once a write failed: McapWriter::error() says why, after drain(). */
    bool failed() const { return m_failed.load(std::memory_order_relaxed); }

private:
    static constexpr size_t BatchSize = 4096;
    struct Message
    {
        std::uint16_t channel;
        std::uint64_t logTime;
        size_t offset, size; ///< in the batch's bytes
    };
    struct Batch
    {
        std::vector<Message> messages;
        std::vector<char> bytes;
    };

    /** Hands the queued batch to the writer once it has finished the one before. */
    void hand()
    {
        if (m_front.messages.empty())
            return;
        std::unique_lock<std::mutex> lock(m_mutex);
        m_idle.wait(lock, [this] { return !m_busy; });
        std::swap(m_front, m_back); // the writer left its batch empty
        m_busy = true;
        lock.unlock();
        m_wake.notify_one();
    }

    void run()
    {
        std::unique_lock<std::mutex> lock(m_mutex);
        for (;;) {
            m_wake.wait(lock, [this] { return m_busy || m_stopping; });
            if (!m_busy)
                return;
            lock.unlock();
            for (const Message &m : m_back.messages) {
                if (!failed() && !m_mcap.addMessage(m.channel, m.logTime,
                                                    QByteArrayView(m_back.bytes.data() + m.offset,
                                                                   qsizetype(m.size))))
                    m_failed = true;
            }
            m_back.messages.clear();
            m_back.bytes.clear(); // keeps its capacity for the next batch
            lock.lock();
            m_busy = false;
            m_idle.notify_all();
        }
    }

    McapWriter &m_mcap;
    Batch m_front; ///< the reading thread's
    Batch m_back;  ///< the writer's while m_busy
    std::mutex m_mutex;
    std::condition_variable m_wake;
    std::condition_variable m_idle;
    bool m_busy = false;
    bool m_stopping = false;
    std::atomic<bool> m_failed{false};
    std::thread m_thread;
};

} // namespace

bool McapExport::write(SessionReader &session, QIODevice *out, QString *error)
{
    const SessionInfo &info = session.info();
    const std::int64_t origin =
        info.started.isValid() ? info.started.toMSecsSinceEpoch() * 1000000 : 0;
    const auto stamp = [origin](double t) { return origin + std::llround(t * 1e9); };
    // Log times are unsigned: a row before the epoch (a hand-made session) is at 0.
    const auto logTime = [&](double t) {
        return std::uint64_t(std::max<std::int64_t>(0, stamp(t)));
    };

    McapWriter mcap(out);
    mcap.begin(QStringLiteral("ros2"), QStringLiteral("semhap ") + info.semhapVersion);
    const auto schema = [&](const char *type) {
        return mcap.addSchema(QLatin1String(type), Ros2Msg, RosTypes::schema(QLatin1String(type)));
    };
    const std::uint16_t contactSchema = schema(M::ContactType);
    const std::uint16_t wrenchSchema = schema(M::WrenchType);
    const std::uint16_t eventSchema = schema(M::EventType);
    const std::uint16_t deviceSchema = schema(M::DeviceType);
    const std::uint16_t inputSchema = schema(M::InputType);
    // A gripper's and a hand's channels come with their first message: a one-handed
    // session shows no empty topics.
    std::map<QString, std::uint16_t> channels;
    // Nothing is queued before the streams are read: the channels made until then need no drain.
    WriterThread writer(mcap);
    const auto channel = [&](std::uint16_t schemaId, const QString &topic) {
        const auto it = channels.find(topic);
        if (it != channels.end())
            return it->second;
        writer.drain(); // the channel's record goes after every message before it
        return channels[topic] = mcap.addChannel(schemaId, topic, Cdr);
    };
    const std::uint16_t events = mcap.addChannel(eventSchema, M::eventsTopic(), Cdr);
    std::vector<std::uint16_t> devices;
    QStringList models;
    std::vector<std::vector<QByteArray>> channelNames; // per device, as UTF-8, made once
    RouterGraph graph;
    LoadError routerError;
    const bool hasGraph = session.routerGraph(&graph, &routerError);
    for (const QString &device : session.deviceNames()) {
        devices.push_back(mcap.addChannel(deviceSchema, M::deviceTopic(device), Cdr));
        QString model;
        for (const RouterNode &node : hasGraph ? graph.nodes : std::vector<RouterNode>()) {
            if (node.id == device)
                model = node.params.value(QLatin1String("model")).toString();
        }
        models << model;
        channelNames.emplace_back();
        for (const QString &c : session.channelNames(int(devices.size() - 1)))
            channelNames.back().push_back(c.toUtf8());
    }
    // Each gripper's and hand's channels, looked up once per gripper, not per row.
    struct Hand
    {
        int contact = -1, input = -1;
        std::array<int, 2> wrench{-1, -1};
    };
    std::array<Hand, 2> hands;
    // The topic is named only the first time: naming it per message cost a tenth of export.
    const auto lazy = [&](int &id, std::uint16_t schemaId, const auto &topic) {
        if (id < 0)
            id = channel(schemaId, topic());
        return std::uint16_t(id);
    };

    CdrWriter cdr;
    const ActorTable &actors = session.actors();
    bool ok = session.readContactFrames(
        [&](const ContactFrame &frame, double) {
            Hand &hand = hands[size_t(frame.gripper)];
            M::contact(cdr, stamp(frame.t), frame, actors);
            writer.add(lazy(hand.contact, contactSchema,
                                 [&] { return M::contactTopic(frame.gripper); }),
                            logTime(frame.t), cdr.bytes());
            for (const bool left : {true, false}) {
                M::wrench(cdr, stamp(frame.t), frame, left);
                writer.add(lazy(hand.wrench[left ? 0 : 1], wrenchSchema,
                                     [&] { return M::wrenchTopic(frame.gripper, left); }),
                                logTime(frame.t), cdr.bytes());
            }
            return !writer.failed();
        },
        error);
    ok = ok && session.readEvents(
                   [&](const SemanticEvent &e) {
                       M::event(cdr, stamp(e.t), e, session.nodeNames().value(e.node));
                       writer.add(events, logTime(e.t), cdr.bytes());
                       return !writer.failed();
                   },
                   error);
    ok = ok && session.readDeviceFrames(
                   [&](const DeviceFrame &f) {
                       M::device(cdr, stamp(f.t), f, session.deviceNames().value(f.device),
                                 models.value(f.device), channelNames[size_t(f.device)]);
                       writer.add(devices[size_t(f.device)], logTime(f.t), cdr.bytes());
                       return !writer.failed();
                   },
                   error);
    ok = ok && session.readHandCommands(
                   [&](const HandCommand &h) {
                       M::input(cdr, stamp(h.t), h);
                       writer.add(
                           lazy(hands[size_t(h.hand)].input, inputSchema,
                                [&] { return M::inputTopic(h.hand); }),
                           logTime(h.t), cdr.bytes());
                       return !writer.failed();
                   },
                   error);
    writer.finish();
    if (!ok || writer.failed()) {
        if (error->isEmpty())
            *error = mcap.error();
        return false;
    }
    mcap.addMetadata(QStringLiteral("semhap"),
                     {{QStringLiteral("time_origin"), QString::number(origin)},
                      {QStringLiteral("source"), info.source},
                      {QStringLiteral("semhap_version"), info.semhapVersion}});
    mcap.addMetadata(
        QStringLiteral("router"),
        {{QStringLiteral("source"), info.routerSource},
         {QStringLiteral("json"),
          QString::fromUtf8(QJsonDocument(info.router).toJson(QJsonDocument::Compact))}});
    if (!info.scene.isEmpty())
        mcap.addMetadata(QStringLiteral("scene"), {{QStringLiteral("name"), info.scene}});
    if (!mcap.end()) {
        *error = mcap.error();
        return false;
    }
    return true;
}

TopicMap McapExport::topicMap()
{
    TopicMap map;
    map.time = TopicMap::Time::Header;
    for (const Gripper g : {Gripper::Left, Gripper::Right}) {
        TopicMap::GripperTopics &topics = map.grippers[size_t(g)];
        topics.present = true;
        topics.optional = true; // a one-handed session exports one gripper
        topics.clock = M::contactTopic(g);
        for (const bool left : {true, false}) {
            TopicMap::Tip &tip = left ? topics.left : topics.right;
            tip.present = true;
            tip.topic = M::wrenchTopic(g, left);
            tip.force = QStringLiteral("wrench.force");
            tip.normalAxis = TopicMap::Axis::PlusY;
            tip.hasCount = true;
            tip.count = {M::contactTopic(g),
                         left ? QStringLiteral("left.n") : QStringLiteral("right.n")};
        }
    }
    return map;
}

} // namespace semhap
