// SPDX-License-Identifier: MIT
#include "routercommands.h"

#include "routerdocument.h"

#include <algorithm>

namespace semhap {

AddNodeCommand::AddNodeCommand(RouterDocument *document, const RouterNode &node,
                               QUndoCommand *parent)
    : QUndoCommand(tr("Add %1").arg(node.id), parent), m_document(document), m_node(node)
{}

void AddNodeCommand::redo()
{
    m_index = int(m_document->graph().nodes.size());
    m_document->insertNode(m_index, m_node);
}

void AddNodeCommand::undo()
{
    m_document->removeNode(m_index);
}

RemoveCommand::RemoveCommand(RouterDocument *document, const QStringList &nodeIds,
                             const std::vector<int> &links, QUndoCommand *parent)
    : QUndoCommand(parent), m_document(document)
{
    const RouterGraph &graph = document->graph();
    for (size_t i = 0; i < graph.nodes.size(); ++i) {
        if (nodeIds.contains(graph.nodes[i].id))
            m_nodes.emplace_back(int(i), graph.nodes[i]);
    }
    for (size_t j = 0; j < graph.links.size(); ++j) {
        const RouterLink &link = graph.links[j];
        if (std::find(links.begin(), links.end(), int(j)) != links.end() ||
            nodeIds.contains(link.from) || nodeIds.contains(link.to))
            m_links.emplace_back(int(j), link);
    }
    setText(m_nodes.empty() ? tr("Disconnect") : tr("Delete"));
}

void RemoveCommand::redo()
{
    for (auto it = m_links.rbegin(); it != m_links.rend(); ++it)
        m_document->removeLink(it->first);
    for (auto it = m_nodes.rbegin(); it != m_nodes.rend(); ++it)
        m_document->removeNode(it->first);
}

void RemoveCommand::undo()
{
    for (const auto &[index, node] : m_nodes)
        m_document->insertNode(index, node);
    for (const auto &[index, link] : m_links)
        m_document->insertLink(index, link);
}

MoveNodesCommand::MoveNodesCommand(RouterDocument *document, const QStringList &ids,
                                   const QList<QPointF> &from, const QList<QPointF> &to,
                                   QUndoCommand *parent)
    : QUndoCommand(tr("Move"), parent), m_document(document), m_ids(ids), m_from(from), m_to(to)
{}

void MoveNodesCommand::redo()
{
    for (int i = 0; i < m_ids.size(); ++i)
        m_document->setNodePos(m_ids[i], m_to[i]);
}

void MoveNodesCommand::undo()
{
    for (int i = 0; i < m_ids.size(); ++i)
        m_document->setNodePos(m_ids[i], m_from[i]);
}

ConnectCommand::ConnectCommand(RouterDocument *document, const RouterLink &link,
                               QUndoCommand *parent)
    : QUndoCommand(tr("Connect %1 to %2").arg(link.from, link.to), parent), m_document(document),
      m_link(link)
{}

void ConnectCommand::redo()
{
    m_index = int(m_document->graph().links.size());
    m_document->insertLink(m_index, m_link);
}

void ConnectCommand::undo()
{
    m_document->removeLink(m_index);
}

SetParamCommand::SetParamCommand(RouterDocument *document, const QString &id, const QString &key,
                                 const QJsonValue &value, QUndoCommand *parent)
    : QUndoCommand(tr("Set %1.%2").arg(id, key), parent), m_document(document), m_id(id)
{
    m_before = document->graph().nodes[size_t(document->graph().nodeIndex(id))].params;
    m_after = m_before;
    if (value.isUndefined())
        m_after.remove(key);
    else
        m_after.insert(key, value);
}

void SetParamCommand::redo()
{
    m_document->setNodeParams(m_id, m_after);
}

void SetParamCommand::undo()
{
    m_document->setNodeParams(m_id, m_before);
}

RenameNodeCommand::RenameNodeCommand(RouterDocument *document, const QString &from,
                                     const QString &to, QUndoCommand *parent)
    : QUndoCommand(tr("Rename %1 to %2").arg(from, to), parent), m_document(document),
      m_from(from), m_to(to)
{}

void RenameNodeCommand::redo()
{
    m_document->renameNode(m_from, m_to);
}

void RenameNodeCommand::undo()
{
    m_document->renameNode(m_to, m_from);
}

} // namespace semhap
