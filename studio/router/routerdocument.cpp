// SPDX-License-Identifier: MIT
#include "routerdocument.h"

#include "outputfile.h"

#include <QJsonDocument>
#include <QUndoStack>

namespace semhap {

RouterDocument::RouterDocument(QObject *parent) : QObject(parent), m_undo(new QUndoStack(this)) {}

RouterDocument::~RouterDocument() = default;

bool RouterDocument::isModified() const
{
    return !m_undo->isClean();
}

void RouterDocument::reset(const RouterGraph &graph, const QString &path)
{
    m_undo->clear();
    m_graph = graph;
    m_path = path;
    emit graphReset();
    emit changed();
}

bool RouterDocument::save(const QString &path, bool selfContained, QString *error)
{
    RouterGraph graph = m_graph;
    LoadError failure;
    if (selfContained && !graph.embedFiles(&failure)) {
        *error = failure.toString();
        return false;
    }
    if (!OutputFile::write(path, QJsonDocument(graph.toJson()).toJson(QJsonDocument::Indented),
                           &failure)) {
        *error = failure.toString();
        return false;
    }
    m_path = path;
    m_undo->setClean();
    return true;
}

QString RouterDocument::uniqueId(const QString &base) const
{
    if (m_graph.nodeIndex(base) < 0)
        return base;
    for (int n = 2;; ++n) {
        const QString id = base + QString::number(n);
        if (m_graph.nodeIndex(id) < 0)
            return id;
    }
}

QPointF RouterDocument::nodePos(const RouterNode &node)
{
    return {node.ui.value(QLatin1String("x")).toDouble(),
            node.ui.value(QLatin1String("y")).toDouble()};
}

void RouterDocument::insertNode(int index, const RouterNode &node)
{
    m_graph.nodes.insert(m_graph.nodes.begin() + index, node);
    emit nodeInserted(index);
    emit changed();
}

void RouterDocument::removeNode(int index)
{
    m_graph.nodes.erase(m_graph.nodes.begin() + index);
    emit nodeRemoved(index);
    emit changed();
}

void RouterDocument::insertLink(int index, const RouterLink &link)
{
    m_graph.links.insert(m_graph.links.begin() + index, link);
    emit linksChanged();
    emit changed();
}

void RouterDocument::removeLink(int index)
{
    m_graph.links.erase(m_graph.links.begin() + index);
    emit linksChanged();
    emit changed();
}

void RouterDocument::setNodeParams(const QString &id, const QJsonObject &params)
{
    const int index = m_graph.nodeIndex(id);
    m_graph.nodes[size_t(index)].params = params;
    emit nodeParamsChanged(index);
    emit changed();
}

void RouterDocument::setNodePos(const QString &id, const QPointF &pos)
{
    const int index = m_graph.nodeIndex(id);
    RouterNode &node = m_graph.nodes[size_t(index)];
    node.ui.insert(QStringLiteral("x"), pos.x());
    node.ui.insert(QStringLiteral("y"), pos.y());
    emit nodeMoved(index);
    emit changed();
}

void RouterDocument::renameNode(const QString &from, const QString &to)
{
    const int index = m_graph.nodeIndex(from);
    m_graph.nodes[size_t(index)].id = to;
    for (RouterLink &link : m_graph.links) {
        if (link.from == from)
            link.from = to;
        if (link.to == from)
            link.to = to;
    }
    emit nodeRenamed(index, from);
    emit linksChanged();
    emit changed();
}

} // namespace semhap
