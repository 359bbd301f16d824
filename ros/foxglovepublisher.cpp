// SPDX-License-Identifier: MIT
#include "foxglovepublisher.h"

#include "deviceframe.h"
#include "foxgloveserver.h"
#include "handcommand.h"
#include "rostypes.h"
#include "router.h"
#include "semanticevent.h"
#include "semhapmessages.h"

#include <algorithm>
#include <cmath>

namespace semhap {

using M = SemhapMessages;

FoxglovePublisher::FoxglovePublisher(FoxgloveServer &server, const Router &router,
                                     const ActorTable &actors, std::int64_t origin)
    : m_server(server), m_actors(actors), m_origin(origin), m_nodes(router.nodeIds())
{
    channel(m_events, M::EventType, M::eventsTopic());
    const Player &player = router.player();
    for (int d = 0; d < player.deviceCount(); ++d) {
        Band band;
        band.name = player.deviceName(d);
        band.model = player.deviceModel(d).name();
        for (const QString &c : player.deviceModel(d).channelNames())
            band.channels.push_back(c.toUtf8());
        channel(band.channel, M::DeviceType, M::deviceTopic(band.name));
        m_bands.push_back(std::move(band));
    }
}

int FoxglovePublisher::channel(int &id, const char *type, const QString &topic)
{
    if (id < 0) {
        const QString name = QLatin1String(type);
        id = m_server.addChannel(topic, name, RosTypes::schema(name));
    }
    return id;
}

std::uint64_t FoxglovePublisher::stamp(double t) const
{
    return std::uint64_t(std::max<std::int64_t>(0, m_origin + std::llround(t * 1e9)));
}

void FoxglovePublisher::advertise(Gripper gripper)
{
    Hand &hand = m_hands[size_t(gripper)];
    channel(hand.contact, M::ContactType, M::contactTopic(gripper));
    for (const bool left : {true, false})
        channel(hand.wrench[left ? 0 : 1], M::WrenchType, M::wrenchTopic(gripper, left));
}

void FoxglovePublisher::onContactFrame(const ContactFrame &frame)
{
    Hand &hand = m_hands[size_t(frame.gripper)];
    const std::uint64_t ns = stamp(frame.t);
    M::contact(m_cdr, std::int64_t(ns), frame, m_actors);
    m_server.publish(channel(hand.contact, M::ContactType, M::contactTopic(frame.gripper)), ns,
                     m_cdr.bytes());
    for (const bool left : {true, false}) {
        M::wrench(m_cdr, std::int64_t(ns), frame, left);
        m_server.publish(
            channel(hand.wrench[left ? 0 : 1], M::WrenchType, M::wrenchTopic(frame.gripper, left)),
            ns, m_cdr.bytes());
    }
}

void FoxglovePublisher::onEvent(const SemanticEvent &event)
{
    const std::uint64_t ns = stamp(event.t);
    M::event(m_cdr, std::int64_t(ns), event, m_nodes.value(event.node));
    m_server.publish(m_events, ns, m_cdr.bytes());
}

void FoxglovePublisher::onDeviceFrame(const DeviceFrame &frame)
{
    if (frame.device < 0 || size_t(frame.device) >= m_bands.size())
        return;
    const Band &band = m_bands[size_t(frame.device)];
    const std::uint64_t ns = stamp(frame.t);
    M::device(m_cdr, std::int64_t(ns), frame, band.name, band.model, band.channels);
    m_server.publish(band.channel, ns, m_cdr.bytes());
}

void FoxglovePublisher::onHandCommand(const HandCommand &command)
{
    const std::uint64_t ns = stamp(command.t);
    M::input(m_cdr, std::int64_t(ns), command);
    m_server.publish(
        channel(m_hands[size_t(command.hand)].input, M::InputType, M::inputTopic(command.hand)),
        ns, m_cdr.bytes());
}

} // namespace semhap
