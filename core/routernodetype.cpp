// SPDX-License-Identifier: MIT
#include "routernodetype.h"

#include "detectorparams.h"
#include "forcedetector.h"
#include "player.h"
#include "routernodes.h"
#include "slipdetector.h"

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

RouterNodeType::Role RouterNodeType::role() const
{
    if (inputs.empty())
        return Role::Source;
    if (outputs.empty())
        return Role::Device;
    return outputs.front().type == PortType::Voice ? Role::Voices : Role::Logic;
}

const ParamSpec *RouterNodeType::param(const QString &name) const
{
    return findParamSpec(params, name);
}

namespace {

QStringList builtinMessageNames()
{
    return {messageName(Message::Grasp), messageName(Message::Break), messageName(Message::Slip)};
}

QStringList categoryNames()
{
    return {categoryName(Category::Confirmation), categoryName(Category::Exception)};
}

ParamSpec messageParam(const QString &help)
{
    return ParamSpec::choice(QStringLiteral("message"), builtinMessageNames(), QString(), help)
        .orNewName();
}

ParamSpec categoryParam()
{
    return ParamSpec::choice(QStringLiteral("category"), categoryNames(), QString(),
                             QStringLiteral("Confirmation or exception; absent: the built-in "
                                            "message's (a new message needs one)"))
        .computed();
}

QStringList gripperNames()
{
    return {gripperName(Gripper::Left), gripperName(Gripper::Right)};
}

ParamSpec gripperParam()
{
    return ParamSpec::choice(QStringLiteral("gripper"), gripperNames(), QString(),
                             QStringLiteral("The gripper whose contact frames it reads"));
}

// A detector's parameters: the gripper it watches, then the detector's own.
std::vector<ParamSpec> detectorParams(std::vector<ParamSpec> own)
{
    own.insert(own.begin(), gripperParam());
    return own;
}

ParamSpec channelsParam()
{
    return ParamSpec::of(QStringLiteral("channels"), ParamKind::Channels, ParamAbsent::Default,
                         QStringLiteral("The device channels it drives; absent: the pattern's "
                                        "own (a one-track pattern may be remapped)"));
}

ParamSpec tauParam()
{
    return ParamSpec::number(QStringLiteral("tau"), DefaultSlopeTau, QStringLiteral("s"),
                             QStringLiteral("How far back the slope is taken: longer is "
                                            "smoother and later"))
        .atLeast(0);
}

} // namespace

const std::vector<RouterNodeType> &routerNodeTypes()
{
    static const std::vector<RouterNodeType> types = [] {
        const PortSpec eventsOut{QStringLiteral("events"), PortType::Event, true};
        const PortSpec in{QStringLiteral("in"), PortType::Event, true};
        const PortSpec out{QStringLiteral("out"), PortType::Event, true};
        const PortSpec signalIn{QStringLiteral("in"), PortType::Signal, false};
        const PortSpec value{QStringLiteral("value"), PortType::Signal, true};
        const QString seconds = QStringLiteral("s");
        return std::vector<RouterNodeType>{
            {QStringLiteral("force"),
             QStringLiteral("Force detector (Algorithm 1): grasp and break messages from F"),
             {},
             {eventsOut},
             detectorParams(ForceDetector::Params::specs())},
            {QStringLiteral("slip"),
             QStringLiteral("Slip detector (Algorithm 2): grasp and slip messages from N"),
             {},
             {eventsOut},
             detectorParams(SlipDetector::Params::specs())},
            {QStringLiteral("signal"),
             QStringLiteral("A continuous quantity of a gripper's contact frames (friction: "
                            "tangential over normal force over mu, 1 at the cone's edge)"),
             {},
             {value},
             {gripperParam(),
              ParamSpec::of(QStringLiteral("quantity"), ParamKind::Signal, ParamAbsent::Required,
                            QStringLiteral("The quantity it reads: a built-in one, or a signal "
                                           "the frames carry (a scene's, a rig's)"))
                  .withChoices(SignalNode::quantityNames()),
              ParamSpec::number(QStringLiteral("mu"), 0, QString(),
                                QStringLiteral("The friction coefficient of the friction "
                                               "quantities; absent: the frames' own"))
                  .above(0)
                  .computed()}},
            {QStringLiteral("derivative"),
             QStringLiteral("The time derivative of a signal, smoothed over tau seconds"),
             {signalIn},
             {value},
             {tauParam()}},
            {QStringLiteral("predict"),
             QStringLiteral("A signal extrapolated over a horizon (default: the downstream "
                            "devices' delay plus the reaction time)"),
             {signalIn},
             {value},
             {ParamSpec::number(QStringLiteral("horizon"), 0, seconds,
                                QStringLiteral("How far ahead it extrapolates; absent: the "
                                               "slowest downstream device's delay plus the "
                                               "reaction time"))
                  .atLeast(0)
                  .computed(),
              tauParam()}},
            {QStringLiteral("threshold"),
             QStringLiteral("A detector on a signal: its message begins when the signal meets "
                            "the condition at the begin level and ends when it no longer "
                            "meets it at the end level"),
             {signalIn},
             {eventsOut},
             {gripperParam(), messageParam(QStringLiteral("The message it raises")),
              categoryParam(),
              ParamSpec::choice(QStringLiteral("condition"), ThresholdNode::conditionNames(),
                                QStringLiteral("above"),
                                QStringLiteral("When the message is active: the signal above "
                                               "or below a level, inside or outside a "
                                               "[low, high] range")),
              ParamSpec::of(QStringLiteral("begin"), ParamKind::Level, ParamAbsent::Required,
                            QStringLiteral("The level (above, below) or [low, high] range "
                                           "(inside, outside) at which the message begins"))
                  .startingWith(0),
              ParamSpec::of(QStringLiteral("end"), ParamKind::Level, ParamAbsent::Computed,
                            QStringLiteral("The level or range at which an active message "
                                           "ends; absent: begin (no hysteresis)")),
              minDurationSpec(),
              ParamSpec::of(QStringLiteral("intensity"), ParamKind::Level, ParamAbsent::Default,
                            QStringLiteral("[x0, x1]: intensity grows from 0 at x0 to 1 at x1, "
                                           "clipped; absent: 1"))}},
            {QStringLiteral("compose"),
             QStringLiteral("A message made of two: while both inputs have an active message "
                            "(all), either has (any), or a has while b has (while)"),
             {{QStringLiteral("a"), PortType::Event, true},
              {QStringLiteral("b"), PortType::Event, true}},
             {eventsOut},
             {messageParam(QStringLiteral("The message it raises")), categoryParam(),
              ParamSpec::choice(QStringLiteral("mode"), ComposeNode::modeNames(),
                                QStringLiteral("all"),
                                QStringLiteral("all: both active, the lower intensity; any: "
                                               "either, the higher; while: a's, while b is "
                                               "active")),
              ParamSpec::choice(QStringLiteral("gripper"), gripperNames(), QString(),
                                QStringLiteral("The gripper its events name; absent: that of "
                                               "the input message that makes it active"))
                  .computed()}},
            {QStringLiteral("filter"),
             QStringLiteral("Passes the messages that match by message, category and gripper"),
             {in},
             {out},
             {ParamSpec::anyOf(QStringLiteral("message"), builtinMessageNames(),
                               QStringLiteral("The messages it passes"))
                  .orNewName(),
              ParamSpec::anyOf(QStringLiteral("category"), categoryNames(),
                               QStringLiteral("The categories it passes")),
              ParamSpec::anyOf(QStringLiteral("gripper"), gripperNames(),
                               QStringLiteral("The grippers whose messages it passes"))}},
            {QStringLiteral("gate"),
             QStringLiteral("Passes its input only while the control has no active message "
                            "(block) or while it has one (open)"),
             {in, {QStringLiteral("control"), PortType::Event, true}},
             {out},
             {ParamSpec::choice(QStringLiteral("mode"),
                                {QStringLiteral("block"), QStringLiteral("open")},
                                QStringLiteral("block"),
                                QStringLiteral("block: an active control stops the input; "
                                               "open: only an active control lets it through"))}},
            {QStringLiteral("debounce"),
             QStringLiteral("Holds ends back for a while and drops small intensity changes"),
             {in},
             {out},
             {ParamSpec::number(QStringLiteral("hold"), 0, seconds,
                                QStringLiteral("How long an end is held back; a message that "
                                               "comes back meanwhile goes on"))
                  .atLeast(0),
              ParamSpec::number(QStringLiteral("band"), 0, QString(),
                                QStringLiteral("Intensity changes smaller than this are "
                                               "dropped"))
                  .atLeast(0)
                  .atMost(1)}},
            {QStringLiteral("curve"),
             QStringLiteral("Maps intensity through a piecewise-linear curve"),
             {in},
             {out},
             {ParamSpec::of(QStringLiteral("points"), ParamKind::Points, ParamAbsent::Default,
                            QStringLiteral("[x, y] points, x increasing, held constant outside "
                                           "them; absent: intensity passes unchanged"))}},
            {QStringLiteral("pattern"),
             QStringLiteral("Plays a pattern while any of its messages is active; one signal "
                            "input per pattern parameter"),
             {{QStringLiteral("events"), PortType::Event, true}},
             {{QStringLiteral("out"), PortType::Voice, true}},
             {ParamSpec::of(QStringLiteral("pattern"), ParamKind::Pattern, ParamAbsent::Required,
                            QStringLiteral("A built-in or embedded pattern's name, or a "
                                           "pattern file")),
              channelsParam()}},
            {QStringLiteral("proportional"),
             QStringLiteral("Drives channels with clip(signal / ref, 0, 1)"),
             {{QStringLiteral("in"), PortType::Signal, false}},
             {{QStringLiteral("out"), PortType::Voice, true}},
             {ParamSpec::number(QStringLiteral("ref"), 1, QString(),
                                QStringLiteral("The signal value that drives the channels "
                                               "fully"))
                  .above(0),
              channelsParam()}},
            {QStringLiteral("device"),
             QStringLiteral("A device instance: mixes its voices into frames at its rate"),
             {{QStringLiteral("in"), PortType::Voice, true}},
             {},
             {ParamSpec::of(QStringLiteral("model"), ParamKind::Model, ParamAbsent::Required,
                            QStringLiteral("A built-in or embedded device model's name, or a "
                                           "model file")),
              ParamSpec::choice(QStringLiteral("policy"),
                                {Player::mixPolicyName(Player::MixPolicy::Priority),
                                 Player::mixPolicyName(Player::MixPolicy::Max),
                                 Player::mixPolicyName(Player::MixPolicy::Sum)},
                                Player::mixPolicyName(Player::MixPolicy::Priority),
                                QStringLiteral("How voices meeting on a channel combine: the "
                                               "highest priority's, the maximum, or the sum")),
              ParamSpec::choice(QStringLiteral("hand"), gripperNames(), QString(),
                                QStringLiteral("The hand that feels it; absent: the id's first "
                                               "part when that is left or right (left.air), "
                                               "else none (an overlay)"))
                  .computed()}},
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
