// SPDX-License-Identifier: MIT
#include "routercompiler.h"

#include "detector.h"
#include "jsonreader.h"
#include "nodebuilder.h"
#include "patternlibrary.h"
#include "routernodes.h"

#include <QDir>
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

/** A row's view of the compiler while it builds one node. */
class RouterCompiler::Builder final : public NodeBuilder
{
public:
    Builder(RouterCompiler &compiler, int node) : m_compiler(compiler), m_node(node) {}

    int node() const override { return m_node; }
    const QJsonObject &params() const override
    {
        return m_compiler.m_graph.nodes[size_t(m_node)].params;
    }
    QJsonValue param(const QString &key) const override { return m_compiler.param(m_node, key); }
    unsigned choiceBits(const QString &key) const override
    {
        return m_compiler.choiceBits(m_node, key);
    }
    const RouterContext &context() const override { return m_compiler.m_context; }
    DetectorKind kind() const override
    {
        return m_compiler.m_info[size_t(m_node)].type->detectorKind;
    }
    bool fail(const QString &key, const QString &reason) override
    {
        return m_compiler.failNode(m_node, key, reason);
    }
    bool messageOf(Message *message, Category *category) override
    {
        return m_compiler.messageOf(m_node, message, category);
    }
    bool level(const QString &key, bool range, double *low, double *high) override
    {
        return m_compiler.level(m_node, key, range, low, high);
    }
    bool adopt(std::unique_ptr<RuntimeNode> node) override
    {
        return m_compiler.adopt(m_node, std::move(node));
    }
    bool adoptDetector(std::unique_ptr<Detector> detector) override
    {
        auto runtime = std::make_unique<DetectorNode>(std::move(detector));
        m_compiler.m_router->m_detectors.push_back(runtime.get());
        return m_compiler.adopt(m_node, std::move(runtime));
    }
    bool playPattern() override { return m_compiler.buildPattern(m_node); }
    bool drive() override { return m_compiler.buildDevice(m_node); }

private:
    RouterCompiler &m_compiler;
    int m_node;
};

template<typename Ptr, typename Lookup>
Ptr RouterCompiler::findFile(int node, const QString &key, const QString &name,
                             QHash<QString, Ptr> *found, Lookup lookup)
{
    // Many nodes may play one pattern or drive one model: each is found or loaded once.
    if (Ptr known = found->value(name))
        return known;
    QString reason;
    Ptr file = lookup(name, &reason);
    if (!file)
        failNode(node, key, reason);
    else
        found->insert(name, file);
    return file;
}

bool RouterCompiler::buildPattern(int node)
{
    const RouterNode &n = m_graph.nodes[size_t(node)];
    NodeInfo &info = m_info[size_t(node)];
    // The pattern first: its parameters are the node's too.
    const ParamSpec &patternSpec = *info.type->paramOfKind(ParamKind::Pattern);
    const QJsonValue name = n.params.value(patternSpec.name);
    QString reason;
    if (name.isUndefined())
        return failNode(node, QString(), patternSpec.missingReason());
    if (!patternSpec.check(name, &reason))
        return failNode(node, patternSpec.name, reason);
    PatternPtr pattern = findFile(
        node, patternSpec.name, name.toString(), &m_patterns,
        [this](const QString &named, QString *why) { return m_graph.pattern(named, why); });
    if (!pattern)
        return false;
    std::vector<ParamSpec> specs = info.type->params;
    RouterGraph::appendPatternParams(*pattern, &specs);
    if (!checkParams(node, specs))
        return false;
    info.channels = Builder(*this, node).channels();
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
    const QString model = param(node, QStringLiteral("model")).toString();
    info.model =
        findFile(node, QStringLiteral("model"), model, &m_models,
                 [this](const QString &named, QString *why) { return m_graph.model(named, why); });
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
    // A node that plays a pattern takes the pattern's parameters too: playPattern() checks
    // them once the pattern is found.
    if (!info.type->paramOfKind(ParamKind::Pattern) && !checkParams(node, info.type->params))
        return false;
    Builder builder(*this, node);
    return info.type->build(builder);
}

bool RouterCompiler::adopt(int node, std::unique_ptr<RuntimeNode> runtime)
{
    if (auto *signal = dynamic_cast<SignalNode *>(runtime.get()))
        m_router->m_signals.push_back(signal);
    if (auto *source = dynamic_cast<MessageSourceNode *>(runtime.get()))
        m_router->m_messageSources.push_back(source);
    if (runtime->hasTimers())
        m_router->m_timed.push_back(runtime.get());
    // Voices drive the channels their node names (absent: the pattern's own).
    if (m_info[size_t(node)].type->param(QStringLiteral("channels")))
        m_info[size_t(node)].channels = Builder(*this, node).channels();
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
        const RouterNodeType *type = routerNodeType(m_graph.nodes[i].type);
        if (type && type->role() == RouterNodeType::Role::Device &&
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
        if (m_info[i].type->isDetector)
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

} // namespace semhap
