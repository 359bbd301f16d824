// SPDX-License-Identifier: MIT
#include "mcapexport.h"

#include "cdrwriter.h"
#include "mcapwriter.h"
#include "nametable.h"
#include "rostypes.h"
#include "routergraph.h"
#include "semanticevent.h"
#include "sessionreader.h"

#include <QJsonDocument>

#include <cmath>
#include <map>

namespace semhap {

namespace {

const QLatin1String Cdr("cdr");
const QLatin1String Ros2Msg("ros2msg");

/** A header: the stamp and the frame it names. */
void header(CdrWriter &cdr, std::int64_t ns, const QString &frame)
{
    cdr.time(ns);
    cdr.string(frame.toUtf8());
}

void fingertip(CdrWriter &cdr, const Fingertip &tip, const ActorTable &actors)
{
    cdr.float64(tip.f);
    cdr.int32(tip.n);
    cdr.string(tip.actor >= 0 ? actors.name(tip.actor).toUtf8() : QByteArray());
    cdr.boolean(tip.hasFxyz);
    for (double c : tip.fxyz)
        cdr.float64(tip.hasFxyz ? c : 0.0);
    cdr.float64(tip.mu);
}

} // namespace

QString McapExport::contactTopic(Gripper gripper)
{
    return QStringLiteral("/semhap/%1/contact").arg(gripperName(gripper));
}

QString McapExport::wrenchTopic(Gripper gripper, bool leftTip)
{
    return QStringLiteral("/semhap/%1/%2/wrench")
        .arg(gripperName(gripper), leftTip ? QStringLiteral("left") : QStringLiteral("right"));
}

QString McapExport::eventsTopic()
{
    return QStringLiteral("/semhap/events");
}

QString McapExport::deviceTopic(const QString &device)
{
    return QStringLiteral("/semhap/devices/") + device;
}

QString McapExport::inputTopic(Gripper hand)
{
    return QStringLiteral("/semhap/%1/input").arg(gripperName(hand));
}

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
    const std::uint16_t contactSchema = schema("semhap_msgs/msg/ContactFrame");
    const std::uint16_t wrenchSchema = schema("geometry_msgs/msg/WrenchStamped");
    const std::uint16_t eventSchema = schema("semhap_msgs/msg/SemanticEvent");
    const std::uint16_t deviceSchema = schema("semhap_msgs/msg/DeviceFrame");
    const std::uint16_t inputSchema = schema("semhap_msgs/msg/HandCommand");
    // A gripper's and a hand's channels come with their first message: a one-handed
    // session shows no empty topics.
    std::map<QString, std::uint16_t> channels;
    const auto channel = [&](std::uint16_t schemaId, const QString &topic) {
        const auto it = channels.find(topic);
        return it != channels.end() ? it->second
                                    : channels[topic] = mcap.addChannel(schemaId, topic, Cdr);
    };
    const std::uint16_t events = mcap.addChannel(eventSchema, eventsTopic(), Cdr);
    std::vector<std::uint16_t> devices;
    QStringList models;
    std::vector<std::vector<QByteArray>> channelNames; // per device, as UTF-8, made once
    RouterGraph graph;
    LoadError routerError;
    const bool hasGraph = session.routerGraph(&graph, &routerError);
    for (const QString &device : session.deviceNames()) {
        devices.push_back(mcap.addChannel(deviceSchema, deviceTopic(device), Cdr));
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
    // Each gripper's and hand's names and channels, looked up once per gripper, not per row.
    struct Hand
    {
        QString name;
        int contact = -1, input = -1;
        std::array<int, 2> wrench{-1, -1};
    };
    std::array<Hand, 2> hands;
    for (const Gripper g : {Gripper::Left, Gripper::Right})
        hands[size_t(g)].name = gripperName(g);
    const auto lazy = [&](int &id, std::uint16_t schemaId, const QString &topic) {
        if (id < 0)
            id = channel(schemaId, topic);
        return std::uint16_t(id);
    };

    CdrWriter cdr;
    const ActorTable &actors = session.actors();
    bool ok = session.readContactFrames(
        [&](const ContactFrame &frame, double) {
            Hand &hand = hands[size_t(frame.gripper)];
            const QString &name = hand.name;
            cdr.clear();
            header(cdr, stamp(frame.t), name);
            fingertip(cdr, frame.left, actors);
            fingertip(cdr, frame.right, actors);
            cdr.sequence(std::uint32_t(frame.signalValues.size()));
            for (const SignalValue &s : frame.signalValues)
                cdr.string(signalNames().name(s.id).toUtf8());
            cdr.sequence(std::uint32_t(frame.signalValues.size()));
            for (const SignalValue &s : frame.signalValues)
                cdr.float64(s.value);
            mcap.addMessage(lazy(hand.contact, contactSchema, contactTopic(frame.gripper)),
                            logTime(frame.t), cdr.bytes());
            for (const bool left : {true, false}) {
                const Fingertip &tip = left ? frame.left : frame.right;
                cdr.clear();
                header(cdr, stamp(frame.t),
                       name + (left ? QStringLiteral("_left") : QStringLiteral("_right")));
                // Without a resultant, the force lies along the grip axis.
                const std::array<double, 3> force =
                    tip.hasFxyz ? tip.fxyz : std::array<double, 3>{0.0, tip.f, 0.0};
                for (double c : force)
                    cdr.float64(c);
                for (int i = 0; i < 3; ++i)
                    cdr.float64(0.0); // no torque is measured
                mcap.addMessage(lazy(hand.wrench[left ? 0 : 1], wrenchSchema,
                                     wrenchTopic(frame.gripper, left)),
                                logTime(frame.t), cdr.bytes());
            }
            return mcap.error().isEmpty();
        },
        error);
    ok = ok && session.readEvents(
                   [&](const SemanticEvent &e) {
                       cdr.clear();
                       header(cdr, stamp(e.t), gripperName(e.gripper));
                       cdr.string(session.nodeNames().value(e.node).toUtf8());
                       cdr.string(detectorKindName(e.detector).toUtf8());
                       cdr.string(messageName(e.message).toUtf8());
                       cdr.string(categoryName(e.category).toUtf8());
                       cdr.string(eventPhaseName(e.phase).toUtf8());
                       cdr.float64(e.intensity);
                       mcap.addMessage(events, logTime(e.t), cdr.bytes());
                       return mcap.error().isEmpty();
                   },
                   error);
    ok = ok && session.readDeviceFrames(
                   [&](const DeviceFrame &f) {
                       cdr.clear();
                       header(cdr, stamp(f.t), session.deviceNames().value(f.device));
                       cdr.string(models.value(f.device).toUtf8());
                       const std::vector<QByteArray> &names = channelNames[size_t(f.device)];
                       cdr.sequence(std::uint32_t(f.channelCount));
                       for (int c = 0; c < f.channelCount; ++c)
                           cdr.string(size_t(c) < names.size() ? names[size_t(c)] : QByteArray());
                       cdr.sequence(std::uint32_t(f.channelCount));
                       for (int c = 0; c < f.channelCount; ++c)
                           cdr.float64(f.values[size_t(c)]);
                       mcap.addMessage(devices[size_t(f.device)], logTime(f.t), cdr.bytes());
                       return mcap.error().isEmpty();
                   },
                   error);
    ok = ok && session.readHandCommands(
                   [&](const HandCommand &h) {
                       cdr.clear();
                       header(cdr, stamp(h.t), gripperName(h.hand));
                       for (double p : h.target.pos)
                           cdr.float64(p);
                       // geometry_msgs/Quaternion is x, y, z, w; a Pose's is w, x, y, z.
                       cdr.float64(h.target.quat[1]);
                       cdr.float64(h.target.quat[2]);
                       cdr.float64(h.target.quat[3]);
                       cdr.float64(h.target.quat[0]);
                       cdr.float64(h.grip);
                       mcap.addMessage(
                           lazy(hands[size_t(h.hand)].input, inputSchema, inputTopic(h.hand)),
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
        topics.clock = contactTopic(g);
        for (const bool left : {true, false}) {
            TopicMap::Tip &tip = left ? topics.left : topics.right;
            tip.present = true;
            tip.topic = wrenchTopic(g, left);
            tip.force = QStringLiteral("wrench.force");
            tip.normalAxis = TopicMap::Axis::PlusY;
            tip.hasCount = true;
            tip.count = {contactTopic(g),
                         left ? QStringLiteral("left.n") : QStringLiteral("right.n")};
        }
    }
    return map;
}

} // namespace semhap
