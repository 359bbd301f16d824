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

#include <algorithm>
#include <cmath>
#include <set>

namespace semhap {

namespace {

// The predict and derivative nodes' smoothing time constant (s): longer than the ring-down of
// a finger landing on an object (20-35 ms of +-2 N at 2 ms steps, measured in the
// simulation), so that an impact does not read as a steep ramp.
constexpr double DefaultSlopeTau = 0.05;

// The most detectors whose messages may meet at one node: each brings two messages and a
// node tracks at most ActiveMessages::Capacity of them without allocating.
constexpr int MaxUpstreamDetectors = ActiveMessages::Capacity / 2;

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
        Gripper gripper = Gripper::Right;
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

    bool checkParams(int node, const QStringList &known);
    bool readGripper(int node);
    bool readNumber(int node, const QString &key, double fallback, double *out);
    bool readChannels(int node);
    bool readNames(int node, const QString &key, const QStringList &names, unsigned *bits);

    bool buildNode(int node);
    bool buildDetector(int node);
    bool buildPattern(int node);
    bool buildDevice(int node);
    std::unique_ptr<RuntimeNode> buildLogic(int node);
    std::unique_ptr<RuntimeNode> buildThreshold(int node);
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

bool RouterCompiler::checkParams(int node, const QStringList &known)
{
    const QJsonObject &params = m_graph.nodes[size_t(node)].params;
    for (auto it = params.begin(); it != params.end(); ++it) {
        if (!known.contains(it.key()))
            return failNode(node, it.key(),
                            QStringLiteral("unknown parameter '%1' (known: %2)")
                                .arg(it.key(), known.join(QStringLiteral(", "))));
    }
    return true;
}

bool RouterCompiler::readGripper(int node)
{
    const QJsonValue v = m_graph.nodes[size_t(node)].params.value(QStringLiteral("gripper"));
    if (v.isUndefined())
        return failNode(node, QString(),
                        QStringLiteral("needs a gripper (\"left\" or "
                                       "\"right\")"));
    if (!gripperFromName(v.toString(), &m_info[size_t(node)].gripper))
        return failNode(node, QStringLiteral("gripper"),
                        QStringLiteral("must be \"left\" or \"right\""));
    return true;
}

bool RouterCompiler::readNumber(int node, const QString &key, double fallback, double *out)
{
    const QJsonValue v = m_graph.nodes[size_t(node)].params.value(key);
    *out = fallback;
    if (v.isUndefined())
        return true;
    if (!v.isDouble() || !std::isfinite(v.toDouble()))
        return failNode(node, key,
                        QStringLiteral("must be a finite number, found ") + jsonTypeName(v));
    *out = v.toDouble();
    return true;
}

bool RouterCompiler::readChannels(int node)
{
    const QJsonValue v = m_graph.nodes[size_t(node)].params.value(QStringLiteral("channels"));
    if (v.isUndefined())
        return true;
    const QJsonArray array = v.toArray();
    if (!v.isArray() || array.isEmpty())
        return failNode(node, QStringLiteral("channels"),
                        QStringLiteral("must be a non-empty array of channel names"));
    for (const QJsonValue &channel : array) {
        if (!channel.isString() || channel.toString().isEmpty())
            return failNode(node, QStringLiteral("channels"),
                            QStringLiteral("must be a non-empty array of channel names"));
        m_info[size_t(node)].channels.append(channel.toString());
    }
    return true;
}

// A name or a list of names, each one of `names`; the result is a bit set over their index.
bool RouterCompiler::readNames(int node, const QString &key, const QStringList &names,
                               unsigned *bits)
{
    *bits = 0;
    const QJsonValue v = m_graph.nodes[size_t(node)].params.value(key);
    if (v.isUndefined())
        return true;
    const QJsonArray list = v.isArray() ? v.toArray() : QJsonArray{v};
    for (const QJsonValue &item : list) {
        const int index = int(names.indexOf(item.toString()));
        if (!item.isString() || index < 0)
            return failNode(node, key,
                            QStringLiteral("must be one of %1, or a list of them")
                                .arg(names.join(QStringLiteral(", "))));
        *bits |= 1u << unsigned(index);
    }
    return true;
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
    if (!readGripper(node))
        return false;
    QJsonObject params = n.params;
    params.remove(QStringLiteral("gripper"));
    QString key;
    QString reason;
    const Gripper gripper = m_info[size_t(node)].gripper;
    std::unique_ptr<Detector> detector;
    if (n.type == QLatin1String("force")) {
        ForceDetector::Params p;
        if (!p.read(params, &key, &reason) || !p.validate(&key, &reason))
            return failNode(node, key, reason);
        detector = std::make_unique<ForceDetector>(node, gripper, p);
    } else {
        SlipDetector::Params p;
        if (!p.read(params, &key, &reason) || !p.validate(&key, &reason))
            return failNode(node, key, reason);
        detector = std::make_unique<SlipDetector>(node, gripper, p);
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
    const QJsonValue name = n.params.value(QStringLiteral("pattern"));
    if (!name.isString() || name.toString().isEmpty())
        return failNode(node, QStringLiteral("pattern"),
                        QStringLiteral("needs a pattern name or file"));
    PatternPtr pattern = findPattern(node, name.toString());
    if (!pattern || !readChannels(node))
        return false;
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
        if (it.key() == QLatin1String("pattern") || it.key() == QLatin1String("channels"))
            continue;
        if (pattern->params().indexOf(it.key()) < 0) {
            QStringList known{QStringLiteral("pattern"), QStringLiteral("channels")};
            for (int p = 0; p < pattern->params().size(); ++p)
                known.append(pattern->params().name(p));
            return failNode(node, it.key(),
                            QStringLiteral("unknown parameter '%1' (known: %2)")
                                .arg(it.key(), known.join(QStringLiteral(", "))));
        }
        if (!it.value().isDouble() || !std::isfinite(it.value().toDouble()))
            return failNode(node, it.key(),
                            QStringLiteral("must be a finite number, found ") +
                                jsonTypeName(it.value()));
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
    const RouterNode &n = m_graph.nodes[size_t(node)];
    NodeInfo &info = m_info[size_t(node)];
    const QJsonValue model = n.params.value(QStringLiteral("model"));
    if (!model.isString() || model.toString().isEmpty())
        return failNode(node, QStringLiteral("model"),
                        QStringLiteral("needs a device model name or file"));
    info.model = findModel(node, model.toString());
    if (!info.model)
        return false;
    m_router->m_sources[size_t(node)].model = info.model;
    const QJsonValue policy = n.params.value(QStringLiteral("policy"));
    if (!policy.isUndefined() && !Player::mixPolicyFromName(policy.toString(), &info.policy))
        return failNode(node, QStringLiteral("policy"),
                        QStringLiteral("must be \"priority\", \"max\" or \"sum\""));
    return true;
}

std::unique_ptr<RuntimeNode> RouterCompiler::buildLogic(int node)
{
    const RouterNode &n = m_graph.nodes[size_t(node)];
    const QJsonObject &params = n.params;
    if (n.type == QLatin1String("signal")) {
        SignalNode::Quantity quantity;
        if (!readGripper(node))
            return nullptr;
        if (!SignalNode::quantityFromName(params.value(QStringLiteral("quantity")).toString(),
                                          &quantity)) {
            failNode(node, QStringLiteral("quantity"),
                     QStringLiteral("must be one of ") +
                         SignalNode::quantityNames().join(QStringLiteral(", ")));
            return nullptr;
        }
        double mu = 0.0;
        if (!readNumber(node, QStringLiteral("mu"), 0.0, &mu))
            return nullptr;
        if (params.contains(QStringLiteral("mu")) && mu <= 0.0) {
            failNode(node, QStringLiteral("mu"), QStringLiteral("must be positive"));
            return nullptr;
        }
        auto signal = std::make_unique<SignalNode>(m_info[size_t(node)].gripper, quantity, mu);
        m_router->m_signals.push_back(signal.get());
        return signal;
    }
    if (n.type == QLatin1String("derivative") || n.type == QLatin1String("predict")) {
        double tau = DefaultSlopeTau;
        double horizon = -1.0;
        if (!readNumber(node, QStringLiteral("tau"), DefaultSlopeTau, &tau) ||
            !readNumber(node, QStringLiteral("horizon"), -1.0, &horizon))
            return nullptr;
        if (tau < 0.0) {
            failNode(node, QStringLiteral("tau"), QStringLiteral("must not be negative"));
            return nullptr;
        }
        if (n.type == QLatin1String("derivative"))
            return std::make_unique<DerivativeNode>(tau);
        if (params.contains(QStringLiteral("horizon")) && horizon < 0.0) {
            failNode(node, QStringLiteral("horizon"), QStringLiteral("must not be negative"));
            return nullptr;
        }
        auto predict = std::make_unique<PredictNode>(tau);
        predict->setHorizon(horizon);
        return predict;
    }
    if (n.type == QLatin1String("threshold"))
        return buildThreshold(node);
    if (n.type == QLatin1String("filter")) {
        unsigned messages = 0;
        unsigned categories = 0;
        unsigned grippers = 0;
        if (!readNames(node, QStringLiteral("message"),
                       {messageName(Message::Grasp), messageName(Message::Break),
                        messageName(Message::Slip)},
                       &messages) ||
            !readNames(node, QStringLiteral("category"),
                       {categoryName(Category::Confirmation), categoryName(Category::Exception)},
                       &categories) ||
            !readNames(node, QStringLiteral("gripper"),
                       {gripperName(Gripper::Left), gripperName(Gripper::Right)}, &grippers))
            return nullptr;
        return std::make_unique<FilterNode>(messages, categories, grippers);
    }
    if (n.type == QLatin1String("gate")) {
        const QString mode =
            params.value(QStringLiteral("mode")).toString(QStringLiteral("block"));
        if (mode != QLatin1String("block") && mode != QLatin1String("open")) {
            failNode(node, QStringLiteral("mode"),
                     QStringLiteral("must be \"block\" or \"open\""));
            return nullptr;
        }
        return std::make_unique<GateNode>(mode == QLatin1String("open"));
    }
    if (n.type == QLatin1String("hysteresis")) {
        double hold = 0;
        double band = 0;
        if (!readNumber(node, QStringLiteral("hold"), 0.0, &hold) ||
            !readNumber(node, QStringLiteral("band"), 0.0, &band))
            return nullptr;
        if (hold < 0 || band < 0 || band > 1) {
            failNode(node, hold < 0 ? QStringLiteral("hold") : QStringLiteral("band"),
                     QStringLiteral("hold must be >= 0 s and band within [0, 1]"));
            return nullptr;
        }
        auto hysteresis = std::make_unique<HysteresisNode>(hold, band);
        m_router->m_timed.push_back(hysteresis.get());
        return hysteresis;
    }
    if (n.type == QLatin1String("curve")) {
        const QJsonValue points = params.value(QStringLiteral("points"));
        if (points.isUndefined())
            return std::make_unique<CurveNode>(Curve());
        std::vector<std::pair<double, double>> list;
        const QString expected = QStringLiteral("must be a list of [x, y] points with x "
                                                "increasing");
        if (!points.isArray() || points.toArray().isEmpty()) {
            failNode(node, QStringLiteral("points"), expected);
            return nullptr;
        }
        for (const QJsonValue &point : points.toArray()) {
            const QJsonArray xy = point.toArray();
            if (xy.size() != 2 || !xy.at(0).isDouble() || !xy.at(1).isDouble() ||
                !std::isfinite(xy.at(0).toDouble()) || !std::isfinite(xy.at(1).toDouble()) ||
                (!list.empty() && xy.at(0).toDouble() <= list.back().first)) {
                failNode(node, QStringLiteral("points"), expected);
                return nullptr;
            }
            list.emplace_back(xy.at(0).toDouble(), xy.at(1).toDouble());
        }
        return std::make_unique<CurveNode>(Curve::points(std::move(list)));
    }
    // proportional
    double ref = 1.0;
    if (!readNumber(node, QStringLiteral("ref"), 1.0, &ref) || !readChannels(node))
        return nullptr;
    if (ref <= 0) {
        failNode(node, QStringLiteral("ref"), QStringLiteral("must be positive"));
        return nullptr;
    }
    return std::make_unique<ProportionalNode>(ref);
}

std::unique_ptr<RuntimeNode> RouterCompiler::buildThreshold(int node)
{
    const QJsonObject &params = m_graph.nodes[size_t(node)].params;
    if (!readGripper(node))
        return nullptr;
    ThresholdNode::Params p;
    const QJsonValue message = params.value(QStringLiteral("message"));
    if (!messageFromName(message.toString(), &p.message)) {
        failNode(node, QStringLiteral("message"),
                 QStringLiteral("must be one of %1, %2, %3")
                     .arg(messageName(Message::Grasp), messageName(Message::Break),
                          messageName(Message::Slip)));
        return nullptr;
    }
    if (!params.contains(QStringLiteral("level")) || !params.contains(QStringLiteral("full"))) {
        failNode(node, QString(), QStringLiteral("needs a level and a full value"));
        return nullptr;
    }
    if (!readNumber(node, QStringLiteral("level"), 0.0, &p.level) ||
        !readNumber(node, QStringLiteral("full"), 1.0, &p.full) ||
        !readNumber(node, QStringLiteral("hysteresis"), 0.0, &p.hysteresis) ||
        !readNumber(node, QStringLiteral("minDuration"), 0.0, &p.minDuration))
        return nullptr;
    if (p.full == p.level) {
        failNode(node, QStringLiteral("full"),
                 QStringLiteral("must differ from level (above it: active while the input "
                                "is above level; below it: while below)"));
        return nullptr;
    }
    for (const auto &[key, value] : {std::pair{QStringLiteral("hysteresis"), p.hysteresis},
                                     std::pair{QStringLiteral("minDuration"), p.minDuration}}) {
        if (value < 0.0) {
            failNode(node, key, QStringLiteral("must not be negative"));
            return nullptr;
        }
    }
    auto threshold = std::make_unique<ThresholdNode>(node, m_info[size_t(node)].gripper, p);
    m_router->m_thresholds.push_back(threshold.get());
    return threshold;
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

    if (n.type == QLatin1String("force") || n.type == QLatin1String("slip"))
        return buildDetector(node); // the detector's own reader checks its keys
    if (n.type == QLatin1String("pattern"))
        return buildPattern(node);
    if (!checkParams(node, info.type->params))
        return false;
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
        if (m_graph.nodes[i].type == QLatin1String("device") && ++devices > RouterGraph::MaxDevices)
            return failNode(int(i), QString(),
                            QStringLiteral("one device more than the %1 a router may drive")
                                .arg(RouterGraph::MaxDevices));
    }
    return true;
}

bool RouterCompiler::resolveLinks()
{
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

        const std::vector<PortSpec> &outputs = from.type->outputs;
        if (outputs.empty())
            return fail(where + QStringLiteral("/from"),
                        nodeLabel(r.from) + QStringLiteral(" has no outputs"));
        const QString fromPort = link.fromPort.isEmpty() ? outputs.front().name : link.fromPort;
        const auto out = std::find_if(outputs.begin(), outputs.end(),
                                      [&](const PortSpec &p) { return p.name == fromPort; });
        if (out == outputs.end())
            return fail(where + QStringLiteral("/from"),
                        nodeLabel(r.from) + QStringLiteral(" has no output '%1'").arg(fromPort));
        if (to.inputs.empty())
            return fail(where + QStringLiteral("/to"),
                        nodeLabel(r.to) + QStringLiteral(" has no inputs"));
        const QString toPort = link.toPort.isEmpty() ? to.inputs.front().name : link.toPort;
        const auto in = std::find_if(to.inputs.begin(), to.inputs.end(),
                                     [&](const PortSpec &p) { return p.name == toPort; });
        if (in == to.inputs.end()) {
            QStringList names;
            for (const PortSpec &p : to.inputs)
                names.append(p.name);
            return fail(where + QStringLiteral("/to"),
                        nodeLabel(r.to) + QStringLiteral(" has no input '%1' (inputs: %2)")
                                              .arg(toPort, names.join(QStringLiteral(", "))));
        }
        if (out->type != in->type)
            return fail(where, QStringLiteral("port type mismatch: '%1:%2' sends %3, '%4:%5' "
                                              "takes %6")
                                   .arg(link.from, fromPort, portTypeName(out->type), link.to,
                                        toPort, portTypeName(in->type)));
        r.fromPort = int(out - outputs.begin());
        r.toPort = int(in - to.inputs.begin());
        r.type = in->type;
        if (!in->multiple && to.inputLinks[size_t(r.toPort)] > 0)
            return fail(where + QStringLiteral("/to"),
                        QStringLiteral("'%1:%2' takes a single link and already has one")
                            .arg(link.to, toPort));
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
    const size_t limit = size_t(MaxUpstreamDetectors) + 1;
    std::vector<std::vector<int>> upstream(count);
    for (size_t i = 0; i < count; ++i) {
        if (m_info[i].type->type == QLatin1String("force") ||
            m_info[i].type->type == QLatin1String("slip") ||
            m_info[i].type->type == QLatin1String("threshold"))
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
        if (upstream[i].size() > size_t(MaxUpstreamDetectors))
            return failNode(int(i), QString(),
                            QStringLiteral("listens to more than %1 detectors; at most %1 may "
                                           "feed one node")
                                .arg(MaxUpstreamDetectors));
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

    if (auto *pattern = dynamic_cast<PatternNode *>(runtime)) {
        auto input = std::make_unique<VoiceInput>(source.pattern);
        QString reason;
        if (!resolvePatternRoutes(*source.pattern, model, source.channels, &input->routes,
                                  &reason))
            return fail(where, nodeLabel(link.from) +
                                   QStringLiteral(" -> device '%1': ").arg(deviceId) + reason);
        m_router->m_player.addInput(device, input.get());
        pattern->voices.push_back(std::move(input));
        return true;
    }
    auto *proportional = static_cast<ProportionalNode *>(runtime);
    auto input = std::make_unique<ProportionalNode::Input>(*proportional);
    const QStringList names = source.channels.isEmpty() ? model.channelNames() : source.channels;
    for (const QString &name : names) {
        const int channel = model.channelIndex(name);
        if (channel < 0)
            return fail(where, nodeLabel(link.from) +
                                   QStringLiteral(" drives channel '%1', which device '%2' "
                                                  "(%3) does not have")
                                       .arg(name, deviceId, model.name()));
        input->routes.push_back({channel, 0});
    }
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
    return std::move(m_router);
}

std::unique_ptr<Router> Router::compile(const RouterGraph &graph, LoadError *error,
                                        const RouterContext &context)
{
    return RouterCompiler(graph, context, error).compile();
}

Router::~Router() = default;

namespace {

} // namespace

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
    // Threshold nodes fire as the signals reach them: after the detectors in the tick.
    for (ThresholdNode *threshold : m_thresholds)
        threshold->setOutput(&events);
    for (const SignalNode *signal : m_signals) {
        if (signal->gripper() == frame.gripper)
            signal->process(frame);
    }
}

void Router::endAll(double t, EventBuffer &events)
{
    for (DetectorNode *detector : m_detectors)
        detector->endAll(t, events);
    for (ThresholdNode *threshold : m_thresholds)
        threshold->endAll(t, events);
}

double Router::nextTimer() const
{
    double next = std::numeric_limits<double>::infinity();
    for (const RuntimeNode *node : m_timed)
        next = std::min(next, node->nextTimer());
    return next;
}

void Router::fireTimers(double t)
{
    for (RuntimeNode *node : m_timed)
        node->fireTimers(t);
}

} // namespace semhap
