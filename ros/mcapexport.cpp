// SPDX-License-Identifier: MIT
#include "mcapexport.h"

#include "cdrwriter.h"
#include "mcapwriter.h"
#include "rostypes.h"
#include "routergraph.h"
#include "semhapmessages.h"
#include "sessionreader.h"

#include <QJsonDocument>

#include <cmath>
#include <map>

namespace semhap {

namespace {

const QLatin1String Cdr("cdr");
const QLatin1String Ros2Msg("ros2msg");
using M = SemhapMessages;

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
    const auto channel = [&](std::uint16_t schemaId, const QString &topic) {
        const auto it = channels.find(topic);
        return it != channels.end() ? it->second
                                    : channels[topic] = mcap.addChannel(schemaId, topic, Cdr);
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
            mcap.addMessage(lazy(hand.contact, contactSchema,
                                 [&] { return M::contactTopic(frame.gripper); }),
                            logTime(frame.t), cdr.bytes());
            for (const bool left : {true, false}) {
                M::wrench(cdr, stamp(frame.t), frame, left);
                mcap.addMessage(lazy(hand.wrench[left ? 0 : 1], wrenchSchema,
                                     [&] { return M::wrenchTopic(frame.gripper, left); }),
                                logTime(frame.t), cdr.bytes());
            }
            return mcap.error().isEmpty();
        },
        error);
    ok = ok && session.readEvents(
                   [&](const SemanticEvent &e) {
                       M::event(cdr, stamp(e.t), e, session.nodeNames().value(e.node));
                       mcap.addMessage(events, logTime(e.t), cdr.bytes());
                       return mcap.error().isEmpty();
                   },
                   error);
    ok = ok && session.readDeviceFrames(
                   [&](const DeviceFrame &f) {
                       M::device(cdr, stamp(f.t), f, session.deviceNames().value(f.device),
                                 models.value(f.device), channelNames[size_t(f.device)]);
                       mcap.addMessage(devices[size_t(f.device)], logTime(f.t), cdr.bytes());
                       return mcap.error().isEmpty();
                   },
                   error);
    ok = ok && session.readHandCommands(
                   [&](const HandCommand &h) {
                       M::input(cdr, stamp(h.t), h);
                       mcap.addMessage(
                           lazy(hands[size_t(h.hand)].input, inputSchema,
                                [&] { return M::inputTopic(h.hand); }),
                           logTime(h.t), cdr.bytes());
                       return mcap.error().isEmpty();
                   },
                   error);
    if (!ok) {
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
