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

class RouterDocument;
class RouterWireItem;

/**
 * The router editor's canvas, a view of a RouterDocument: one node item per node and one
 * wire per link, kept in step with the document's change signals. It never edits the
 * document; mouse gestures only ask for edits (signals), so every edit goes through the
 * document's undo stack. It checks a link before asking for it, with the core's rules
 * (RouterGraph::checkLink), and shows validation errors and the running router's activity.
 */
class RouterScene : public QGraphicsScene
{
    Q_OBJECT

public:
    /** The MIME type of a palette entry dragged onto the canvas (the node type, UTF-8). */
    static constexpr const char *NodeTypeMime = "application/x-semhap-node-type";

    explicit RouterScene(const RouterDocument &document, QObject *parent = nullptr);

    /** The document's graph, as shown. */
    const RouterGraph &graph() const;

    RouterNodeItem *nodeItem(const QString &id) const;
    /** The wire of link `index`, or null when the link does not resolve to ports. */
    RouterWireItem *wireItem(int index) const;
    /**
     * Where a new node goes near `preferred` (its top left) without covering another: there
     * if it is free, else the nearest free place in `visible` (the view's part of the
     * scene), else right of the graph.
     */
    QPointF freePlace(const QPointF &preferred, const QRectF &visible) const;
    /** The room a new node is given: most nodes' height with their ports. */
    static constexpr double NewNodeHeight = 100.0;
    /** Ids of the selected nodes, in graph order. */
    QStringList selectedNodeIds() const;
    /** Indexes of the selected wires' links. */
    std::vector<int> selectedLinks() const;

    /**
     * Positions for `graph`'s nodes in columns by role (sources, logic, voices, devices),
     * rows by flow, spaced by the height each node is drawn at.
     */
    static std::map<QString, QPointF> arrangedPositions(const RouterGraph &graph);
    /** `graph` with every node that has no position (the presets) laid out; others keep theirs. */
    static RouterGraph placed(const RouterGraph &graph);

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
    void rebuild();
    void insertItem(int index);
    void removeItem(int index);
    void renameItem(int index, const QString &from);
    RouterNodeItem *makeItem(const RouterNode &node);
    void refreshNode(RouterNodeItem *item, const RouterNode &node);
    void rebuildWires();
    void updateWires(RouterNodeItem *item);
    bool portUnder(const QPointF &scenePos, RouterPort *port) const;
    void refreshState(const QString &id);
    void fade();

    const RouterDocument &m_document;
    std::vector<RouterNodeItem *> m_items; ///< parallel to graph().nodes
    std::vector<RouterWireItem *> m_wires; ///< parallel to graph().links; null: unresolved
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
