// SPDX-License-Identifier: MIT
#pragma once

#include "routernodetype.h"

#include <QColor>
#include <QElapsedTimer>
#include <QGraphicsPathItem>

namespace semhap {

class RouterNodeItem;

/**
 * A link on the editor's canvas: a curve from an output port to an input port in the port
 * type's colour. It lights up in a message's category colour when an event passes along it
 * and fades back over half a second.
 */
class RouterWireItem : public QGraphicsPathItem
{
public:
    /** How long a lit wire takes to fade back (s). */
    static constexpr double FadeSeconds = 0.5;

    RouterWireItem(RouterNodeItem *from, const QString &fromPort, RouterNodeItem *to,
                   const QString &toPort, PortType type);

    RouterNodeItem *fromNode() const { return m_from; }
    RouterNodeItem *toNode() const { return m_to; }
    const QString &fromPort() const { return m_fromPort; }
    const QString &toPort() const { return m_toPort; }

    /** Follows the nodes' ports after a move. */
    void updatePath();
    /** Marks the link refused by validation (drawn dashed, vermillion). */
    void setError(const QString &error);
    /** Lights the wire up now in `color`. */
    void flash(const QColor &color);
    /** How lit the wire is, 1 just flashed, 0 faded; repaints while it fades. */
    double glow() const;

    /** The curve between two points the editor draws wires (and a wire being dragged) with. */
    static QPainterPath curve(const QPointF &from, const QPointF &to);

    QRectF boundingRect() const override;
    QPainterPath shape() const override;
    void paint(QPainter *painter, const QStyleOptionGraphicsItem *option,
               QWidget *widget) override;

private:
    RouterNodeItem *m_from;
    RouterNodeItem *m_to;
    QString m_fromPort;
    QString m_toPort;
    PortType m_type;
    QString m_error;
    QColor m_flashColor;
    QElapsedTimer m_sinceFlash;
};

} // namespace semhap
