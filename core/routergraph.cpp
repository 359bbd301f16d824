// SPDX-License-Identifier: MIT
#include "routergraph.h"

#include "inputfile.h"
#include "jsonreader.h"
#include "patternlibrary.h"
#include "patternrender.h"

#include <QDir>
#include <QFileInfo>
#include <QHash>
#include <QJsonArray>
#include <QJsonDocument>
#include <QSet>

#include <algorithm>
#include <cmath>

namespace semhap {

namespace {

/** The node's parameter naming a file of `kind` (the pattern it plays, its model), or null. */
const ParamSpec *fileParam(const RouterNode &node, ParamKind kind)
{
    const RouterNodeType *type = routerNodeType(node.type);
    return type ? type->paramOfKind(kind) : nullptr;
}

bool validId(const QString &id)
{
    if (id.isEmpty())
        return false;
    for (const QChar c : id) {
        if (c == QLatin1Char(':') || c.isSpace())
            return false;
    }
    return true;
}

// "node" or "node:port".
void splitEndpoint(const QString &text, QString *node, QString *port)
{
    const int colon = int(text.indexOf(QLatin1Char(':')));
    *node = colon < 0 ? text : text.left(colon);
    *port = colon < 0 ? QString() : text.mid(colon + 1);
}

QString joinEndpoint(const QString &node, const QString &port)
{
    return port.isEmpty() ? node : node + QLatin1Char(':') + port;
}

/**
 * Spellings older files wrote, read as today's with a located warning: a type's former name
 * and its row's upgrade of old parameters (RouterNodeType::formerNames, upgrade).
 */
void readOldSpellings(const QString &file, const QString &where, RouterNode *node,
                      std::vector<LoadError> *warnings)
{
    const UpgradeWarning warn = [&](const QString &pointer, const QString &message) {
        warnings->push_back(LoadError::at(file, where + pointer, message));
    };
    const RouterNodeType *type = routerNodeType(node->type);
    for (const RouterNodeType &row : routerNodeTypes()) {
        if (!type && row.formerNames.contains(node->type)) {
            warn(QStringLiteral("/type"),
                 deprecatedSpelling(QStringLiteral("node type"), node->type, row.type));
            node->type = row.type;
            type = &row;
        }
    }
    if (type && type->upgrade)
        type->upgrade(node->params, warn);
}

bool readNodes(JsonReader &reader, const QJsonArray &nodes, RouterGraph *graph)
{
    if (nodes.size() > RouterGraph::MaxNodes)
        return reader.fail(QStringLiteral("/nodes"),
                           QStringLiteral("%1 nodes, more than the %2 a router may have")
                               .arg(nodes.size())
                               .arg(RouterGraph::MaxNodes));
    QSet<QString> ids;
    ids.reserve(nodes.size());
    graph->nodes.reserve(size_t(nodes.size()));
    for (int i = 0; i < nodes.size(); ++i) {
        const QString where = jsonPointerChild(QStringLiteral("/nodes"), i);
        if (!nodes.at(i).isObject())
            return reader.fail(where, QStringLiteral("expected a node object, got ") +
                                          jsonTypeName(nodes.at(i)));
        const QJsonObject o = nodes.at(i).toObject();
        RouterNode node;
        if (!reader.checkKeys(o, where,
                              {QLatin1String("id"), QLatin1String("type"), QLatin1String("params"),
                               QLatin1String("ui")}) ||
            !reader.string(o, where, QLatin1String("id"), &node.id) ||
            !reader.string(o, where, QLatin1String("type"), &node.type) ||
            !reader.object(o, where, QLatin1String("params"), &node.params, false) ||
            !reader.object(o, where, QLatin1String("ui"), &node.ui, false))
            return false;
        readOldSpellings(graph->file, where, &node, &graph->warnings);
        if (!validId(node.id))
            return reader.fail(where + QStringLiteral("/id"),
                               QStringLiteral("'%1' is not a valid id (non-empty, no ':' or "
                                              "spaces)")
                                   .arg(node.id));
        if (ids.contains(node.id))
            return reader.fail(where + QStringLiteral("/id"),
                               QStringLiteral("duplicate node id '%1'").arg(node.id));
        ids.insert(node.id);
        graph->nodes.push_back(node);
    }
    return true;
}

bool readLinks(JsonReader &reader, const QJsonArray &links, RouterGraph *graph)
{
    if (links.size() > RouterGraph::MaxLinks)
        return reader.fail(QStringLiteral("/links"),
                           QStringLiteral("%1 links, more than the %2 a router may have")
                               .arg(links.size())
                               .arg(RouterGraph::MaxLinks));
    graph->links.reserve(size_t(links.size()));
    for (int i = 0; i < links.size(); ++i) {
        const QString where = jsonPointerChild(QStringLiteral("/links"), i);
        if (!links.at(i).isObject())
            return reader.fail(where, QStringLiteral("expected a link object {\"from\", \"to\"}, "
                                                     "got ") +
                                          jsonTypeName(links.at(i)));
        const QJsonObject o = links.at(i).toObject();
        QString from;
        QString to;
        if (!reader.checkKeys(o, where, {QLatin1String("from"), QLatin1String("to")}) ||
            !reader.string(o, where, QLatin1String("from"), &from) ||
            !reader.string(o, where, QLatin1String("to"), &to))
            return false;
        RouterLink link;
        splitEndpoint(from, &link.from, &link.fromPort);
        splitEndpoint(to, &link.to, &link.toPort);
        graph->links.push_back(link);
    }
    return true;
}

/**
 * The name under which `item` is embedded in `list`: its own, unless another item of that
 * name is there already, then a suffixed one.
 */
template<typename Ptr, typename Parse>
QString embed(std::vector<Ptr> &list, const Ptr &item, Parse parse)
{
    const QJsonObject json = item->toJson();
    QString name = item->name();
    for (int k = 2;; ++k) {
        const auto same = std::find_if(list.begin(), list.end(),
                                       [&](const Ptr &p) { return p->name() == name; });
        if (same == list.end())
            break;
        if (*same == item || (*same)->toJson() == json)
            return name;
        name = item->name() + QLatin1Char('~') + QString::number(k);
    }
    if (name == item->name()) {
        list.push_back(item);
        return name;
    }
    QJsonObject renamed = json;
    renamed.insert(QStringLiteral("name"), name);
    LoadError ignored;
    list.push_back(parse(renamed, QString(), &ignored));
    return list.back() ? name : item->name();
}

/** An embedded item named `name`, or null. */
template<typename Ptr> Ptr embedded(const std::vector<Ptr> &list, const QString &name)
{
    const auto found =
        std::find_if(list.begin(), list.end(), [&](const Ptr &p) { return p->name() == name; });
    return found == list.end() ? Ptr() : *found;
}

} // namespace

PatternPtr RouterGraph::pattern(const QString &nameOrPath, QString *reason) const
{
    if (PatternPtr found = embedded(patterns, nameOrPath))
        return found;
    if (!InputFile::namesFile(nameOrPath)) {
        if (PatternPtr builtin = PatternLibrary::builtin(nameOrPath))
            return builtin;
        *reason = QStringLiteral("unknown pattern '%1' (built-in: %2)")
                      .arg(nameOrPath, PatternLibrary::builtinNames().join(QStringLiteral(", ")));
        return nullptr;
    }
    if (!filesAllowed) {
        *reason = QStringLiteral("names the file '%1'; this router must carry its patterns")
                      .arg(nameOrPath);
        return nullptr;
    }
    LoadError error;
    PatternPtr loaded = Pattern::fromFile(QDir(baseDir).filePath(nameOrPath), &error);
    if (!loaded)
        *reason = QStringLiteral("cannot load pattern: ") + error.toString();
    return loaded;
}

QStringList RouterGraph::nodesPlayingFile(const QString &path) const
{
    const QString wanted = QDir::cleanPath(QFileInfo(path).absoluteFilePath());
    QStringList ids;
    for (const RouterNode &node : nodes) {
        const ParamSpec *played = fileParam(node, ParamKind::Pattern);
        const QString named = played ? node.params.value(played->name).toString() : QString();
        if (played && !embedded(patterns, named) && InputFile::namesFile(named) &&
            QDir::cleanPath(QDir(baseDir).absoluteFilePath(named)) == wanted)
            ids.append(node.id);
    }
    return ids;
}

QStringList RouterGraph::followRenamedFile(const QString &from, const QString &to)
{
    const QStringList ids = nodesPlayingFile(from);
    for (const QString &id : ids) {
        RouterNode &node = nodes[size_t(nodeIndex(id))];
        node.params.insert(fileParam(node, ParamKind::Pattern)->name, to);
    }
    return ids;
}

DeviceModelPtr RouterGraph::model(const QString &nameOrPath, QString *reason) const
{
    if (DeviceModelPtr found = embedded(models, nameOrPath))
        return found;
    const bool isFile = InputFile::namesFile(nameOrPath);
    if (isFile && !filesAllowed) {
        *reason = QStringLiteral("names the file '%1'; this router must carry its models")
                      .arg(nameOrPath);
        return nullptr;
    }
    LoadError error;
    DeviceModelPtr loaded =
        DeviceModelLibrary::load(isFile ? QDir(baseDir).filePath(nameOrPath) : nameOrPath, &error);
    if (!loaded)
        *reason = isFile ? QStringLiteral("cannot load model: ") + error.toString() : error.reason;
    return loaded;
}

PatternPtr RouterGraph::playedPattern(const RouterNode &node) const
{
    const ParamSpec *spec = fileParam(node, ParamKind::Pattern);
    if (!spec)
        return nullptr;
    QString ignored;
    const QString played = node.params.value(spec->name).toString();
    return played.isEmpty() ? nullptr : pattern(played, &ignored);
}

std::vector<PortSpec> RouterGraph::inputsOf(const RouterNode &node) const
{
    const RouterNodeType *type = routerNodeType(node.type);
    if (!type)
        return {};
    std::vector<PortSpec> inputs = type->inputs;
    if (const PatternPtr played = playedPattern(node))
        appendPatternInputs(*played, &inputs);
    return inputs;
}

std::vector<PortSpec> RouterGraph::outputsOf(const RouterNode &node)
{
    const RouterNodeType *type = routerNodeType(node.type);
    return type ? type->outputs : std::vector<PortSpec>();
}

QString RouterGraph::portOf(const QString &node, const QString &port, bool output) const
{
    if (!port.isEmpty())
        return port;
    // The default is the type's first port: a pattern node's own inputs come after it, so
    // no pattern needs to be found (or read from its file) to name it.
    const int index = nodeIndex(node);
    const RouterNodeType *type = index < 0 ? nullptr : routerNodeType(nodes[size_t(index)].type);
    if (!type)
        return QString();
    const std::vector<PortSpec> &ports = output ? type->outputs : type->inputs;
    return ports.empty() ? QString() : ports.front().name;
}

bool RouterGraph::reaches(const QString &from, const QString &to) const
{
    std::vector<QString> stack{from};
    QSet<QString> seen;
    while (!stack.empty()) {
        const QString node = stack.back();
        stack.pop_back();
        if (node == to)
            return true;
        if (seen.contains(node))
            continue;
        seen.insert(node);
        for (const RouterLink &link : links) {
            if (link.from == node)
                stack.push_back(link.to);
        }
    }
    return false;
}

QString RouterGraph::portProblem(const RouterNode &from, const QString &fromPort,
                                 const RouterNode &to, const std::vector<PortSpec> &inputs,
                                 const QString &toPort, int linksIntoPort, LinkEnd *end)
{
    const auto label = [](const RouterNode &node) {
        return QStringLiteral("node '%1' (%2)").arg(node.id, node.type);
    };
    *end = LinkEnd::From;
    const std::vector<PortSpec> outputs = outputsOf(from);
    if (outputs.empty())
        return label(from) + QStringLiteral(" has no outputs");
    const QString outName = fromPort.isEmpty() ? outputs.front().name : fromPort;
    const auto out = std::find_if(outputs.begin(), outputs.end(),
                                  [&](const PortSpec &p) { return p.name == outName; });
    if (out == outputs.end())
        return label(from) + QStringLiteral(" has no output '%1'").arg(outName);
    *end = LinkEnd::To;
    if (inputs.empty())
        return label(to) + QStringLiteral(" has no inputs");
    const QString inName = toPort.isEmpty() ? inputs.front().name : toPort;
    const auto in = std::find_if(inputs.begin(), inputs.end(),
                                 [&](const PortSpec &p) { return p.name == inName; });
    if (in == inputs.end()) {
        QStringList names;
        for (const PortSpec &p : inputs)
            names.append(p.name);
        return label(to) + QStringLiteral(" has no input '%1' (inputs: %2)")
                               .arg(inName, names.join(QStringLiteral(", ")));
    }
    if (out->type != in->type) {
        *end = LinkEnd::Both;
        return QStringLiteral("port type mismatch: '%1:%2' sends %3, '%4:%5' takes %6")
            .arg(from.id, outName, portTypeName(out->type), to.id, inName, portTypeName(in->type));
    }
    if (!in->multiple && linksIntoPort > 0)
        return QStringLiteral("'%1:%2' takes a single link and already has one")
            .arg(to.id, inName);
    return QString();
}

QString RouterGraph::voiceProblem(const RouterNode &from, const Pattern *pattern,
                                  const QStringList &channels, const RouterNode &device,
                                  const DeviceModel &model,
                                  std::vector<PlayerInput::Route> *routes)
{
    const QString label = QStringLiteral("node '%1' (%2)").arg(from.id, from.type);
    routes->clear();
    QString reason;
    if (pattern) {
        if (!resolvePatternRoutes(*pattern, model, channels, routes, &reason))
            return label + QStringLiteral(" -> device '%1': ").arg(device.id) + reason;
        return QString();
    }
    for (const QString &name : channels.isEmpty() ? model.channelNames() : channels) {
        const int channel = model.channelIndex(name);
        if (channel < 0)
            return label + QStringLiteral(" drives channel '%1', which device '%2' (%3) does "
                                          "not have")
                               .arg(name, device.id, model.name());
        routes->push_back({channel, 0});
    }
    return QString();
}

QString RouterGraph::fanInProblem()
{
    return QStringLiteral("listens to more than %1 detectors; at most %1 may feed one node")
        .arg(MaxUpstreamDetectors);
}

bool RouterGraph::isDetectorType(const QString &type)
{
    const RouterNodeType *row = routerNodeType(type);
    return row && row->isDetector;
}

bool RouterGraph::checkLink(const RouterLink &link, QString *reason) const
{
    const int fromIndex = nodeIndex(link.from);
    const int toIndex = nodeIndex(link.to);
    if (fromIndex < 0 || toIndex < 0) {
        *reason =
            QStringLiteral("dangling link: no node '%1'").arg(fromIndex < 0 ? link.from : link.to);
        return false;
    }
    const RouterNode &from = nodes[size_t(fromIndex)];
    const RouterNode &to = nodes[size_t(toIndex)];
    const QString fromPort = portOf(link.from, link.fromPort, true);
    const QString toPort = portOf(link.to, link.toPort, false);
    int linksIntoPort = 0;
    for (const RouterLink &other : links) {
        if (other.to != to.id || portOf(other.to, other.toPort, false) != toPort)
            continue;
        if (other.from == from.id && portOf(other.from, other.fromPort, true) == fromPort) {
            *reason = QStringLiteral("'%1:%2' already feeds '%3:%4'")
                          .arg(from.id, fromPort, to.id, toPort);
            return false;
        }
        ++linksIntoPort;
    }
    LinkEnd end = LinkEnd::Both;
    *reason = portProblem(from, fromPort, to, inputsOf(to), toPort, linksIntoPort, &end);
    if (!reason->isEmpty())
        return false;
    if (from.id == to.id) {
        *reason = QStringLiteral("node '%1' (%2) cannot feed itself").arg(from.id, from.type);
        return false;
    }
    if (reaches(to.id, from.id)) {
        *reason = QStringLiteral("this link would make a cycle: '%1' already leads to '%2'")
                      .arg(to.id, from.id);
        return false;
    }
    const std::vector<PortSpec> outputs = outputsOf(from);
    const auto out = std::find_if(outputs.begin(), outputs.end(),
                                  [&](const PortSpec &p) { return p.name == fromPort; });
    if (out->type == PortType::Voice) {
        // Whether the voice fits the device; a pattern or model that cannot be found is the
        // node's problem, which the compiler reports on the node.
        QString ignored;
        const DeviceModelPtr device =
            model(to.params.value(QLatin1String("model")).toString(), &ignored);
        const PatternPtr played = playedPattern(from);
        if (!device || (fileParam(from, ParamKind::Pattern) && !played))
            return true;
        QStringList channels;
        for (const QJsonValue &channel : from.params.value(QLatin1String("channels")).toArray())
            channels.append(channel.toString());
        std::vector<PlayerInput::Route> routes;
        *reason = voiceProblem(from, played.get(), channels, to, *device, &routes);
        return reason->isEmpty();
    }
    if (out->type != PortType::Event)
        return true;

    // Fan-in: the detectors heard at each node, over event links, with the new link added.
    // Sets stop one past the limit, so the work stays linear in the links.
    const size_t limit = size_t(MaxUpstreamDetectors) + 1;
    std::vector<RouterLink> eventLinks;
    for (const RouterLink &l : links) {
        const int index = nodeIndex(l.from);
        const std::vector<PortSpec> ports = outputsOf(nodes[size_t(index)]);
        const QString port = portOf(l.from, l.fromPort, true);
        for (const PortSpec &spec : ports) {
            if (spec.name == port && spec.type == PortType::Event)
                eventLinks.push_back(l);
        }
    }
    eventLinks.push_back(link);
    QHash<QString, QSet<QString>> heard;
    for (const RouterNode &node : nodes) {
        if (isDetectorType(node.type))
            heard[node.id].insert(node.id);
    }
    // Relax until nothing grows: the event graph is acyclic, so this ends within its depth.
    for (bool grew = true; grew;) {
        grew = false;
        for (const RouterLink &l : eventLinks) {
            const QSet<QString> source = heard.value(l.from);
            QSet<QString> &target = heard[l.to];
            for (const QString &detector : source) {
                if (size_t(target.size()) < limit && !target.contains(detector)) {
                    target.insert(detector);
                    grew = true;
                }
            }
        }
    }
    for (auto it = heard.begin(); it != heard.end(); ++it) {
        if (size_t(it->size()) > size_t(MaxUpstreamDetectors) && reaches(link.to, it.key())) {
            const RouterNode &node = nodes[size_t(nodeIndex(it.key()))];
            *reason = QStringLiteral("node '%1' (%2): ").arg(node.id, node.type) + fanInProblem();
            return false;
        }
    }
    return true;
}

std::vector<ParamSpec> RouterGraph::paramsOf(const RouterNode &node) const
{
    const RouterNodeType *type = routerNodeType(node.type);
    if (!type)
        return {};
    std::vector<ParamSpec> params = type->params;
    if (const PatternPtr played = playedPattern(node))
        appendPatternParams(*played, &params);
    return params;
}

void RouterGraph::appendPatternParams(const Pattern &pattern, std::vector<ParamSpec> *params)
{
    for (int p = 0; p < pattern.params().size(); ++p) {
        const QString &name = pattern.params().name(p);
        params->push_back(ParamSpec::number(
            name, pattern.params().defaultValue(p), QString(),
            QStringLiteral("The pattern's parameter '%1': its value for this node's voices, "
                           "until a signal input sets it")
                .arg(name)));
    }
}

void RouterGraph::appendPatternInputs(const Pattern &pattern, std::vector<PortSpec> *inputs)
{
    for (int p = 0; p < pattern.params().size(); ++p) {
        if (p != ParamTable::Intensity)
            inputs->push_back({pattern.params().name(p), PortType::Signal, false});
    }
}

QString RouterGraph::embedPattern(const PatternPtr &pattern)
{
    return embed(patterns, pattern, Pattern::fromJson);
}

QString RouterGraph::embedModel(const DeviceModelPtr &model)
{
    return embed(models, model, DeviceModel::fromJson);
}

bool RouterGraph::embedFiles(LoadError *error)
{
    // One file may be named by many nodes: each is read once.
    QHash<QString, QString> embeddedAs;
    for (size_t i = 0; i < nodes.size(); ++i) {
        RouterNode &node = nodes[i];
        const ParamSpec *patternSpec = fileParam(node, ParamKind::Pattern);
        const ParamSpec *modelSpec = fileParam(node, ParamKind::Model);
        const bool isPattern = patternSpec != nullptr;
        if (!patternSpec && !modelSpec)
            continue;
        const QString key = isPattern ? patternSpec->name : modelSpec->name;
        const QString named = node.params.value(key).toString();
        if (named.isEmpty() || !InputFile::namesFile(named))
            continue;
        const QString path = QDir(baseDir).filePath(named);
        QString as = embeddedAs.value(path);
        if (as.isEmpty()) {
            QString reason;
            if (isPattern) {
                if (const PatternPtr p = pattern(named, &reason))
                    as = embedPattern(p);
            } else if (const DeviceModelPtr m = model(named, &reason)) {
                as = embedModel(m);
            }
            if (as.isEmpty()) {
                *error = LoadError::at(
                    file,
                    jsonPointerChild(jsonPointerChild(QStringLiteral("/nodes"), int(i)) +
                                         QStringLiteral("/params"),
                                     key),
                    QStringLiteral("cannot embed %1: %2").arg(named, reason));
                return false;
            }
            embeddedAs.insert(path, as);
        }
        node.params.insert(key, as);
    }
    return true;
}

bool RouterGraph::fromJson(const QJsonObject &json, const QString &file, RouterGraph *graph,
                           LoadError *error)
{
    *graph = RouterGraph();
    graph->file = file;
    if (!checkFormat(json, file, QLatin1String(Format), error))
        return false;
    JsonReader reader(file);
    if (readDocument(reader, json, graph))
        return true;
    *error = reader.error();
    return false;
}

bool RouterGraph::readDocument(JsonReader &reader, const QJsonObject &json, RouterGraph *graph)
{
    const QString root;
    if (!reader.checkKeys(json, root,
                          {QLatin1String("format"), QLatin1String("name"),
                           QLatin1String("description"), QLatin1String("nodes"),
                           QLatin1String("links"), QLatin1String("patterns"),
                           QLatin1String("models")}))
        return false;
    QJsonArray nodes;
    QJsonArray links;
    QJsonArray patterns;
    QJsonArray models;
    if (!reader.string(json, root, QLatin1String("name"), &graph->name, false) ||
        !reader.string(json, root, QLatin1String("description"), &graph->description, false) ||
        !reader.array(json, root, QLatin1String("nodes"), &nodes) ||
        !reader.array(json, root, QLatin1String("links"), &links, false) ||
        !reader.array(json, root, QLatin1String("patterns"), &patterns, false) ||
        !reader.array(json, root, QLatin1String("models"), &models, false))
        return false;
    if (!readNodes(reader, nodes, graph) || !readLinks(reader, links, graph))
        return false;

    for (int i = 0; i < patterns.size(); ++i) {
        const QString where = jsonPointerChild(QStringLiteral("/patterns"), i);
        if (!patterns.at(i).isObject())
            return reader.fail(where, QStringLiteral("expected a pattern object"));
        LoadError inner;
        PatternPtr pattern = Pattern::fromJson(patterns.at(i).toObject(), graph->file, &inner);
        if (!pattern)
            return reader.fail(where + inner.pointer, inner.reason);
        graph->patterns.push_back(pattern);
    }
    for (int i = 0; i < models.size(); ++i) {
        const QString where = jsonPointerChild(QStringLiteral("/models"), i);
        if (!models.at(i).isObject())
            return reader.fail(where, QStringLiteral("expected a device model object"));
        LoadError inner;
        DeviceModelPtr model = DeviceModel::fromJson(models.at(i).toObject(), graph->file, &inner);
        if (!model)
            return reader.fail(where + inner.pointer, inner.reason);
        graph->models.push_back(model);
    }
    return true;
}

bool RouterGraph::fromFile(const QString &path, RouterGraph *graph, LoadError *error)
{
    QJsonObject json;
    if (!readJsonObjectFile(path, &json, error))
        return false;
    if (!fromJson(json, path, graph, error))
        return false;
    graph->baseDir = QFileInfo(path).absolutePath();
    return true;
}

QJsonObject RouterGraph::toJson() const
{
    QJsonArray nodeArray;
    for (const RouterNode &node : nodes) {
        QJsonObject o{{QStringLiteral("id"), node.id}, {QStringLiteral("type"), node.type}};
        if (!node.params.isEmpty())
            o.insert(QStringLiteral("params"), node.params);
        if (!node.ui.isEmpty())
            o.insert(QStringLiteral("ui"), node.ui);
        nodeArray.append(o);
    }
    QJsonArray linkArray;
    for (const RouterLink &link : links) {
        linkArray.append(
            QJsonObject{{QStringLiteral("from"), joinEndpoint(link.from, link.fromPort)},
                        {QStringLiteral("to"), joinEndpoint(link.to, link.toPort)}});
    }
    QJsonObject json{{QStringLiteral("format"), QLatin1String(Format)},
                     {QStringLiteral("nodes"), nodeArray},
                     {QStringLiteral("links"), linkArray}};
    if (!name.isEmpty())
        json.insert(QStringLiteral("name"), name);
    if (!description.isEmpty())
        json.insert(QStringLiteral("description"), description);
    if (!patterns.empty()) {
        QJsonArray array;
        for (const PatternPtr &pattern : patterns)
            array.append(pattern->toJson());
        json.insert(QStringLiteral("patterns"), array);
    }
    if (!models.empty()) {
        QJsonArray array;
        for (const DeviceModelPtr &model : models)
            array.append(model->toJson());
        json.insert(QStringLiteral("models"), array);
    }
    return json;
}

int RouterGraph::nodeIndex(const QString &id) const
{
    for (size_t i = 0; i < nodes.size(); ++i) {
        if (nodes[i].id == id)
            return int(i);
    }
    return -1;
}

bool RouterGraph::applyOverride(const QString &assignment, LoadError *error)
{
    const QString where = QStringLiteral("--set ") + assignment;
    const int equals = int(assignment.indexOf(QLatin1Char('=')));
    const int dot = equals < 0 ? -1 : int(assignment.lastIndexOf(QLatin1Char('.'), equals));
    if (equals < 0 || dot <= 0 || dot + 1 == equals) {
        *error = LoadError::at(where, QString(), QStringLiteral("expected NODE.PARAM=VALUE"));
        return false;
    }
    const QString nodeId = assignment.left(dot);
    const QString param = assignment.mid(dot + 1, equals - dot - 1);
    const QString text = assignment.mid(equals + 1);
    const int index = nodeIndex(nodeId);
    if (index < 0) {
        *error = LoadError::at(where, QString(),
                               QStringLiteral("no node '%1' in router '%2'")
                                   .arg(nodeId, name.isEmpty() ? file : name));
        return false;
    }
    // Wrap the value so that scalars parse too; fall back to a plain string.
    const QJsonDocument doc =
        QJsonDocument::fromJson(QByteArrayLiteral("[") + text.toUtf8() + QByteArrayLiteral("]"));
    QJsonValue value(text);
    if (doc.isArray() && doc.array().size() == 1)
        value = doc.array().at(0);
    nodes[size_t(index)].params.insert(param, value);
    return true;
}

QStringList RouterPresets::names()
{
    QStringList names;
    const QStringList files = QDir(QStringLiteral(":/semhap/routers"))
                                  .entryList({QStringLiteral("*.json")}, QDir::Files);
    for (const QString &file : files)
        names.append(file.chopped(5));
    return names;
}

bool RouterPresets::preset(const QString &name, RouterGraph *graph, LoadError *error)
{
    const QString path = QStringLiteral(":/semhap/routers/%1.json").arg(name);
    if (!QFileInfo::exists(path) || name.contains(QLatin1Char('/'))) {
        *error = LoadError::at(name, QString(),
                               QStringLiteral("no such router preset "
                                              "(presets: %1)")
                                   .arg(names().join(QStringLiteral(", "))));
        return false;
    }
    QJsonObject json;
    if (!readJsonObjectFile(path, &json, error) ||
        !RouterGraph::fromJson(json, name, graph, error))
        return false;
    return true;
}

bool RouterPresets::load(const QString &nameOrPath, RouterGraph *graph, LoadError *error)
{
    if (InputFile::namesFile(nameOrPath))
        return RouterGraph::fromFile(nameOrPath, graph, error);
    return preset(nameOrPath, graph, error);
}

} // namespace semhap
