// SPDX-License-Identifier: MIT
#include "routerwireitem.h"

#include "colors.h"
#include "routernodeitem.h"

#include <QPainter>
#include <QPainterPathStroker>

#include <algorithm>
#include <cmath>

namespace semhap {

RouterWireItem::RouterWireItem(RouterNodeItem *from, const QString &fromPort, RouterNodeItem *to,
                               const QString &toPort, PortType type)
    : m_from(from), m_to(to), m_fromPort(fromPort), m_toPort(toPort), m_type(type)
{
    setFlag(ItemIsSelectable);
    setZValue(0.0);
    updatePath();
}

QPainterPath RouterWireItem::curve(const QPointF &from, const QPointF &to)
{
    // Horizontal tangents at both ends, as signal flow reads left to right.
    const double dx = std::max(40.0, std::abs(to.x() - from.x()) / 2);
    QPainterPath path(from);
    path.cubicTo(from + QPointF(dx, 0), to - QPointF(dx, 0), to);
    return path;
}

void RouterWireItem::updatePath()
{
    setPath(curve(m_from->portScenePos(m_fromPort, true), m_to->portScenePos(m_toPort, false)));
}

void RouterWireItem::setError(const QString &error)
{
    if (error == m_error)
        return;
    m_error = error;
    setToolTip(error);
    update();
}

void RouterWireItem::flash(const QColor &color)
{
    m_flashColor = color;
    m_sinceFlash.start();
    update();
}

double RouterWireItem::glow() const
{
    if (!m_sinceFlash.isValid())
        return 0.0;
    const double age = double(m_sinceFlash.elapsed()) / 1000.0;
    return std::clamp(1.0 - age / FadeSeconds, 0.0, 1.0);
}

QRectF RouterWireItem::boundingRect() const
{
    return path().boundingRect().adjusted(-8, -8, 8, 8);
}

QPainterPath RouterWireItem::shape() const
{
    QPainterPathStroker stroker;
    stroker.setWidth(10);
    return stroker.createStroke(path());
}

void RouterWireItem::paint(QPainter *painter, const QStyleOptionGraphicsItem *, QWidget *)
{
    painter->setRenderHint(QPainter::Antialiasing);
    const double lit = glow();
    if (lit > 0.0) {
        QColor halo = m_flashColor;
        halo.setAlphaF(float(0.85 * lit));
        painter->setPen(QPen(halo, 3.0 + 6.0 * lit, Qt::SolidLine, Qt::RoundCap));
        painter->drawPath(path());
    }
    QColor color = m_error.isEmpty() ? RouterNodeItem::portColor(m_type) : colors::Error;
    QPen pen(color, isSelected() ? 4.0 : 2.0);
    if (!m_error.isEmpty())
        pen.setStyle(Qt::DashLine);
    painter->setPen(pen);
    painter->drawPath(path());
}

} // namespace semhap
