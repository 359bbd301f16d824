// SPDX-License-Identifier: MIT
#include "routerscene.h"

#include "colors.h"
#include "patternlibrary.h"
#include "routerdocument.h"
#include "routerwireitem.h"

#include <QDir>
#include <QGraphicsPathItem>
#include <QGraphicsSceneDragDropEvent>
#include <QGraphicsSceneMouseEvent>
#include <QJsonArray>
#include <QLineF>
#include <QLocale>
#include <QMimeData>

#include <algorithm>
#include <array>
#include <optional>
#include <set>

namespace semhap {

namespace {

constexpr double ColumnSpacing = 230.0;
constexpr double RowGap = 18.0;

/** The layout column of a node type: sources, logic, voice makers, devices, left to right. */
int columnOf(const QString &type)
{
    const RouterNodeType *spec = routerNodeType(type);
    return spec ? int(spec->role()) : int(RouterNodeType::Role::Logic);
}

/** Whether nodes of `type` play (show their frames' level) rather than pass messages on. */
bool isDevice(const QString &type)
{
    const RouterNodeType *spec = routerNodeType(type);
    return spec && spec->role() == RouterNodeType::Role::Device;
}

/** The node's parameters worth reading on the canvas: its names, not its numbers. */
QString summaryOf(const RouterNode &node)
{
    QStringList parts;
    const RouterNodeType *type = routerNodeType(node.type);
    for (const ParamSpec &spec : type ? type->params : std::vector<ParamSpec>()) {
        if (spec.kind != ParamKind::Pattern && spec.kind != ParamKind::Model &&
            spec.kind != ParamKind::Choice && spec.kind != ParamKind::Choices &&
            spec.kind != ParamKind::Signal)
            continue;
        const QJsonValue v = node.params.value(spec.name);
        if (v.isString())
            parts.append(v.toString());
        else if (v.isArray()) {
            QStringList names;
            for (const QJsonValue &item : v.toArray())
                names.append(item.toString());
            parts.append(names.join(QLatin1Char('|')));
        }
    }
    return parts.join(QStringLiteral(" · "));
}

} // namespace

RouterScene::RouterScene(const RouterDocument &document, QObject *parent)
    : QGraphicsScene(parent), m_document(document)
{
    setBackgroundBrush(colors::Canvas);
    m_fadeTimer.setInterval(33);
    connect(&m_fadeTimer, &QTimer::timeout, this, &RouterScene::fade);
    connect(&document, &RouterDocument::graphReset, this, &RouterScene::rebuild);
    connect(&document, &RouterDocument::nodeInserted, this, &RouterScene::insertItem);
    connect(&document, &RouterDocument::nodeRemoved, this, &RouterScene::removeItem);
    connect(&document, &RouterDocument::nodeRenamed, this, &RouterScene::renameItem);
    connect(&document, &RouterDocument::nodeParamsChanged, this, [this](int index) {
        refreshNode(m_items[size_t(index)], graph().nodes[size_t(index)]);
        rebuildWires(); // a pattern node's ports follow its pattern's parameters
    });
    connect(&document, &RouterDocument::nodeMoved, this, [this](int index) {
        m_items[size_t(index)]->setPos(RouterDocument::nodePos(graph().nodes[size_t(index)]));
    });
    connect(&document, &RouterDocument::linksChanged, this, &RouterScene::rebuildWires);
    rebuild();
}

const RouterGraph &RouterScene::graph() const
{
    return m_document.graph();
}

RouterGraph RouterScene::placed(const RouterGraph &graph)
{
    const auto hasPos = [](const RouterNode &node) {
        return node.ui.contains(QLatin1String("x")) && node.ui.contains(QLatin1String("y"));
    };
    if (std::all_of(graph.nodes.begin(), graph.nodes.end(), hasPos))
        return graph;
    RouterGraph result = graph;
    const std::map<QString, QPointF> positions = arrangedPositions(graph);
    for (RouterNode &node : result.nodes) {
        if (hasPos(node))
            continue;
        const QPointF p = positions.at(node.id);
        node.ui.insert(QStringLiteral("x"), p.x());
        node.ui.insert(QStringLiteral("y"), p.y());
    }
    return result;
}

void RouterScene::rebuild()
{
    clearSelection();
    for (RouterWireItem *wire : m_wires)
        delete wire;
    m_wires.clear();
    for (RouterNodeItem *item : m_items)
        delete item;
    m_items.clear();
    m_nodeErrors.clear();
    m_linkErrors.clear();
    m_active.clear();
    for (const RouterNode &node : graph().nodes)
        m_items.push_back(makeItem(node));
    rebuildWires();
}

RouterNodeItem *RouterScene::makeItem(const RouterNode &node)
{
    auto *item = new RouterNodeItem(node.id, node.type);
    addItem(item);
    refreshNode(item, node);
    item->setPos(RouterDocument::nodePos(node));
    connect(item, &RouterNodeItem::moved, this, [this, item] { updateWires(item); });
    return item;
}

void RouterScene::refreshNode(RouterNodeItem *item, const RouterNode &node)
{
    item->setId(node.id);
    item->setSummary(summaryOf(node));
    item->setPorts(graph().inputsOf(node), RouterGraph::outputsOf(node));
    item->setError(m_nodeErrors.value(node.id));
}

void RouterScene::insertItem(int index)
{
    m_items.insert(m_items.begin() + index, makeItem(graph().nodes[size_t(index)]));
    rebuildWires();
}

void RouterScene::removeItem(int index)
{
    delete m_items[size_t(index)];
    m_items.erase(m_items.begin() + index);
    rebuildWires();
}

void RouterScene::renameItem(int index, const QString &from)
{
    const RouterNode &node = graph().nodes[size_t(index)];
    if (m_active.contains(from))
        m_active.insert(node.id, m_active.take(from));
    refreshNode(m_items[size_t(index)], node);
}

RouterNodeItem *RouterScene::nodeItem(const QString &id) const
{
    const int index = graph().nodeIndex(id);
    return index < 0 ? nullptr : m_items[size_t(index)];
}

RouterWireItem *RouterScene::wireItem(int index) const
{
    return index >= 0 && size_t(index) < m_wires.size() ? m_wires[size_t(index)] : nullptr;
}

QStringList RouterScene::selectedNodeIds() const
{
    QStringList ids;
    for (const RouterNodeItem *item : m_items) {
        if (item->isSelected())
            ids.append(item->id());
    }
    return ids;
}

std::vector<int> RouterScene::selectedLinks() const
{
    std::vector<int> links;
    for (size_t j = 0; j < m_wires.size(); ++j) {
        if (m_wires[j] && m_wires[j]->isSelected())
            links.push_back(int(j));
    }
    return links;
}

std::map<QString, QPointF> RouterScene::arrangedPositions(const RouterGraph &graph)
{
    // Each column in graph order for the first, then by the mean row of what feeds each
    // node, so wires run mostly straight; nodes nothing feeds go last.
    std::array<std::vector<int>, 4> columns;
    for (size_t i = 0; i < graph.nodes.size(); ++i)
        columns[size_t(columnOf(graph.nodes[i].type))].push_back(int(i));
    std::map<QString, double> rowOf;
    std::map<QString, QPointF> positions;
    double tallest = 0.0;
    std::array<double, 4> heights{};
    const auto nodeHeight = [&graph](int i) {
        const RouterNode &node = graph.nodes[size_t(i)];
        return RouterNodeItem::heightFor(graph.inputsOf(node), RouterGraph::outputsOf(node));
    };
    for (size_t c = 0; c < columns.size(); ++c) {
        std::vector<std::pair<double, int>> order;
        for (size_t k = 0; k < columns[c].size(); ++k) {
            const int i = columns[c][k];
            double sum = 0.0;
            int count = 0;
            for (const RouterLink &link : graph.links) {
                if (link.to == graph.nodes[size_t(i)].id && rowOf.count(link.from)) {
                    sum += rowOf[link.from];
                    ++count;
                }
            }
            order.emplace_back(count ? sum / count : 1e6 + double(k), i);
        }
        std::stable_sort(order.begin(), order.end(),
                         [](const auto &a, const auto &b) { return a.first < b.first; });
        double y = 0.0;
        for (size_t r = 0; r < order.size(); ++r) {
            const int i = order[r].second;
            rowOf[graph.nodes[size_t(i)].id] = double(r);
            positions[graph.nodes[size_t(i)].id] = QPointF(double(c) * ColumnSpacing, y);
            y += nodeHeight(i) + RowGap;
        }
        heights[c] = y;
        tallest = std::max(tallest, y);
    }
    // Columns centred on the tallest one.
    for (auto &[id, p] : positions) {
        const int c = int(p.x() / ColumnSpacing + 0.5);
        p.setY(p.y() + (tallest - heights[size_t(c)]) / 2);
    }
    return positions;
}

void RouterScene::rebuildWires()
{
    for (RouterWireItem *wire : m_wires)
        delete wire;
    m_wires.clear();
    for (size_t j = 0; j < graph().links.size(); ++j) {
        const RouterLink &link = graph().links[j];
        RouterNodeItem *from = nodeItem(link.from);
        RouterNodeItem *to = nodeItem(link.to);
        const QString fromPort = graph().portOf(link.from, link.fromPort, true);
        const QString toPort = graph().portOf(link.to, link.toPort, false);
        RouterWireItem *wire = nullptr;
        if (from && to) {
            const auto out = std::find_if(from->outputs().begin(), from->outputs().end(),
                                          [&](const PortSpec &p) { return p.name == fromPort; });
            const bool hasIn = std::any_of(to->inputs().begin(), to->inputs().end(),
                                           [&](const PortSpec &p) { return p.name == toPort; });
            if (out != from->outputs().end() && hasIn) {
                wire = new RouterWireItem(from, fromPort, to, toPort, out->type);
                wire->setError(m_linkErrors.value(int(j)));
                addItem(wire);
            }
        }
        m_wires.push_back(wire);
    }
}

void RouterScene::updateWires(RouterNodeItem *item)
{
    for (RouterWireItem *wire : m_wires) {
        if (wire && (wire->fromNode() == item || wire->toNode() == item))
            wire->updatePath();
    }
}

void RouterScene::setErrors(const QHash<QString, QString> &nodeErrors,
                            const QHash<int, QString> &linkErrors)
{
    m_nodeErrors = nodeErrors;
    m_linkErrors = linkErrors;
    for (RouterNodeItem *item : m_items)
        item->setError(nodeErrors.value(item->id()));
    for (size_t j = 0; j < m_wires.size(); ++j) {
        if (m_wires[j])
            m_wires[j]->setError(linkErrors.value(int(j)));
    }
}

bool RouterScene::portUnder(const QPointF &scenePos, RouterPort *port) const
{
    for (QGraphicsItem *item : items(scenePos, Qt::IntersectsItemBoundingRect)) {
        if (auto *node = dynamic_cast<RouterNodeItem *>(item)) {
            if (node->portAt(scenePos, port))
                return true;
        }
    }
    return false;
}

void RouterScene::mousePressEvent(QGraphicsSceneMouseEvent *event)
{
    RouterPort port;
    if (event->button() == Qt::LeftButton && portUnder(event->scenePos(), &port)) {
        m_dragging = true;
        m_dragFrom = port;
        m_dragWire =
            addPath(QPainterPath(), QPen(RouterNodeItem::portColor(port.type), 2.0, Qt::DashLine));
        m_dragWire->setZValue(2.0);
        event->accept();
        return;
    }
    QGraphicsScene::mousePressEvent(event);
    m_pressPositions.clear();
    for (const RouterNodeItem *item : m_items)
        m_pressPositions[item->id()] = item->pos();
}

void RouterScene::mouseMoveEvent(QGraphicsSceneMouseEvent *event)
{
    if (!m_dragging) {
        QGraphicsScene::mouseMoveEvent(event);
        return;
    }
    const RouterNodeItem *from = nodeItem(m_dragFrom.node);
    const QPointF anchor = from->portScenePos(m_dragFrom.port, m_dragFrom.output);
    m_dragWire->setPath(m_dragFrom.output ? RouterWireItem::curve(anchor, event->scenePos())
                                          : RouterWireItem::curve(event->scenePos(), anchor));
}

void RouterScene::mouseReleaseEvent(QGraphicsSceneMouseEvent *event)
{
    if (!m_dragging) {
        QGraphicsScene::mouseReleaseEvent(event);
        QStringList ids;
        QList<QPointF> from;
        QList<QPointF> to;
        for (const RouterNodeItem *item : m_items) {
            const auto it = m_pressPositions.find(item->id());
            if (it != m_pressPositions.end() && it->second != item->pos()) {
                ids.append(item->id());
                from.append(it->second);
                to.append(item->pos());
            }
        }
        m_pressPositions.clear();
        if (!ids.isEmpty())
            emit nodesMoved(ids, from, to);
        return;
    }
    m_dragging = false;
    delete m_dragWire;
    m_dragWire = nullptr;
    RouterPort target;
    if (!portUnder(event->scenePos(), &target))
        return; // dropped on nothing: no link asked for
    if (target.output == m_dragFrom.output) {
        emit connectRefused(m_dragFrom.output ? tr("an output connects to an input, not to "
                                                   "another output")
                                              : tr("an input connects to an output, not to "
                                                   "another input"),
                            event->scenePos());
        return;
    }
    const RouterPort &out = m_dragFrom.output ? m_dragFrom : target;
    const RouterPort &in = m_dragFrom.output ? target : m_dragFrom;
    // Default ports stay implicit, as the presets write them.
    const auto explicitName = [this](const RouterPort &port) {
        return graph().portOf(port.node, QString(), port.output) == port.port ? QString()
                                                                              : port.port;
    };
    const RouterLink link{out.node, explicitName(out), in.node, explicitName(in)};
    QString reason;
    if (!graph().checkLink(link, &reason))
        emit connectRefused(reason, event->scenePos());
    else
        emit connectRequested(link);
}

void RouterScene::dragEnterEvent(QGraphicsSceneDragDropEvent *event)
{
    event->setAccepted(event->mimeData()->hasFormat(QLatin1String(NodeTypeMime)));
}

void RouterScene::dragMoveEvent(QGraphicsSceneDragDropEvent *event)
{
    event->setAccepted(event->mimeData()->hasFormat(QLatin1String(NodeTypeMime)));
}

void RouterScene::dropEvent(QGraphicsSceneDragDropEvent *event)
{
    const QByteArray type = event->mimeData()->data(QLatin1String(NodeTypeMime));
    if (type.isEmpty())
        return;
    event->acceptProposedAction();
    emit nodeDropped(QString::fromUtf8(type), event->scenePos());
}

void RouterScene::showActivity(const QString &node, const NodeActivity &activity, bool flash)
{
    const NodeActivity was = m_active.value(node);
    m_active.insert(node, activity);
    refreshState(node);
    if (!flash || !activity.isActive() || (was.isActive() && was.sameMessages(activity)))
        return; // nothing new began passing: the wires keep their glow
    const QColor color =
        colors::category(activity.exception ? Category::Exception : Category::Confirmation);
    for (size_t j = 0; j < graph().links.size(); ++j) {
        const RouterLink &link = graph().links[j];
        const bool in = link.to == node && m_active.value(link.from).isActive();
        const int to = link.from == node ? graph().nodeIndex(link.to) : -1;
        // Devices report through their frames, not the router: light the voices into them.
        const bool out = to >= 0 && isDevice(graph().nodes[size_t(to)].type);
        if ((in || out) && m_wires[j])
            m_wires[j]->flash(color);
    }
    if (!m_fadeTimer.isActive())
        m_fadeTimer.start();
}

void RouterScene::refreshState(const QString &id)
{
    RouterNodeItem *item = nodeItem(id);
    if (!item)
        return;
    if (isDevice(item->nodeType())) {
        const double level = m_deviceLevels.value(id, 0.0);
        item->setState(level > 0.0 ? tr("output %1").arg(QLocale().toString(level, 'f', 2))
                                   : QString(),
                       level);
        return;
    }
    const NodeActivity activity = m_active.value(id);
    if (!activity.isActive()) {
        item->setState(QString(), -1.0);
        return;
    }
    QStringList messages;
    for (int i = 0; i < activity.messageCount; ++i)
        messages.append(messageName(Message(activity.messages[size_t(i)])));
    item->setState(tr("%1 %2").arg(messages.join(QLatin1Char('+')),
                                   QLocale().toString(activity.level, 'f', 2)),
                   activity.level);
}

void RouterScene::setDeviceLevel(const QString &device, double level)
{
    m_deviceLevels.insert(device, level);
    refreshState(device);
}

void RouterScene::clearActivity()
{
    m_active.clear();
    m_deviceLevels.clear();
    for (const RouterNodeItem *item : m_items)
        refreshState(item->id());
}

void RouterScene::fade()
{
    bool lit = false;
    for (RouterWireItem *wire : m_wires) {
        if (wire && wire->glow() > 0.0) {
            wire->update();
            lit = true;
        }
    }
    // One more repaint after the last glow ended clears it.
    if (!lit)
        m_fadeTimer.stop();
    for (RouterWireItem *wire : m_wires) {
        if (wire && !lit)
            wire->update();
    }
}

QPointF RouterScene::freePlace(const QPointF &preferred, const QRectF &visible) const
{
    constexpr double Gap = 16.0;
    const QSizeF size(RouterNodeItem::Width, NewNodeHeight);
    QList<QRectF> taken;
    for (const RouterNode &node : graph().nodes) {
        if (const RouterNodeItem *item = nodeItem(node.id))
            taken.append(item->sceneBoundingRect().adjusted(-Gap, -Gap, Gap, Gap));
    }
    const auto free = [&](const QPointF &at) {
        const QRectF place(at, size);
        return std::none_of(taken.begin(), taken.end(),
                            [&](const QRectF &t) { return t.intersects(place); });
    };
    if (free(preferred))
        return preferred;
    // The free place nearest to the preferred one on a half-node grid over the view.
    const QRectF &view = visible;
    const double stepX = size.width() / 2;
    const double stepY = size.height() / 2;
    std::optional<QPointF> best;
    double nearest = 0.0;
    for (double y = view.top(); y + size.height() <= view.bottom(); y += stepY) {
        for (double x = view.left(); x + size.width() <= view.right(); x += stepX) {
            const QPointF at(x, y);
            const double distance = QLineF(at, preferred).length();
            if ((!best || distance < nearest) && free(at)) {
                best = at;
                nearest = distance;
            }
        }
    }
    if (best)
        return *best;
    // Nothing free in sight: beside the graph, to its right.
    return QPointF(itemsBoundingRect().right() + 2 * Gap, preferred.y());
}

} // namespace semhap
