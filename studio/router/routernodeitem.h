// SPDX-License-Identifier: MIT
#pragma once

#include "routernodetype.h"

#include <QColor>
#include <QGraphicsObject>

#include <vector>

namespace semhap {

/** One end of a link as the editor sees it: a node's port and which side it is on. */
struct RouterPort
{
    QString node;
    QString port;
    bool output = false;
    PortType type = PortType::Event;
};

/**
 * A router node on the editor's canvas: a titled box with its input ports on the left and
 * its outputs on the right, its validation error as a red outline and tooltip, and its live
 * state (the message it plays, a device's level) under the title.
 */
class RouterNodeItem : public QGraphicsObject
{
    Q_OBJECT

public:
    static constexpr double Width = 168.0;

    RouterNodeItem(const QString &id, const QString &type, QGraphicsItem *parent = nullptr);

    const QString &id() const { return m_id; }
    const QString &nodeType() const { return m_type; }
    void setId(const QString &id);
    /** The parameter summary shown under the title (`air.squeeze`, `confirmation`). */
    void setSummary(const QString &summary);
    /** The ports to draw; pattern nodes have one signal input per pattern parameter. */
    void setPorts(const std::vector<PortSpec> &inputs, const std::vector<PortSpec> &outputs);
    const std::vector<PortSpec> &inputs() const { return m_inputs; }
    const std::vector<PortSpec> &outputs() const { return m_outputs; }

    /** The validation error that names this node; empty clears the mark. */
    void setError(const QString &error);
    const QString &error() const { return m_error; }
    /** Live state: what is active here (empty when idle) and a level in [0, 1] (-1: none). */
    void setState(const QString &state, double level);
    const QString &state() const { return m_state; }

    /** Where a port's connector sits, in scene coordinates; null point when unknown. */
    QPointF portScenePos(const QString &port, bool output) const;
    /** The port whose connector is under `scenePos` (within a few pixels). */
    bool portAt(const QPointF &scenePos, RouterPort *port) const;

    /** The colour wires and connectors of a port type are drawn in. */
    static QColor portColor(PortType type);
    /** The header colour of a node type's kind (detector, logic, source, device). */
    static QColor kindColor(const QString &type);

    /** The height a node with these ports is drawn at. */
    static double heightFor(const std::vector<PortSpec> &inputs,
                            const std::vector<PortSpec> &outputs);

    QRectF boundingRect() const override;
    void paint(QPainter *painter, const QStyleOptionGraphicsItem *option,
               QWidget *widget) override;

signals:
    /** The node moved (its wires follow). */
    void moved();

protected:
    QVariant itemChange(GraphicsItemChange change, const QVariant &value) override;

private:
    double height() const;
    QPointF portPos(int index, bool output) const;

    QString m_id;
    QString m_type;
    QString m_summary;
    QString m_error;
    QString m_state;
    double m_level = -1.0;
    std::vector<PortSpec> m_inputs;
    std::vector<PortSpec> m_outputs;
};

} // namespace semhap
