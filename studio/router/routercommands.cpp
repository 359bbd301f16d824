// SPDX-License-Identifier: MIT
#include "routercommands.h"

#include "routerscene.h"

#include <algorithm>

namespace semhap {

AddNodeCommand::AddNodeCommand(RouterScene *scene, const RouterNode &node, QUndoCommand *parent)
    : QUndoCommand(tr("Add %1").arg(node.id), parent), m_scene(scene), m_node(node)
{}

void AddNodeCommand::redo()
{
    m_index = int(m_scene->graph().nodes.size());
    m_scene->insertNode(m_index, m_node);
}

void AddNodeCommand::undo()
{
    m_scene->removeNode(m_index);
}

RemoveCommand::RemoveCommand(RouterScene *scene, const QStringList &nodeIds,
                             const std::vector<int> &links, QUndoCommand *parent)
    : QUndoCommand(parent), m_scene(scene)
{
    const RouterGraph &graph = scene->graph();
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
        m_scene->removeLink(it->first);
    for (auto it = m_nodes.rbegin(); it != m_nodes.rend(); ++it)
        m_scene->removeNode(it->first);
}

void RemoveCommand::undo()
{
    for (const auto &[index, node] : m_nodes)
        m_scene->insertNode(index, node);
    for (const auto &[index, link] : m_links)
        m_scene->insertLink(index, link);
}

MoveNodesCommand::MoveNodesCommand(RouterScene *scene, const QStringList &ids,
                                   const QList<QPointF> &from, const QList<QPointF> &to,
                                   QUndoCommand *parent)
    : QUndoCommand(tr("Move"), parent), m_scene(scene), m_ids(ids), m_from(from), m_to(to)
{}

void MoveNodesCommand::redo()
{
    for (int i = 0; i < m_ids.size(); ++i)
        m_scene->setNodePos(m_ids[i], m_to[i]);
}

void MoveNodesCommand::undo()
{
    for (int i = 0; i < m_ids.size(); ++i)
        m_scene->setNodePos(m_ids[i], m_from[i]);
}

ConnectCommand::ConnectCommand(RouterScene *scene, const RouterLink &link, QUndoCommand *parent)
    : QUndoCommand(tr("Connect %1 to %2").arg(link.from, link.to), parent), m_scene(scene),
      m_link(link)
{}

void ConnectCommand::redo()
{
    m_index = int(m_scene->graph().links.size());
    m_scene->insertLink(m_index, m_link);
}

void ConnectCommand::undo()
{
    m_scene->removeLink(m_index);
}

SetParamCommand::SetParamCommand(RouterScene *scene, const QString &id, const QString &key,
                                 const QJsonValue &value, QUndoCommand *parent)
    : QUndoCommand(tr("Set %1.%2").arg(id, key), parent), m_scene(scene), m_id(id)
{
    m_before = scene->graph().nodes[size_t(scene->graph().nodeIndex(id))].params;
    m_after = m_before;
    if (value.isUndefined())
        m_after.remove(key);
    else
        m_after.insert(key, value);
}

void SetParamCommand::redo()
{
    m_scene->setNodeParams(m_id, m_after);
}

void SetParamCommand::undo()
{
    m_scene->setNodeParams(m_id, m_before);
}

RenameNodeCommand::RenameNodeCommand(RouterScene *scene, const QString &from, const QString &to,
                                     QUndoCommand *parent)
    : QUndoCommand(tr("Rename %1 to %2").arg(from, to), parent), m_scene(scene), m_from(from),
      m_to(to)
{}

void RenameNodeCommand::redo()
{
    m_scene->renameNode(m_from, m_to);
}

void RenameNodeCommand::undo()
{
    m_scene->renameNode(m_to, m_from);
}

} // namespace semhap
