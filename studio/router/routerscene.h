// SPDX-License-Identifier: MIT
#pragma once

#include "nodeactivity.h"
#include "routergraph.h"
#include "routernodeitem.h"
#include "semanticevent.h"

#include <QGraphicsScene>
#include <QHash>
#include <QMap>
#include <QTimer>

#include <map>
#include <vector>

class QGraphicsPathItem;

namespace semhap {

class RouterWireItem;

/**
 * The router editor's canvas and the document it shows: it owns the RouterGraph and keeps
 * one node item per node and one wire per link in step with it. The edit functions are
 * what the undo commands call; mouse gestures only ask for edits (signals), so every edit
 * goes through the undo stack. It also checks a link before it is made, with the
 * compiler's rules, and shows validation errors and live activity.
 */
class RouterScene : public QGraphicsScene
{
    Q_OBJECT

public:
    /** The MIME type of a palette entry dragged onto the canvas (the node type, UTF-8). */
    static constexpr const char *NodeTypeMime = "application/x-semhap-node-type";

    explicit RouterScene(QObject *parent = nullptr);

    /** Shows `graph`; nodes without a position in `ui` are laid out in columns by kind. */
    void setGraph(const RouterGraph &graph);
    /** The document, node positions in `ui` included. */
    const RouterGraph &graph() const { return m_graph; }

    void insertNode(int index, const RouterNode &node);
    void removeNode(int index);
    void insertLink(int index, const RouterLink &link);
    void removeLink(int index);
    void setNodeParams(const QString &id, const QJsonObject &params);
    void setNodePos(const QString &id, const QPointF &pos);
    /** Renames a node and the links that name it. */
    void renameNode(const QString &from, const QString &to);

    RouterNodeItem *nodeItem(const QString &id) const;
    /** The wire of link `index`, or null when the link does not resolve to ports. */
    RouterWireItem *wireItem(int index) const;
    /** Ids of the selected nodes, in graph order. */
    QStringList selectedNodeIds() const;
    /** Indexes of the selected wires' links. */
    std::vector<int> selectedLinks() const;

    /** `base` if no node has that id, else `base` with the lowest free number appended. */
    QString uniqueId(const QString &base) const;
    /** Positions in columns by kind (detectors, logic, sources, devices), rows by flow. */
    std::map<QString, QPointF> arrangedPositions() const;
    static QPointF nodePos(const RouterNode &node);

    /** Marks nodes and links with the validation errors (by node id and link index). */
    void setErrors(const QHash<QString, QString> &nodeErrors,
                   const QHash<int, QString> &linkErrors);

    /**
     * Shows what node `node` passes on now, as the running router reports it: its state
     * line, and a flash on each wire into it from a node that passes something (and, for
     * a node that plays, on its wires to the devices).
     */
    void showActivity(const QString &node, const NodeActivity &activity, bool flash = true);
    /** A device's current output level (max over its channels, 0..1). */
    void setDeviceLevel(const QString &device, double level);
    /** Forgets the live state (a new run). */
    void clearActivity();

signals:
    /** The document changed (any edit, undo or redo). */
    void graphChanged();
    /** The user dragged a wire between two ports that may be linked. */
    void connectRequested(const semhap::RouterLink &link);
    /** The user dropped a wire where it cannot go; `reason` says why. */
    void connectRefused(const QString &reason, const QPointF &scenePos);
    /** The user dragged nodes: where they were and where they are now. */
    void nodesMoved(const QStringList &ids, const QList<QPointF> &from, const QList<QPointF> &to);
    /** A palette entry was dropped on the canvas. */
    void nodeDropped(const QString &type, const QPointF &scenePos);

protected:
    void mousePressEvent(QGraphicsSceneMouseEvent *event) override;
    void mouseMoveEvent(QGraphicsSceneMouseEvent *event) override;
    void mouseReleaseEvent(QGraphicsSceneMouseEvent *event) override;
    void dragEnterEvent(QGraphicsSceneDragDropEvent *event) override;
    void dragMoveEvent(QGraphicsSceneDragDropEvent *event) override;
    void dropEvent(QGraphicsSceneDragDropEvent *event) override;

private:
    RouterNodeItem *makeItem(const RouterNode &node);
    void refreshNode(RouterNodeItem *item, const RouterNode &node);
    void rebuildWires();
    void updateWires(RouterNodeItem *item);
    bool portUnder(const QPointF &scenePos, RouterPort *port) const;
    void refreshState(const QString &id);
    void fade();

    RouterGraph m_graph;
    std::vector<RouterNodeItem *> m_items; ///< parallel to m_graph.nodes
    std::vector<RouterWireItem *> m_wires; ///< parallel to m_graph.links; null: unresolved
    QHash<QString, QString> m_nodeErrors;
    QHash<int, QString> m_linkErrors;

    // A wire being dragged out of a port.
    bool m_dragging = false;
    RouterPort m_dragFrom;
    QGraphicsPathItem *m_dragWire = nullptr;
    // Node positions when a press began, to tell a move from a click.
    std::map<QString, QPointF> m_pressPositions;

    /** Per node, what the router last said it passes on. */
    QHash<QString, NodeActivity> m_active;
    QHash<QString, double> m_deviceLevels;
    QTimer m_fadeTimer;
};

} // namespace semhap
