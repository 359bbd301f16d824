// SPDX-License-Identifier: MIT
#include "routernodetype.h"

namespace semhap {

QString portTypeName(PortType type)
{
    switch (type) {
    case PortType::Event:
        return QStringLiteral("event");
    case PortType::Signal:
        return QStringLiteral("signal");
    case PortType::Voice:
        return QStringLiteral("voice");
    }
    return QString();
}

const PortSpec *RouterNodeType::input(const QString &name) const
{
    for (const PortSpec &port : inputs) {
        if (port.name == name)
            return &port;
    }
    return nullptr;
}

const PortSpec *RouterNodeType::output(const QString &name) const
{
    for (const PortSpec &port : outputs) {
        if (port.name == name)
            return &port;
    }
    return nullptr;
}

const std::vector<RouterNodeType> &routerNodeTypes()
{
    static const std::vector<RouterNodeType> types = [] {
        const PortSpec eventsOut{QStringLiteral("events"), PortType::Event, true};
        const PortSpec in{QStringLiteral("in"), PortType::Event, true};
        const PortSpec out{QStringLiteral("out"), PortType::Event, true};
        const QString gripper = QStringLiteral("gripper");
        const QString minDuration = QStringLiteral("minDuration");
        const QString hysteresis = QStringLiteral("hysteresis");
        const PortSpec signalIn{QStringLiteral("in"), PortType::Signal, false};
        const PortSpec value{QStringLiteral("value"), PortType::Signal, true};
        return std::vector<RouterNodeType>{
            {QStringLiteral("force"),
             QStringLiteral("Force detector (Algorithm 1): grasp and break messages from F"),
             {},
             {eventsOut},
             {gripper, QStringLiteral("grasp"), QStringLiteral("break"), QStringLiteral("max"),
              hysteresis, minDuration}},
            {QStringLiteral("slip"),
             QStringLiteral("Slip detector (Algorithm 2): grasp and slip messages from N"),
             {},
             {eventsOut},
             {gripper, QStringLiteral("grasp"), QStringLiteral("loss"), QStringLiteral("min"),
              hysteresis, minDuration}},
            {QStringLiteral("signal"),
             QStringLiteral("A continuous quantity of a gripper's contact frames (friction: "
                            "tangential over normal force over mu, 1 at the cone's edge)"),
             {},
             {value},
             {gripper, QStringLiteral("quantity"), QStringLiteral("mu")}},
            {QStringLiteral("derivative"),
             QStringLiteral("The time derivative of a signal, smoothed over tau seconds"),
             {signalIn},
             {value},
             {QStringLiteral("tau")}},
            {QStringLiteral("predict"),
             QStringLiteral("A signal extrapolated over a horizon (default: the downstream "
                            "devices' delay plus the reaction time)"),
             {signalIn},
             {value},
             {QStringLiteral("horizon"), QStringLiteral("tau")}},
            {QStringLiteral("threshold"),
             QStringLiteral("A detector on a signal: its message is active while the signal is "
                            "beyond level, toward full, with intensity growing to full"),
             {signalIn},
             {eventsOut},
             {gripper, QStringLiteral("message"), QStringLiteral("level"), QStringLiteral("full"),
              hysteresis, minDuration}},
            {QStringLiteral("filter"),
             QStringLiteral("Passes the messages that match by message, category and gripper"),
             {in},
             {out},
             {QStringLiteral("message"), QStringLiteral("category"), gripper}},
            {QStringLiteral("gate"),
             QStringLiteral("Passes its input only while the control has no active message "
                            "(block) or while it has one (open)"),
             {in, {QStringLiteral("control"), PortType::Event, true}},
             {out},
             {QStringLiteral("mode")}},
            {QStringLiteral("hysteresis"),
             QStringLiteral("Holds ends back for a while and drops small intensity changes"),
             {in},
             {out},
             {QStringLiteral("hold"), QStringLiteral("band")}},
            {QStringLiteral("curve"),
             QStringLiteral("Maps intensity through a piecewise-linear curve"),
             {in},
             {out},
             {QStringLiteral("points")}},
            {QStringLiteral("pattern"),
             QStringLiteral("Plays a pattern while any of its messages is active; one signal "
                            "input per pattern parameter"),
             {{QStringLiteral("events"), PortType::Event, true}},
             {{QStringLiteral("out"), PortType::Voice, true}},
             {QStringLiteral("pattern"), QStringLiteral("channels")}},
            {QStringLiteral("proportional"),
             QStringLiteral("Drives channels with clip(signal / ref, 0, 1)"),
             {{QStringLiteral("in"), PortType::Signal, false}},
             {{QStringLiteral("out"), PortType::Voice, true}},
             {QStringLiteral("ref"), QStringLiteral("channels")}},
            {QStringLiteral("device"),
             QStringLiteral("A device instance: mixes its voices into frames at its rate"),
             {{QStringLiteral("in"), PortType::Voice, true}},
             {},
             {QStringLiteral("model"), QStringLiteral("policy")}},
        };
    }();
    return types;
}

const RouterNodeType *routerNodeType(const QString &type)
{
    for (const RouterNodeType &t : routerNodeTypes()) {
        if (t.type == type)
            return &t;
    }
    return nullptr;
}

} // namespace semhap
