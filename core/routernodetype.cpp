// SPDX-License-Identifier: MIT
#include "routernodetype.h"

#include "detectorparams.h"
#include "forcedetector.h"
#include "impactdetector.h"
#include "nodebuilder.h"
#include "player.h"
#include "routernodes.h"
#include "slipdetector.h"

#include <QHash>
#include <QJsonArray>

#include <cmath>

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

const ParamSpec *RouterNodeType::paramOfKind(ParamKind kind) const
{
    for (const ParamSpec &spec : params) {
        if (spec.kind == kind)
            return &spec;
    }
    return nullptr;
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

/** The detector kinds DetectorKind names, at its ids. */
QStringList builtinDetectorKinds()
{
    return {QStringLiteral("force"), QStringLiteral("slip"), QStringLiteral("threshold"),
            QStringLiteral("compose")};
}

// The build functions of the rows below: each reads its node's checked parameters and makes
// the node.

bool buildSignal(NodeBuilder &b)
{
    const QString name = b.param(QStringLiteral("quantity")).toString();
    const Gripper hand = b.gripper();
    SignalNode::Quantity quantity = SignalNode::Quantity::Named;
    int id = -1;
    if (!SignalNode::quantityFromName(name, &quantity)) {
        const QStringList &known = b.context().signalNames[size_t(hand)];
        if (b.context().knowsSignals && !known.contains(name))
            return b.fail(QStringLiteral("quantity"),
                          QStringLiteral("the %1 gripper's frames carry no signal '%2' (%3)")
                              .arg(gripperName(hand), name,
                                   known.isEmpty() ? QStringLiteral("they carry none")
                                                   : QStringLiteral("they carry: ") +
                                                         known.join(QStringLiteral(", "))));
        id = signalNames().intern(name);
        if (id < 0)
            return b.fail(QStringLiteral("quantity"),
                          QStringLiteral("more signal names than the %1 semhap can hold")
                              .arg(NameTable::Capacity));
    }
    return b.adopt(
        std::make_unique<SignalNode>(hand, quantity, b.number(QStringLiteral("mu")), id));
}

bool buildDerivative(NodeBuilder &b)
{
    return b.adopt(std::make_unique<DerivativeNode>(b.number(QStringLiteral("tau"))));
}

bool buildPredict(NodeBuilder &b)
{
    auto predict = std::make_unique<PredictNode>(b.number(QStringLiteral("tau")));
    const QJsonValue horizon = b.param(QStringLiteral("horizon"));
    // Absent: the compiler works it out once the devices downstream are known.
    predict->setHorizon(horizon.isUndefined() ? -1.0 : horizon.toDouble());
    return b.adopt(std::move(predict));
}

bool buildThreshold(NodeBuilder &b)
{
    using Condition = ThresholdNode::Condition;
    ThresholdNode::Params p;
    if (!b.messageOf(&p.message, &p.category))
        return false;
    p.condition = Condition(
        ThresholdNode::conditionNames().indexOf(b.param(QStringLiteral("condition")).toString()));
    const bool range = p.condition == Condition::Inside || p.condition == Condition::Outside;
    const QString begin = QStringLiteral("begin");
    const QString end = QStringLiteral("end");
    if (!b.level(begin, range, &p.begin, &p.beginHigh))
        return false;
    if (b.param(end).isUndefined()) {
        p.end = p.begin;
        p.endHigh = p.beginHigh;
    } else if (!b.level(end, range, &p.end, &p.endHigh)) {
        return false;
    }
    // The end level lies on the far side of the begin level, or the message would end as
    // it begins.
    bool crossed = false;
    switch (p.condition) {
    case Condition::Above:
        crossed = p.end > p.begin;
        break;
    case Condition::Below:
        crossed = p.end < p.begin;
        break;
    case Condition::Inside:
        crossed = p.end > p.begin || p.endHigh < p.beginHigh;
        break;
    case Condition::Outside:
        crossed = p.end < p.begin || p.endHigh > p.beginHigh;
        break;
    }
    if (crossed) {
        static const char *const rules[] = {
            "above: end must not be above begin", "below: end must not be below begin",
            "inside: the end range must contain the begin range",
            "outside: the end range must lie within the begin range"};
        return b.fail(end, QStringLiteral("begin/end levels crossed (%1)")
                               .arg(QLatin1String(rules[int(p.condition)])));
    }
    p.minDuration = b.number(QStringLiteral("minDuration"));
    const QJsonValue intensity = b.param(QStringLiteral("intensity"));
    if (!intensity.isUndefined()) {
        const QJsonArray pair = intensity.toArray();
        if (!intensity.isArray() || pair.at(0).toDouble() == pair.at(1).toDouble())
            return b.fail(QStringLiteral("intensity"),
                          QStringLiteral("must be [x0, x1] with x0 and x1 apart: the input at "
                                         "intensity 0 and at 1"));
        p.mapsIntensity = true;
        p.intensityFrom = pair.at(0).toDouble();
        p.intensityTo = pair.at(1).toDouble();
    }
    return b.adopt(std::make_unique<ThresholdNode>(b.node(), b.gripper(), p));
}

bool buildCompose(NodeBuilder &b)
{
    ComposeNode::Params p;
    if (!b.messageOf(&p.message, &p.category))
        return false;
    p.mode = ComposeNode::Mode(
        ComposeNode::modeNames().indexOf(b.param(QStringLiteral("mode")).toString()));
    p.fixedGripper = !b.param(QStringLiteral("gripper")).isUndefined();
    if (p.fixedGripper)
        p.gripper = b.gripper();
    return b.adopt(std::make_unique<ComposeNode>(b.node(), p));
}

bool buildFilter(NodeBuilder &b)
{
    std::vector<Message> messages;
    const QJsonValue value = b.param(QStringLiteral("message"));
    for (const QJsonValue &item : value.isArray() ? value.toArray() : QJsonArray{value}) {
        Message message = Message::Grasp;
        if (item.isString() && !messageFromName(item.toString(), &message))
            return b.fail(QStringLiteral("message"),
                          QStringLiteral("more new messages than the %1 semhap can name")
                              .arg(NameTable::Capacity));
        if (item.isString())
            messages.push_back(message);
    }
    return b.adopt(std::make_unique<FilterNode>(std::move(messages),
                                                b.choiceBits(QStringLiteral("category")),
                                                b.choiceBits(QStringLiteral("gripper"))));
}

bool buildGate(NodeBuilder &b)
{
    return b.adopt(std::make_unique<GateNode>(b.param(QStringLiteral("mode")).toString() ==
                                              QLatin1String("open")));
}

bool buildDebounce(NodeBuilder &b)
{
    return b.adopt(std::make_unique<DebounceNode>(b.number(QStringLiteral("hold")),
                                                  b.number(QStringLiteral("band"))));
}

bool buildCurve(NodeBuilder &b)
{
    const QJsonValue points = b.param(QStringLiteral("points"));
    if (points.isUndefined())
        return b.adopt(std::make_unique<CurveNode>(Curve()));
    std::vector<std::pair<double, double>> list;
    for (const QJsonValue &point : points.toArray())
        list.emplace_back(point.toArray().at(0).toDouble(), point.toArray().at(1).toDouble());
    return b.adopt(std::make_unique<CurveNode>(Curve::points(std::move(list))));
}

bool buildPattern(NodeBuilder &b)
{
    return b.playPattern();
}

bool buildProportional(NodeBuilder &b)
{
    return b.adopt(std::make_unique<ProportionalNode>(b.number(QStringLiteral("ref"))));
}

bool buildDevice(NodeBuilder &b)
{
    return b.drive();
}

// The upgrades of older files' parameters (semhap 1.0's spellings).

/** A threshold had one `level`, a `hysteresis` back from it and intensity growing to `full`
 * (which also set the direction). */
void upgradeThreshold(QJsonObject &params, const UpgradeWarning &warn)
{
    const QJsonValue level = params.value(QLatin1String("level"));
    const QJsonValue full = params.value(QLatin1String("full"));
    const QJsonValue hysteresis = params.value(QLatin1String("hysteresis"));
    if (!level.isDouble() || full.toDouble(1.0) == level.toDouble() ||
        params.contains(QLatin1String("begin")))
        return;
    const double at = level.toDouble();
    const double to = full.toDouble(1.0);
    const double relief = std::abs(hysteresis.toDouble(0.0));
    params.insert(QStringLiteral("condition"),
                  to > at ? QStringLiteral("above") : QStringLiteral("below"));
    params.insert(QStringLiteral("begin"), at);
    if (relief > 0.0)
        params.insert(QStringLiteral("end"), to > at ? at - relief : at + relief);
    params.insert(QStringLiteral("intensity"), QJsonArray{at, to});
    for (const char *old : {"level", "full", "hysteresis"})
        params.remove(QLatin1String(old));
    warn(QStringLiteral("/params"),
         QStringLiteral("deprecated: threshold parameters \"level\", \"full\" and "
                        "\"hysteresis\" are now \"condition\", \"begin\", \"end\" and "
                        "\"intensity\" (read as those)"));
}

/** A fingertip's quantities were `f.left` where the contact frame says `left.f`. */
void upgradeSignal(QJsonObject &params, const UpgradeWarning &warn)
{
    static const QHash<QString, QString> quantities{
        {QStringLiteral("f.left"), QStringLiteral("left.f")},
        {QStringLiteral("f.right"), QStringLiteral("right.f")},
        {QStringLiteral("n.left"), QStringLiteral("left.n")},
        {QStringLiteral("n.right"), QStringLiteral("right.n")},
        {QStringLiteral("friction.left"), QStringLiteral("left.friction")},
        {QStringLiteral("friction.right"), QStringLiteral("right.friction")}};
    const QString quantity = params.value(QLatin1String("quantity")).toString();
    if (!quantities.contains(quantity))
        return;
    params.insert(QStringLiteral("quantity"), quantities.value(quantity));
    warn(QStringLiteral("/params/quantity"),
         deprecatedSpelling(QStringLiteral("quantity"), quantity, quantities.value(quantity)));
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
        std::vector<RouterNodeType> rows{
            {QStringLiteral("force"),
             QStringLiteral("Force detector (Algorithm 1): grasp and break messages from F"),
             {},
             {eventsOut},
             detectorParams(ForceDetector::Params::specs()),
             &buildDetector<ForceDetector>,
             true},
            {QStringLiteral("slip"),
             QStringLiteral("Slip detector (Algorithm 2): grasp and slip messages from N"),
             {},
             {eventsOut},
             detectorParams(SlipDetector::Params::specs()),
             &buildDetector<SlipDetector>,
             true},
            {QStringLiteral("impact"),
             QStringLiteral("Impact detector: an impact message when F rises faster than a "
                            "rate, as when the hand strikes something"),
             {},
             {eventsOut},
             detectorParams(ImpactDetector::Params::specs()),
             &buildDetector<ImpactDetector>,
             true},
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
                  .computed()},
             &buildSignal,
             false,
             {},
             &upgradeSignal},
            {QStringLiteral("derivative"),
             QStringLiteral("The time derivative of a signal, smoothed over tau seconds"),
             {signalIn},
             {value},
             {tauParam()},
             &buildDerivative},
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
              tauParam()},
             &buildPredict},
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
                                           "clipped; absent: 1"))},
             &buildThreshold,
             true,
             {},
             &upgradeThreshold},
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
                  .computed()},
             &buildCompose,
             true},
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
                               QStringLiteral("The grippers whose messages it passes"))},
             &buildFilter},
            {QStringLiteral("gate"),
             QStringLiteral("Passes its input only while the control has no active message "
                            "(block) or while it has one (open)"),
             {in, {QStringLiteral("control"), PortType::Event, true}},
             {out},
             {ParamSpec::choice(QStringLiteral("mode"),
                                {QStringLiteral("block"), QStringLiteral("open")},
                                QStringLiteral("block"),
                                QStringLiteral("block: an active control stops the input; "
                                               "open: only an active control lets it through"))},
             &buildGate},
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
                  .atMost(1)},
             &buildDebounce,
             false,
             {QStringLiteral("hysteresis")}},
            {QStringLiteral("curve"),
             QStringLiteral("Maps intensity through a piecewise-linear curve"),
             {in},
             {out},
             {ParamSpec::of(QStringLiteral("points"), ParamKind::Points, ParamAbsent::Default,
                            QStringLiteral("[x, y] points, x increasing, held constant outside "
                                           "them; absent: intensity passes unchanged"))},
             &buildCurve},
            {QStringLiteral("pattern"),
             QStringLiteral("Plays a pattern while any of its messages is active; one signal "
                            "input per pattern parameter"),
             {{QStringLiteral("events"), PortType::Event, true}},
             {{QStringLiteral("out"), PortType::Voice, true}},
             {ParamSpec::of(QStringLiteral("pattern"), ParamKind::Pattern, ParamAbsent::Required,
                            QStringLiteral("A built-in or embedded pattern's name, or a "
                                           "pattern file")),
              channelsParam()},
             &buildPattern},
            {QStringLiteral("proportional"),
             QStringLiteral("Drives channels with clip(signal / ref, 0, 1)"),
             {{QStringLiteral("in"), PortType::Signal, false}},
             {{QStringLiteral("out"), PortType::Voice, true}},
             {ParamSpec::number(QStringLiteral("ref"), 1, QString(),
                                QStringLiteral("The signal value that drives the channels "
                                               "fully"))
                  .above(0),
              channelsParam()},
             &buildProportional},
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
                  .computed()},
             &buildDevice},
        };
        // The built-in kinds keep their ids (DetectorKind); a new detector takes the next.
        const QStringList builtin = builtinDetectorKinds();
        int next = int(builtin.size());
        for (RouterNodeType &row : rows) {
            if (row.isDetector)
                row.detectorKind = DetectorKind(
                    builtin.contains(row.type) ? int(builtin.indexOf(row.type)) : next++);
        }
        return rows;
    }();
    return types;
}

QString deprecatedSpelling(const QString &what, const QString &old, const QString &now)
{
    return QStringLiteral("deprecated: %1 \"%2\" is now \"%3\" (read as \"%3\")")
        .arg(what, old, now);
}

QStringList detectorKindNames()
{
    static const QStringList names = [] {
        QStringList list = builtinDetectorKinds();
        for (const RouterNodeType &row : routerNodeTypes()) {
            if (row.isDetector && !list.contains(row.type))
                list.append(row.type);
        }
        return list;
    }();
    return names;
}

QString detectorKindName(DetectorKind kind)
{
    const QStringList names = detectorKindNames();
    return int(kind) >= 0 && int(kind) < names.size() ? names[int(kind)] : QString();
}

bool detectorKindFromName(const QString &name, DetectorKind *kind)
{
    const qsizetype index = detectorKindNames().indexOf(name);
    if (index < 0)
        return false;
    *kind = DetectorKind(index);
    return true;
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
