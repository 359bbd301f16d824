// SPDX-License-Identifier: MIT
#include "router.h"

#include "forcedetector.h"
#include "jsonreader.h"
#include "patternlibrary.h"
#include "patternrender.h"
#include "routernodes.h"
#include "routernodetype.h"
#include "slipdetector.h"

#include <QDir>
#include <QHash>
#include <QJsonArray>
#include <QSet>

#include <algorithm>
#include <cmath>
#include <set>

namespace semhap {

namespace {

static_assert(RouterGraph::MaxUpstreamDetectors == ActiveMessages::Capacity / 2,
              "a node tracks two messages per detector it hears");

} // namespace

/** Turns a RouterGraph into a Router, reporting the first problem with node and reason. */
class RouterCompiler
{
public:
    RouterCompiler(const RouterGraph &graph, const RouterContext &context, LoadError *error)
        : m_graph(graph), m_context(context), m_error(error)
    {}

    std::unique_ptr<Router> compile();

private:
    struct NodeInfo
    {
        const RouterNodeType *type = nullptr;
        std::vector<PortSpec> inputs;
        std::vector<int> inputLinks; ///< links into each input port
        PatternPtr pattern;
        QStringList channels; ///< pattern and proportional nodes: explicit channel list
        DeviceModelPtr model;
        Player::MixPolicy policy = Player::MixPolicy::Priority;
        int hand = -1; ///< devices: the Gripper that feels it, -1 for none
    };
    struct ResolvedLink
    {
        int from = -1;
        int fromPort = 0;
        int to = -1;
        int toPort = 0;
        PortType type = PortType::Event;
    };

    bool fail(const QString &pointer, const QString &reason);
    bool failNode(int node, const QString &key, const QString &reason);
    QString nodeLabel(int node) const;

    /** Checks the node's parameters against `specs`: known, well-formed, required ones given. */
    bool checkParams(int node, const std::vector<ParamSpec> &specs);
    /** A checked parameter's value, or its spec's default when absent. */
    QJsonValue param(int node, const QString &key) const;
    double number(int node, const QString &key) const;
    Gripper gripper(int node) const;
    QStringList channels(int node) const;
    /** A filter parameter as a bit set over its choices; absent: 0, which a filter takes as any.
     */
    unsigned choiceBits(int node, const QString &key) const;

    bool buildNode(int node);
    bool buildDetector(int node);
    bool buildPattern(int node);
    bool buildDevice(int node);
    std::unique_ptr<RuntimeNode> buildLogic(int node);
    std::unique_ptr<RuntimeNode> buildThreshold(int node);
    std::unique_ptr<RuntimeNode> buildCompose(int node);
    std::unique_ptr<RuntimeNode> buildSignal(int node);
    /** The message and category of a threshold or compose node; false after failNode. */
    bool messageOf(int node, Message *message, Category *category);
    /** A [low, high] or single-number level parameter; false after failNode. */
    bool level(int node, const QString &key, bool range, double *low, double *high);
    /** The default horizons of predict nodes: downstream devices' delay + reaction time. */
    void setDefaultHorizons();

    PatternPtr findPattern(int node, const QString &name);
    DeviceModelPtr findModel(int node, const QString &name);

    /** The graph's size against the caps (RouterGraph::MaxNodes, MaxLinks, MaxDevices). */
    bool checkSize();
    bool resolveLinks();
    bool checkCycles();
    bool checkFanIn();
    bool wire();
    bool connectVoice(int linkIndex, const ResolvedLink &link);

    const RouterGraph &m_graph;
    RouterContext m_context;
    LoadError *m_error;
    std::vector<NodeInfo> m_info;
    std::vector<ResolvedLink> m_links;
    QHash<QString, int> m_nodeIndex;       ///< node id → index
    std::vector<std::vector<int>> m_out;   ///< per node, the links leaving it
    std::vector<int> m_order;              ///< nodes in topological order (checkCycles)
    QHash<QString, PatternPtr> m_patterns; ///< embedded and loaded patterns by name or path
    QHash<QString, DeviceModelPtr> m_models;
    QHash<int, std::pair<Category, int>> m_categories; ///< message -> category, first node
    std::unique_ptr<Router> m_router;
};

bool RouterCompiler::fail(const QString &pointer, const QString &reason)
{
    *m_error = LoadError::at(m_graph.file, pointer, reason);
    return false;
}

QString RouterCompiler::nodeLabel(int node) const
{
    const RouterNode &n = m_graph.nodes[size_t(node)];
    return QStringLiteral("node '%1' (%2)").arg(n.id, n.type);
}

bool RouterCompiler::failNode(int node, const QString &key, const QString &reason)
{
    QString pointer = jsonPointerChild(QStringLiteral("/nodes"), node);
    if (!key.isEmpty())
        pointer = jsonPointerChild(pointer + QStringLiteral("/params"), key);
    return fail(pointer, nodeLabel(node) + QStringLiteral(": ") + reason);
}

bool RouterCompiler::checkParams(int node, const std::vector<ParamSpec> &specs)
{
    const QJsonObject &params = m_graph.nodes[size_t(node)].params;
    for (auto it = params.begin(); it != params.end(); ++it) {
        const ParamSpec *spec = findParamSpec(specs, it.key());
        QString reason;
        if (!spec)
            return failNode(node, it.key(),
                            QStringLiteral("unknown parameter '%1' (known: %2)")
                                .arg(it.key(), paramSpecNames(specs).join(QStringLiteral(", "))));
        if (!spec->check(it.value(), &reason))
            return failNode(node, it.key(), reason);
    }
    for (const ParamSpec &spec : specs) {
        if (spec.absent == ParamAbsent::Required && !params.contains(spec.name))
            return failNode(node, QString(), spec.missingReason());
    }
    return true;
}

QJsonValue RouterCompiler::param(int node, const QString &key) const
{
    const QJsonValue value = m_graph.nodes[size_t(node)].params.value(key);
    if (!value.isUndefined())
        return value;
    const ParamSpec *spec = m_info[size_t(node)].type->param(key);
    return spec ? spec->defaultValue() : value;
}

double RouterCompiler::number(int node, const QString &key) const
{
    return param(node, key).toDouble();
}

Gripper RouterCompiler::gripper(int node) const
{
    Gripper gripper = Gripper::Right;
    gripperFromName(param(node, QStringLiteral("gripper")).toString(), &gripper);
    return gripper;
}

QStringList RouterCompiler::channels(int node) const
{
    QStringList list;
    for (const QJsonValue &channel : param(node, QStringLiteral("channels")).toArray())
        list.append(channel.toString());
    return list;
}

unsigned RouterCompiler::choiceBits(int node, const QString &key) const
{
    const QJsonValue value = param(node, key);
    const QStringList &choices = m_info[size_t(node)].type->param(key)->choices;
    if (value.isUndefined())
        return 0;
    unsigned bits = 0;
    for (const QJsonValue &item : value.isArray() ? value.toArray() : QJsonArray{value})
        bits |= 1u << unsigned(choices.indexOf(item.toString()));
    return bits;
}

PatternPtr RouterCompiler::findPattern(int node, const QString &name)
{
    // Many nodes may play one pattern: each is found or loaded once.
    if (PatternPtr known = m_patterns.value(name))
        return known;
    QString reason;
    PatternPtr pattern = m_graph.pattern(name, &reason);
    if (!pattern)
        failNode(node, QStringLiteral("pattern"), reason);
    else
        m_patterns.insert(name, pattern);
    return pattern;
}

DeviceModelPtr RouterCompiler::findModel(int node, const QString &name)
{
    if (DeviceModelPtr known = m_models.value(name))
        return known;
    QString reason;
    DeviceModelPtr model = m_graph.model(name, &reason);
    if (!model)
        failNode(node, QStringLiteral("model"), reason);
    else
        m_models.insert(name, model);
    return model;
}

bool RouterCompiler::buildDetector(int node)
{
    const RouterNode &n = m_graph.nodes[size_t(node)];
    QJsonObject params = n.params;
    params.remove(QStringLiteral("gripper"));
    QString key;
    QString reason;
    std::unique_ptr<Detector> detector;
    // The node's own values are checked and kept in the graph; they run fitted to the
    // gripper, like a predict node's horizon to the reaction time.
    const GripperTraits &traits = m_context.grippers[size_t(gripper(node))];
    if (n.type == QLatin1String("force")) {
        ForceDetector::Params p;
        if (!p.read(params, &key, &reason) || !p.validate(&key, &reason))
            return failNode(node, key, reason);
        detector = std::make_unique<ForceDetector>(node, gripper(node), p.fittedTo(traits));
    } else {
        SlipDetector::Params p;
        if (!p.read(params, &key, &reason) || !p.validate(&key, &reason))
            return failNode(node, key, reason);
        detector = std::make_unique<SlipDetector>(node, gripper(node), p.fittedTo(traits));
    }
    auto runtime = std::make_unique<DetectorNode>(std::move(detector));
    m_router->m_detectors.push_back(runtime.get());
    m_router->m_nodes[size_t(node)] = std::move(runtime);
    return true;
}

bool RouterCompiler::buildPattern(int node)
{
    const RouterNode &n = m_graph.nodes[size_t(node)];
    NodeInfo &info = m_info[size_t(node)];
    // The pattern first: its parameters are the node's too.
    const ParamSpec &patternSpec = *info.type->param(QStringLiteral("pattern"));
    const QJsonValue name = n.params.value(patternSpec.name);
    QString reason;
    if (name.isUndefined())
        return failNode(node, QString(), patternSpec.missingReason());
    if (!patternSpec.check(name, &reason))
        return failNode(node, patternSpec.name, reason);
    PatternPtr pattern = findPattern(node, name.toString());
    if (!pattern)
        return false;
    std::vector<ParamSpec> specs = info.type->params;
    RouterGraph::appendPatternParams(*pattern, &specs);
    if (!checkParams(node, specs))
        return false;
    info.channels = channels(node);
    m_router->m_sources[size_t(node)].pattern = pattern;
    if (!info.channels.isEmpty() && pattern->tracks().size() != 1)
        return failNode(node, QStringLiteral("channels"),
                        QStringLiteral("channels can only be remapped for a pattern with one "
                                       "track; '%1' has %2")
                            .arg(pattern->name())
                            .arg(pattern->tracks().size()));

    // Node parameters named after pattern parameters override their defaults: bake them into
    // a variant of the pattern, so voices reset to the node's values.
    QJsonObject json = pattern->toJson();
    QJsonObject defaults = json.value(QStringLiteral("params")).toObject();
    bool overridden = false;
    for (auto it = n.params.begin(); it != n.params.end(); ++it) {
        if (info.type->param(it.key()))
            continue;
        defaults.insert(it.key(), it.value());
        overridden = true;
    }
    if (overridden) {
        json.insert(QStringLiteral("params"), defaults);
        LoadError inner;
        pattern = Pattern::fromJson(json, m_graph.file, &inner);
        if (!pattern)
            return failNode(node, QString(), inner.reason);
    }
    info.pattern = pattern;

    // Port 0 takes events; one signal input per parameter but intensity, which events set.
    info.inputs = info.type->inputs;
    RouterGraph::appendPatternInputs(*pattern, &info.inputs);
    info.inputLinks.assign(info.inputs.size(), 0);
    return true;
}

bool RouterCompiler::buildDevice(int node)
{
    NodeInfo &info = m_info[size_t(node)];
    info.model = findModel(node, param(node, QStringLiteral("model")).toString());
    if (!info.model)
        return false;
    m_router->m_sources[size_t(node)].model = info.model;
    Player::mixPolicyFromName(param(node, QStringLiteral("policy")).toString(), &info.policy);
    const QJsonValue hand = param(node, QStringLiteral("hand"));
    Gripper gripper = Gripper::Right;
    if (gripperFromName(hand.isUndefined()
                            ? m_graph.nodes[size_t(node)].id.section(QLatin1Char('.'), 0, 0)
                            : hand.toString(),
                        &gripper))
        info.hand = int(gripper);
    return true;
}

std::unique_ptr<RuntimeNode> RouterCompiler::buildLogic(int node)
{
    const RouterNode &n = m_graph.nodes[size_t(node)];
    if (n.type == QLatin1String("signal"))
        return buildSignal(node);
    if (n.type == QLatin1String("derivative"))
        return std::make_unique<DerivativeNode>(number(node, QStringLiteral("tau")));
    if (n.type == QLatin1String("predict")) {
        auto predict = std::make_unique<PredictNode>(number(node, QStringLiteral("tau")));
        const QJsonValue horizon = param(node, QStringLiteral("horizon"));
        // Absent: setDefaultHorizons works it out once the devices downstream are known.
        predict->setHorizon(horizon.isUndefined() ? -1.0 : horizon.toDouble());
        return predict;
    }
    if (n.type == QLatin1String("threshold"))
        return buildThreshold(node);
    if (n.type == QLatin1String("compose"))
        return buildCompose(node);
    if (n.type == QLatin1String("filter")) {
        std::vector<Message> messages;
        const QJsonValue value = param(node, QStringLiteral("message"));
        for (const QJsonValue &item : value.isArray() ? value.toArray() : QJsonArray{value}) {
            Message message = Message::Grasp;
            if (item.isString() && !messageFromName(item.toString(), &message)) {
                failNode(node, QStringLiteral("message"),
                         QStringLiteral("more new messages than the %1 semhap can name")
                             .arg(NameTable::Capacity));
                return nullptr;
            }
            if (item.isString())
                messages.push_back(message);
        }
        return std::make_unique<FilterNode>(std::move(messages),
                                            choiceBits(node, QStringLiteral("category")),
                                            choiceBits(node, QStringLiteral("gripper")));
    }
    if (n.type == QLatin1String("gate"))
        return std::make_unique<GateNode>(param(node, QStringLiteral("mode")).toString() ==
                                          QLatin1String("open"));
    if (n.type == QLatin1String("debounce")) {
        auto debounce = std::make_unique<DebounceNode>(number(node, QStringLiteral("hold")),
                                                       number(node, QStringLiteral("band")));
        m_router->m_timed.push_back(debounce.get());
        return debounce;
    }
    if (n.type == QLatin1String("curve")) {
        const QJsonValue points = param(node, QStringLiteral("points"));
        if (points.isUndefined())
            return std::make_unique<CurveNode>(Curve());
        std::vector<std::pair<double, double>> list;
        for (const QJsonValue &point : points.toArray())
            list.emplace_back(point.toArray().at(0).toDouble(), point.toArray().at(1).toDouble());
        return std::make_unique<CurveNode>(Curve::points(std::move(list)));
    }
    // proportional
    m_info[size_t(node)].channels = channels(node);
    return std::make_unique<ProportionalNode>(number(node, QStringLiteral("ref")));
}

std::unique_ptr<RuntimeNode> RouterCompiler::buildSignal(int node)
{
    const QString name = param(node, QStringLiteral("quantity")).toString();
    const Gripper hand = gripper(node);
    SignalNode::Quantity quantity = SignalNode::Quantity::Named;
    int id = -1;
    if (!SignalNode::quantityFromName(name, &quantity)) {
        const QStringList &known = m_context.signalNames[size_t(hand)];
        if (m_context.knowsSignals && !known.contains(name)) {
            failNode(node, QStringLiteral("quantity"),
                     QStringLiteral("the %1 gripper's frames carry no signal '%2' (%3)")
                         .arg(gripperName(hand), name,
                              known.isEmpty() ? QStringLiteral("they carry none")
                                              : QStringLiteral("they carry: ") +
                                                    known.join(QStringLiteral(", "))));
            return nullptr;
        }
        id = signalNames().intern(name);
        if (id < 0) {
            failNode(node, QStringLiteral("quantity"),
                     QStringLiteral("more signal names than the %1 semhap can hold")
                         .arg(NameTable::Capacity));
            return nullptr;
        }
    }
    auto signal =
        std::make_unique<SignalNode>(hand, quantity, number(node, QStringLiteral("mu")), id);
    m_router->m_signals.push_back(signal.get());
    return signal;
}

bool RouterCompiler::messageOf(int node, Message *message, Category *category)
{
    const QString name = param(node, QStringLiteral("message")).toString();
    if (!messageFromName(name, message))
        return failNode(node, QStringLiteral("message"),
                        QStringLiteral("more new messages than the %1 semhap can name")
                            .arg(NameTable::Capacity));
    const QJsonValue given = param(node, QStringLiteral("category"));
    if (given.isUndefined()) {
        if (!isBuiltinMessage(*message))
            return failNode(node, QString(),
                            QStringLiteral("needs \"category\" for the new message '%1': "
                                           "\"confirmation\" or \"exception\"")
                                .arg(name));
        *category = categoryOf(*message);
    } else {
        categoryFromName(given.toString(), category);
    }
    // A message means one thing in a router: the patterns and the plots take its category.
    const auto known = m_categories.constFind(int(*message));
    if (known != m_categories.cend() && known->first != *category)
        return failNode(
            node, QStringLiteral("category"),
            QStringLiteral("'%1' has the category %2 in node '%3': a message has one")
                .arg(name, categoryName(known->first), m_graph.nodes[size_t(known->second)].id));
    if (isBuiltinMessage(*message) && *category != categoryOf(*message))
        return failNode(node, QStringLiteral("category"),
                        QStringLiteral("'%1' has the category %2")
                            .arg(name, categoryName(categoryOf(*message))));
    m_categories.insert(int(*message), {*category, node});
    return true;
}

bool RouterCompiler::level(int node, const QString &key, bool range, double *low, double *high)
{
    const QJsonValue value = param(node, key);
    if (range != value.isArray())
        return failNode(node, key,
                        range ? QStringLiteral("must be a [low, high] range for the condition "
                                               "'%1'")
                                    .arg(param(node, QStringLiteral("condition")).toString())
                              : QStringLiteral("must be a number for the condition '%1'")
                                    .arg(param(node, QStringLiteral("condition")).toString()));
    if (!range) {
        *low = *high = value.toDouble();
        return true;
    }
    *low = value.toArray().at(0).toDouble();
    *high = value.toArray().at(1).toDouble();
    if (!(*low < *high))
        return failNode(node, key,
                        QStringLiteral("empty range: low %1 is not below high %2")
                            .arg(formatNumber(*low), formatNumber(*high)));
    return true;
}

std::unique_ptr<RuntimeNode> RouterCompiler::buildThreshold(int node)
{
    using Condition = ThresholdNode::Condition;
    ThresholdNode::Params p;
    if (!messageOf(node, &p.message, &p.category))
        return nullptr;
    p.condition = Condition(ThresholdNode::conditionNames().indexOf(
        param(node, QStringLiteral("condition")).toString()));
    const bool range = p.condition == Condition::Inside || p.condition == Condition::Outside;
    const QString begin = QStringLiteral("begin");
    const QString end = QStringLiteral("end");
    if (!level(node, begin, range, &p.begin, &p.beginHigh))
        return nullptr;
    if (param(node, end).isUndefined()) {
        p.end = p.begin;
        p.endHigh = p.beginHigh;
    } else if (!level(node, end, range, &p.end, &p.endHigh)) {
        return nullptr;
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
        failNode(node, end,
                 QStringLiteral("begin/end levels crossed (%1)")
                     .arg(QLatin1String(rules[int(p.condition)])));
        return nullptr;
    }
    p.minDuration = number(node, QStringLiteral("minDuration"));
    const QJsonValue intensity = param(node, QStringLiteral("intensity"));
    if (!intensity.isUndefined()) {
        const QJsonArray pair = intensity.toArray();
        if (!intensity.isArray() || pair.at(0).toDouble() == pair.at(1).toDouble()) {
            failNode(node, QStringLiteral("intensity"),
                     QStringLiteral("must be [x0, x1] with x0 and x1 apart: the input at "
                                    "intensity 0 and at 1"));
            return nullptr;
        }
        p.mapsIntensity = true;
        p.intensityFrom = pair.at(0).toDouble();
        p.intensityTo = pair.at(1).toDouble();
    }
    auto threshold = std::make_unique<ThresholdNode>(node, gripper(node), p);
    m_router->m_messageSources.push_back(threshold.get());
    return threshold;
}

std::unique_ptr<RuntimeNode> RouterCompiler::buildCompose(int node)
{
    ComposeNode::Params p;
    if (!messageOf(node, &p.message, &p.category))
        return nullptr;
    p.mode = ComposeNode::Mode(
        ComposeNode::modeNames().indexOf(param(node, QStringLiteral("mode")).toString()));
    const QJsonValue hand = param(node, QStringLiteral("gripper"));
    p.fixedGripper = !hand.isUndefined();
    if (p.fixedGripper)
        p.gripper = gripper(node);
    auto compose = std::make_unique<ComposeNode>(node, p);
    m_router->m_messageSources.push_back(compose.get());
    return compose;
}

void RouterCompiler::setDefaultHorizons()
{
    // The slowest device each node's output reaches, whatever the path (signals, events,
    // voices): in reverse topological order, every node downstream is known first.
    std::vector<double> delay(m_graph.nodes.size(), 0.0);
    for (auto it = m_order.rbegin(); it != m_order.rend(); ++it) {
        const size_t node = size_t(*it);
        if (m_info[node].model)
            delay[node] = m_info[node].model->responseDelay();
        for (int index : m_out[node])
            delay[node] = std::max(delay[node], delay[size_t(m_links[size_t(index)].to)]);
    }
    for (size_t i = 0; i < m_graph.nodes.size(); ++i) {
        auto *predict = dynamic_cast<PredictNode *>(m_router->m_nodes[i].get());
        if (predict && predict->horizon() < 0.0)
            predict->setHorizon(delay[i] + m_context.reactionTime);
    }
}

bool RouterCompiler::buildNode(int node)
{
    const RouterNode &n = m_graph.nodes[size_t(node)];
    NodeInfo &info = m_info[size_t(node)];
    info.type = routerNodeType(n.type);
    if (!info.type) {
        QStringList known;
        for (const RouterNodeType &type : routerNodeTypes())
            known.append(type.type);
        return fail(jsonPointerChild(QStringLiteral("/nodes"), node) + QStringLiteral("/type"),
                    QStringLiteral("node '%1': unknown node type '%2' (known: %3)")
                        .arg(n.id, n.type, known.join(QStringLiteral(", "))));
    }
    info.inputs = info.type->inputs;
    info.inputLinks.assign(info.inputs.size(), 0);

    if (n.type == QLatin1String("pattern"))
        return buildPattern(node);
    if (!checkParams(node, info.type->params))
        return false;
    if (n.type == QLatin1String("force") || n.type == QLatin1String("slip"))
        return buildDetector(node);
    if (n.type == QLatin1String("device"))
        return buildDevice(node);
    std::unique_ptr<RuntimeNode> runtime = buildLogic(node);
    if (!runtime)
        return false;
    m_router->m_nodes[size_t(node)] = std::move(runtime);
    return true;
}

bool RouterCompiler::checkSize()
{
    if (m_graph.nodes.size() > size_t(RouterGraph::MaxNodes))
        return fail(QStringLiteral("/nodes"), QStringLiteral("%1 nodes, more than the %2 a "
                                                             "router may have")
                                                  .arg(m_graph.nodes.size())
                                                  .arg(RouterGraph::MaxNodes));
    if (m_graph.links.size() > size_t(RouterGraph::MaxLinks))
        return fail(QStringLiteral("/links"), QStringLiteral("%1 links, more than the %2 a "
                                                             "router may have")
                                                  .arg(m_graph.links.size())
                                                  .arg(RouterGraph::MaxLinks));
    int devices = 0;
    for (size_t i = 0; i < m_graph.nodes.size(); ++i) {
        if (m_graph.nodes[i].type == QLatin1String("device") &&
            ++devices > RouterGraph::MaxDevices)
            return failNode(int(i), QString(),
                            QStringLiteral("one device more than the %1 a router may drive")
                                .arg(RouterGraph::MaxDevices));
    }
    return true;
}

bool RouterCompiler::resolveLinks()
{
    QSet<QString> seen; // each link once: a second would deliver every message twice
    for (size_t j = 0; j < m_graph.links.size(); ++j) {
        const RouterLink &link = m_graph.links[j];
        const QString where = jsonPointerChild(QStringLiteral("/links"), int(j));
        ResolvedLink r;
        r.from = m_nodeIndex.value(link.from, -1);
        r.to = m_nodeIndex.value(link.to, -1);
        if (r.from < 0)
            return fail(where + QStringLiteral("/from"),
                        QStringLiteral("dangling link: no node '%1'").arg(link.from));
        if (r.to < 0)
            return fail(where + QStringLiteral("/to"),
                        QStringLiteral("dangling link: no node '%1'").arg(link.to));
        const NodeInfo &from = m_info[size_t(r.from)];
        NodeInfo &to = m_info[size_t(r.to)];
        const QString fromPort = link.fromPort.isEmpty() && !from.type->outputs.empty()
                                     ? from.type->outputs.front().name
                                     : link.fromPort;
        const QString toPort =
            link.toPort.isEmpty() && !to.inputs.empty() ? to.inputs.front().name : link.toPort;
        const auto out = std::find_if(from.type->outputs.begin(), from.type->outputs.end(),
                                      [&](const PortSpec &p) { return p.name == fromPort; });
        const auto in = std::find_if(to.inputs.begin(), to.inputs.end(),
                                     [&](const PortSpec &p) { return p.name == toPort; });
        const int linksIntoPort =
            in == to.inputs.end() ? 0 : to.inputLinks[size_t(in - to.inputs.begin())];
        RouterGraph::LinkEnd end = RouterGraph::LinkEnd::Both;
        const QString problem = RouterGraph::portProblem(m_graph.nodes[size_t(r.from)], fromPort,
                                                         m_graph.nodes[size_t(r.to)], to.inputs,
                                                         toPort, linksIntoPort, &end);
        if (!problem.isEmpty())
            return fail(end == RouterGraph::LinkEnd::From ? where + QStringLiteral("/from")
                        : end == RouterGraph::LinkEnd::To ? where + QStringLiteral("/to")
                                                          : where,
                        problem);
        const QString key =
            QStringLiteral("%1\n%2\n%3\n%4").arg(link.from, fromPort, link.to, toPort);
        if (seen.contains(key))
            return fail(where, QStringLiteral("'%1:%2' already feeds '%3:%4'")
                                   .arg(link.from, fromPort, link.to, toPort));
        seen.insert(key);
        r.fromPort = int(out - from.type->outputs.begin());
        r.toPort = int(in - to.inputs.begin());
        r.type = in->type;
        ++to.inputLinks[size_t(r.toPort)];
        m_out[size_t(r.from)].push_back(int(m_links.size()));
        m_links.push_back(r);
    }
    return true;
}

bool RouterCompiler::checkCycles()
{
    // Kahn's algorithm; whatever cannot be ordered sits on a cycle.
    const size_t count = m_graph.nodes.size();
    std::vector<int> incoming(count, 0);
    for (const ResolvedLink &link : m_links)
        ++incoming[size_t(link.to)];
    std::vector<int> ready;
    for (size_t i = 0; i < count; ++i) {
        if (incoming[i] == 0)
            ready.push_back(int(i));
    }
    m_order.clear();
    m_order.reserve(count);
    while (!ready.empty()) {
        const int node = ready.back();
        ready.pop_back();
        m_order.push_back(node);
        for (int index : m_out[size_t(node)]) {
            const int to = m_links[size_t(index)].to;
            if (--incoming[size_t(to)] == 0)
                ready.push_back(to);
        }
    }
    if (m_order.size() == count)
        return true;
    for (size_t i = 0; i < count; ++i) {
        if (incoming[i] > 0)
            return failNode(int(i), QString(), QStringLiteral("is part of a cycle"));
    }
    return true;
}

bool RouterCompiler::checkFanIn()
{
    // Which detectors' messages can reach each node: bounded so nodes never allocate. In
    // topological order every node's set is complete before it passes it on; a set stops
    // growing one past the limit, so the work stays linear in the links.
    const size_t count = m_graph.nodes.size();
    const size_t limit = size_t(RouterGraph::MaxUpstreamDetectors) + 1;
    std::vector<std::vector<int>> upstream(count);
    for (size_t i = 0; i < count; ++i) {
        if (RouterGraph::isDetectorType(m_info[i].type->type))
            upstream[i].push_back(int(i));
    }
    for (int node : m_order) {
        const std::vector<int> &from = upstream[size_t(node)];
        for (int index : m_out[size_t(node)]) {
            const ResolvedLink &link = m_links[size_t(index)];
            if (link.type != PortType::Event)
                continue;
            std::vector<int> &to = upstream[size_t(link.to)];
            for (int d : from) {
                if (to.size() < limit && std::find(to.begin(), to.end(), d) == to.end())
                    to.push_back(d);
            }
        }
    }
    for (size_t i = 0; i < count; ++i) {
        if (upstream[i].size() > size_t(RouterGraph::MaxUpstreamDetectors))
            return failNode(int(i), QString(), RouterGraph::fanInProblem());
    }
    return true;
}

bool RouterCompiler::connectVoice(int linkIndex, const ResolvedLink &link)
{
    const NodeInfo &source = m_info[size_t(link.from)];
    const DeviceModel &model = *m_info[size_t(link.to)].model;
    const QString &deviceId = m_graph.nodes[size_t(link.to)].id;
    const int device = m_router->m_player.deviceIndex(deviceId);
    RuntimeNode *runtime = m_router->m_nodes[size_t(link.from)].get();
    const QString where = jsonPointerChild(QStringLiteral("/links"), linkIndex);

    std::vector<PlayerInput::Route> routes;
    const QString problem =
        RouterGraph::voiceProblem(m_graph.nodes[size_t(link.from)], source.pattern.get(),
                                  source.channels, m_graph.nodes[size_t(link.to)], model, &routes);
    if (!problem.isEmpty())
        return fail(where, problem);
    if (auto *pattern = dynamic_cast<PatternNode *>(runtime)) {
        auto input = std::make_unique<VoiceInput>(source.pattern, device);
        input->routes = std::move(routes);
        m_router->m_player.addInput(device, input.get());
        m_router->m_voices.push_back({link.from, input.get()});
        pattern->voices.push_back(std::move(input));
        return true;
    }
    auto *proportional = static_cast<ProportionalNode *>(runtime);
    auto input = std::make_unique<ProportionalNode::Input>(*proportional);
    input->routes = std::move(routes);
    m_router->m_player.addInput(device, input.get());
    proportional->inputs.push_back(std::move(input));
    return true;
}

bool RouterCompiler::wire()
{
    for (size_t i = 0; i < m_graph.nodes.size(); ++i) {
        if (m_info[i].model)
            m_router->m_player.addDevice(m_graph.nodes[i].id, m_info[i].model, m_info[i].policy);
    }
    // Player indices follow device names, known only once every device is in.
    m_router->m_deviceHands.assign(size_t(m_router->m_player.deviceCount()), -1);
    for (size_t i = 0; i < m_graph.nodes.size(); ++i) {
        if (m_info[i].model)
            m_router->m_deviceHands[size_t(m_router->m_player.deviceIndex(m_graph.nodes[i].id))] =
                m_info[i].hand;
    }
    for (size_t j = 0; j < m_links.size(); ++j) {
        const ResolvedLink &link = m_links[j];
        RuntimeNode *from = m_router->m_nodes[size_t(link.from)].get();
        RuntimeNode *to = m_router->m_nodes[size_t(link.to)].get();
        switch (link.type) {
        case PortType::Event:
            from->eventTargets.push_back({to, link.toPort});
            break;
        case PortType::Signal:
            from->signalTargets.push_back({to, link.toPort});
            break;
        case PortType::Voice:
            if (!connectVoice(int(j), link))
                return false;
            break;
        }
    }
    return true;
}

std::unique_ptr<Router> RouterCompiler::compile()
{
    m_router.reset(new Router);
    m_router->m_graph = m_graph;
    const size_t count = m_graph.nodes.size();
    if (!checkSize())
        return nullptr;
    m_nodeIndex.reserve(qsizetype(count));
    for (size_t i = 0; i < count; ++i)
        m_nodeIndex.insert(m_graph.nodes[i].id, int(i));
    // An embedded pattern or model shadows a built-in of its name; the first of a name wins.
    for (const PatternPtr &pattern : m_graph.patterns) {
        if (!m_patterns.contains(pattern->name()))
            m_patterns.insert(pattern->name(), pattern);
    }
    for (const DeviceModelPtr &model : m_graph.models) {
        if (!m_models.contains(model->name()))
            m_models.insert(model->name(), model);
    }
    m_out.resize(count);
    m_info.resize(count);
    m_router->m_nodes.resize(count);
    m_router->m_sources.resize(count);
    for (size_t i = 0; i < count; ++i) {
        m_router->m_nodeIds.append(m_graph.nodes[i].id);
        if (!buildNode(int(i)))
            return nullptr;
    }
    // Pattern nodes are built once their event input is known to be linked or not.
    if (!resolveLinks() || !checkCycles() || !checkFanIn())
        return nullptr;
    for (size_t i = 0; i < count; ++i) {
        const NodeInfo &info = m_info[i];
        if (!info.pattern)
            continue;
        auto node = std::make_unique<PatternNode>(info.pattern, info.inputLinks.front() == 0);
        node->signalParams.push_back(-1);
        for (size_t port = 1; port < info.inputs.size(); ++port)
            node->signalParams.push_back(info.pattern->params().indexOf(info.inputs[port].name));
        m_router->m_nodes[i] = std::move(node);
    }
    if (!wire())
        return nullptr;
    setDefaultHorizons();
    m_router->m_activity = std::make_unique<RouterActivity>();
    m_router->m_activity->resize(int(count));
    for (size_t i = 0; i < count; ++i) {
        if (RuntimeNode *node = m_router->m_nodes[i].get())
            node->setActivity(m_router->m_activity.get(), int(i));
    }
    return std::move(m_router);
}

std::unique_ptr<Router> Router::compile(const RouterGraph &graph, LoadError *error,
                                        const RouterContext &context)
{
    return RouterCompiler(graph, context, error).compile();
}

Router::~Router() = default;

bool Router::deviceHand(int device, Gripper *hand) const
{
    const int gripper = m_deviceHands[size_t(device)];
    if (gripper < 0)
        return false;
    *hand = Gripper(gripper);
    return true;
}

const std::vector<NodeActivity> &Router::activity() const
{
    return m_activity->nodes();
}

const std::vector<int> &Router::activityChanges() const
{
    return m_activity->changed();
}

void Router::clearActivityChanges()
{
    m_activity->clearChanges();
}

std::vector<const Detector *> Router::detectors() const
{
    std::vector<const Detector *> list;
    for (const DetectorNode *node : m_detectors)
        list.push_back(&node->detector());
    return list;
}

std::vector<ThresholdLevels> Router::thresholds() const
{
    std::vector<ThresholdLevels> list;
    for (size_t i = 0; i < m_nodes.size(); ++i) {
        const auto *node = dynamic_cast<const ThresholdNode *>(m_nodes[i].get());
        if (!node)
            continue;
        const ThresholdNode::Params &p = node->params();
        ThresholdLevels t;
        t.node = m_nodeIds[int(i)];
        t.gripper = node->gripper();
        t.message = p.message;
        t.category = p.category;
        t.condition = ThresholdNode::conditionNames().value(int(p.condition));
        t.range = p.condition == ThresholdNode::Condition::Inside ||
                  p.condition == ThresholdNode::Condition::Outside;
        t.begin = p.begin;
        t.beginHigh = p.beginHigh;
        t.end = p.end;
        t.endHigh = p.endHigh;
        t.levelsInSignalUnits = true;
        // Up the single signal input: through derivative and predict to the signal node.
        QString at = t.node;
        for (int hops = 0; hops <= int(m_graph.nodes.size()); ++hops) {
            const auto in = std::find_if(m_graph.links.begin(), m_graph.links.end(),
                                         [&at](const RouterLink &l) { return l.to == at; });
            const int from = in == m_graph.links.end() ? -1 : m_graph.nodeIndex(in->from);
            if (from < 0)
                break;
            const RouterNode &source = m_graph.nodes[size_t(from)];
            if (source.type == QLatin1String("signal")) {
                t.quantity = source.params.value(QStringLiteral("quantity")).toString();
                t.signalGripper =
                    static_cast<const SignalNode *>(m_nodes[size_t(from)].get())->gripper();
                break;
            }
            if (source.type != QLatin1String("derivative") &&
                source.type != QLatin1String("predict"))
                break;
            t.via.prepend(source.type);
            t.levelsInSignalUnits &= source.type != QLatin1String("derivative");
            at = source.id;
        }
        list.push_back(t);
    }
    return list;
}

int Router::soundingPattern(int device) const
{
    int pattern = -1;
    int priority = -1;
    for (const auto &[node, voice] : m_voices) {
        if (voice->device == device && voice->isSounding() && int(voice->priority()) > priority) {
            pattern = node;
            priority = int(voice->priority());
        }
    }
    return pattern;
}

std::vector<MessageRoute> Router::messageRoutes(double intensity) const
{
    std::vector<MessageRoute> routes;
    for (size_t source = 0; source < m_nodes.size(); ++source) {
        const RuntimeNode *node = m_nodes[source].get();
        std::vector<SemanticEvent> messages;
        if (const auto *detector = dynamic_cast<const DetectorNode *>(node))
            messages = detector->detector().probes(intensity);
        else if (const auto *sender = dynamic_cast<const MessageSourceNode *>(node))
            messages.push_back(sender->probeMessage(intensity));
        for (const SemanticEvent &message : messages) {
            ProbeWalk walk;
            node->probeTargets(message, &walk);
            for (const auto &hit : walk.hits) {
                const PatternNode *patternNode = hit.first;
                const SemanticEvent &arrived = hit.second;
                const auto at = std::find_if(m_nodes.begin(), m_nodes.end(),
                                             [&](const auto &n) { return n.get() == patternNode; });
                for (const std::unique_ptr<VoiceInput> &voice : patternNode->voices) {
                    MessageRoute route;
                    route.source = int(source);
                    route.message = message;
                    route.intensity = arrived.intensity;
                    route.pattern = int(at - m_nodes.begin());
                    route.played = voice->pattern;
                    route.device = voice->device;
                    route.routes = voice->routes;
                    routes.push_back(std::move(route));
                }
            }
        }
    }
    return routes;
}

RouterGraph Router::selfContained() const
{
    RouterGraph graph = m_graph;
    for (size_t i = 0; i < m_sources.size(); ++i) {
        QJsonObject &params = graph.nodes[i].params;
        if (m_sources[i].pattern)
            params.insert(QStringLiteral("pattern"), graph.embedPattern(m_sources[i].pattern));
        if (m_sources[i].model)
            params.insert(QStringLiteral("model"), graph.embedModel(m_sources[i].model));
    }
    // Nothing is left to find on disk.
    graph.baseDir.clear();
    return graph;
}

std::unique_ptr<Router> loadRouter(const QString &nameOrPath, const QStringList &overrides,
                                   LoadError *error, const RouterContext &context)
{
    RouterGraph graph;
    if (!RouterPresets::load(nameOrPath, &graph, error))
        return nullptr;
    return compileWithOverrides(std::move(graph), overrides, error, context);
}

std::unique_ptr<Router> compileWithOverrides(RouterGraph graph, const QStringList &overrides,
                                             LoadError *error, const RouterContext &context)
{
    for (const QString &assignment : overrides) {
        if (!graph.applyOverride(assignment, error))
            return nullptr;
    }
    std::unique_ptr<Router> router = Router::compile(graph, error, context);
    if (router)
        return router;
    // An override that makes its node invalid is the culprit: say so, not the file.
    for (const QString &assignment : overrides) {
        const QString target = assignment.section(QLatin1Char('='), 0, 0);
        const int node = graph.nodeIndex(target.left(int(target.lastIndexOf(QLatin1Char('.')))));
        const QString pointer = QStringLiteral("/nodes/%1").arg(node);
        if (error->pointer == pointer || error->pointer.startsWith(pointer + QLatin1Char('/'))) {
            *error =
                LoadError::at(QStringLiteral("--set ") + assignment, QString(), error->reason);
            break;
        }
    }
    return nullptr;
}

bool routesAs(const Router &router, const QString &nameOrPath)
{
    LoadError error;
    const std::unique_ptr<Router> named = loadRouter(nameOrPath, {}, &error);
    if (!named)
        return false;
    // Both self-contained, so a pattern compares by what it plays, whatever names it; and
    // what routes, not where the editor drew it.
    const auto routing = [](const Router &r) {
        QJsonObject json = r.selfContained().toJson();
        QJsonArray nodes = json.value(QLatin1String("nodes")).toArray();
        for (QJsonValueRef node : nodes) {
            QJsonObject object = node.toObject();
            object.remove(QLatin1String("ui"));
            node = object;
        }
        json.insert(QStringLiteral("nodes"), nodes);
        json.remove(QLatin1String("name"));
        json.remove(QLatin1String("description"));
        return json;
    };
    return routing(*named) == routing(router);
}

void Router::start(double t0)
{
    m_player.start(t0);
    for (const auto &node : m_nodes) {
        if (node)
            node->start(t0);
    }
    m_started = true;
}

void Router::process(const ContactFrame &frame, EventBuffer &events)
{
    for (DetectorNode *detector : m_detectors) {
        if (detector->detector().gripper() == frame.gripper)
            detector->process(frame, events);
    }
    // Threshold and compose nodes fire as signals and events reach them: after the
    // detectors in the tick.
    for (MessageSourceNode *source : m_messageSources)
        source->setOutput(&events);
    for (const SignalNode *signal : m_signals) {
        if (signal->gripper() == frame.gripper)
            signal->process(frame);
    }
}

void Router::endAll(double t, EventBuffer &events)
{
    for (MessageSourceNode *source : m_messageSources)
        source->setOutput(&events);
    for (DetectorNode *detector : m_detectors)
        detector->endAll(t, events);
    for (MessageSourceNode *source : m_messageSources)
        source->endAll(t, events);
}

void Router::appendActive(double t, EventBuffer &events) const
{
    for (const DetectorNode *detector : m_detectors)
        detector->detector().appendActive(t, events);
    for (const MessageSourceNode *source : m_messageSources)
        source->appendActive(t, events);
}

double Router::nextTimer() const
{
    double next = std::numeric_limits<double>::infinity();
    for (const RuntimeNode *node : m_timed)
        next = std::min(next, node->nextTimer());
    return next;
}

void Router::fireTimers(double t, EventBuffer &events)
{
    for (MessageSourceNode *source : m_messageSources)
        source->setOutput(&events);
    for (RuntimeNode *node : m_timed)
        node->fireTimers(t);
}

} // namespace semhap
