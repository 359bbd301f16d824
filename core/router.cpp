// SPDX-License-Identifier: MIT
#include "router.h"

#include "routercompiler.h"
#include "routernodes.h"

#include <QJsonArray>

#include <algorithm>

namespace semhap {

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
            const RuntimeNode *runtime = m_nodes[size_t(from)].get();
            if (const auto *signal = dynamic_cast<const SignalNode *>(runtime)) {
                t.quantity = source.params.value(QStringLiteral("quantity")).toString();
                t.signalGripper = signal->gripper();
                break;
            }
            const bool derivative = dynamic_cast<const DerivativeNode *>(runtime) != nullptr;
            if (!derivative && !dynamic_cast<const PredictNode *>(runtime))
                break;
            t.via.prepend(source.type);
            t.levelsInSignalUnits &= !derivative;
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
