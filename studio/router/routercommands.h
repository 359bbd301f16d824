// SPDX-License-Identifier: MIT
#pragma once

#include "routergraph.h"

#include <QCoreApplication>
#include <QList>
#include <QPointF>
#include <QUndoCommand>

#include <vector>

namespace semhap {

class RouterDocument;

/** Adds a node (the palette, paste). */
class AddNodeCommand : public QUndoCommand
{
    Q_DECLARE_TR_FUNCTIONS(RouterCommands)

public:
    AddNodeCommand(RouterDocument *document, const RouterNode &node,
                   QUndoCommand *parent = nullptr);
    void redo() override;
    void undo() override;

private:
    RouterDocument *m_document;
    RouterNode m_node;
    int m_index = -1;
};

/** Removes nodes with every link that touches them, and links on their own (delete, cut). */
class RemoveCommand : public QUndoCommand
{
    Q_DECLARE_TR_FUNCTIONS(RouterCommands)

public:
    RemoveCommand(RouterDocument *document, const QStringList &nodeIds,
                  const std::vector<int> &links, QUndoCommand *parent = nullptr);
    void redo() override;
    void undo() override;

private:
    RouterDocument *m_document;
    /** What went, by index in the graph, ascending: put back in this order, it is exact. */
    std::vector<std::pair<int, RouterNode>> m_nodes;
    std::vector<std::pair<int, RouterLink>> m_links;
};

/** Moves nodes (a drag, arranging). */
class MoveNodesCommand : public QUndoCommand
{
    Q_DECLARE_TR_FUNCTIONS(RouterCommands)

public:
    MoveNodesCommand(RouterDocument *document, const QStringList &ids, const QList<QPointF> &from,
                     const QList<QPointF> &to, QUndoCommand *parent = nullptr);
    void redo() override;
    void undo() override;

private:
    RouterDocument *m_document;
    QStringList m_ids;
    QList<QPointF> m_from;
    QList<QPointF> m_to;
};

/** Links an output port to an input port. */
class ConnectCommand : public QUndoCommand
{
    Q_DECLARE_TR_FUNCTIONS(RouterCommands)

public:
    ConnectCommand(RouterDocument *document, const RouterLink &link,
                   QUndoCommand *parent = nullptr);
    void redo() override;
    void undo() override;

private:
    RouterDocument *m_document;
    RouterLink m_link;
    int m_index = -1;
};

/** Sets one parameter of a node; an undefined value removes it (back to the default). */
class SetParamCommand : public QUndoCommand
{
    Q_DECLARE_TR_FUNCTIONS(RouterCommands)

public:
    SetParamCommand(RouterDocument *document, const QString &id, const QString &key,
                    const QJsonValue &value, QUndoCommand *parent = nullptr);
    void redo() override;
    void undo() override;

private:
    RouterDocument *m_document;
    QString m_id;
    QJsonObject m_before;
    QJsonObject m_after;
};

/** Renames a node, and the links that name it. */
class RenameNodeCommand : public QUndoCommand
{
    Q_DECLARE_TR_FUNCTIONS(RouterCommands)

public:
    RenameNodeCommand(RouterDocument *document, const QString &from, const QString &to,
                      QUndoCommand *parent = nullptr);
    void redo() override;
    void undo() override;

private:
    RouterDocument *m_document;
    QString m_from;
    QString m_to;
};

} // namespace semhap
