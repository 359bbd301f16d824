// SPDX-License-Identifier: MIT
#include "routernodeitem.h"

#include "colors.h"

#include <QFontMetricsF>
#include <QPainter>
#include <QStyleOptionGraphicsItem>

#include <algorithm>

namespace semhap {

namespace {

constexpr double HeaderHeight = 36.0; ///< title and summary
constexpr double StateHeight = 18.0;  ///< the live state line
constexpr double PortSpacing = 18.0;
constexpr double PortRadius = 5.0;
constexpr double HitRadius = 9.0;

} // namespace

RouterNodeItem::RouterNodeItem(const QString &id, const QString &type, QGraphicsItem *parent)
    : QGraphicsObject(parent), m_id(id), m_type(type)
{
    setFlags(ItemIsMovable | ItemIsSelectable | ItemSendsGeometryChanges);
    setZValue(1.0);
    setCacheMode(DeviceCoordinateCache);
}

void RouterNodeItem::setId(const QString &id)
{
    m_id = id;
    update();
}

void RouterNodeItem::setSummary(const QString &summary)
{
    m_summary = summary;
    update();
}

void RouterNodeItem::setPorts(const std::vector<PortSpec> &inputs,
                              const std::vector<PortSpec> &outputs)
{
    prepareGeometryChange();
    m_inputs = inputs;
    m_outputs = outputs;
    emit moved();
}

void RouterNodeItem::setError(const QString &error)
{
    if (error == m_error)
        return;
    m_error = error;
    setToolTip(error);
    update();
}

void RouterNodeItem::setState(const QString &state, double level)
{
    if (state == m_state && level == m_level)
        return;
    m_state = state;
    m_level = level;
    update();
}

double RouterNodeItem::heightFor(const std::vector<PortSpec> &inputs,
                                 const std::vector<PortSpec> &outputs)
{
    const size_t rows = std::max<size_t>({inputs.size(), outputs.size(), 1});
    return HeaderHeight + double(rows) * PortSpacing + StateHeight;
}

double RouterNodeItem::height() const
{
    return heightFor(m_inputs, m_outputs);
}

QPointF RouterNodeItem::portPos(int index, bool output) const
{
    return {output ? Width : 0.0, HeaderHeight + (double(index) + 0.5) * PortSpacing};
}

QPointF RouterNodeItem::portScenePos(const QString &port, bool output) const
{
    const std::vector<PortSpec> &ports = output ? m_outputs : m_inputs;
    for (size_t i = 0; i < ports.size(); ++i) {
        if (ports[i].name == port)
            return mapToScene(portPos(int(i), output));
    }
    return {};
}

bool RouterNodeItem::portAt(const QPointF &scenePos, RouterPort *port) const
{
    const QPointF local = mapFromScene(scenePos);
    for (bool output : {false, true}) {
        const std::vector<PortSpec> &ports = output ? m_outputs : m_inputs;
        for (size_t i = 0; i < ports.size(); ++i) {
            const QPointF d = local - portPos(int(i), output);
            if (d.x() * d.x() + d.y() * d.y() <= HitRadius * HitRadius) {
                *port = {m_id, ports[i].name, output, ports[i].type};
                return true;
            }
        }
    }
    return false;
}

QColor RouterNodeItem::portColor(PortType type)
{
    switch (type) {
    case PortType::Event:
        return colors::Blue;
    case PortType::Signal:
        return colors::Green;
    case PortType::Voice:
        return colors::Purple;
    }
    return colors::Black;
}

QColor RouterNodeItem::kindColor(const QString &type)
{
    // By the type's role in the table, so a new type is coloured without a change here.
    const RouterNodeType *spec = routerNodeType(type);
    switch (spec ? spec->role() : RouterNodeType::Role::Logic) {
    case RouterNodeType::Role::Source:
        return colors::Sky; // where events and signals come from
    case RouterNodeType::Role::Voices:
        return colors::Purple; // what makes voices
    case RouterNodeType::Role::Device:
        return colors::Orange; // what plays
    case RouterNodeType::Role::Logic:
        break;
    }
    return colors::Green; // logic
}

QRectF RouterNodeItem::boundingRect() const
{
    // The connectors stick out on both sides; the error outline is wider than the border.
    return QRectF(-PortRadius - 2, -3, Width + 2 * PortRadius + 4, height() + 6);
}

void RouterNodeItem::paint(QPainter *painter, const QStyleOptionGraphicsItem *, QWidget *)
{
    painter->setRenderHint(QPainter::Antialiasing);
    const QRectF body(0, 0, Width, height());
    const QColor kind = kindColor(m_type);

    // Body, then the header band in the kind's colour, pale so the black title reads.
    painter->setPen(Qt::NoPen);
    painter->setBrush(colors::Card);
    painter->drawRoundedRect(body, 6, 6);
    painter->setBrush(kind.lighter(150));
    painter->drawRoundedRect(QRectF(0, 0, Width, HeaderHeight), 6, 6);
    painter->drawRect(QRectF(0, HeaderHeight - 6, Width, 6));

    QPen border(colors::MutedText, 1.0);
    if (isSelected())
        border = QPen(colors::Confirmation, 2.5);
    if (!m_error.isEmpty())
        border = QPen(colors::Error, isSelected() ? 3.5 : 2.5);
    painter->setPen(border);
    painter->setBrush(Qt::NoBrush);
    painter->drawRoundedRect(body, 6, 6);

    QFont titleFont = painter->font();
    titleFont.setBold(true);
    painter->setFont(titleFont);
    painter->setPen(Qt::black);
    const QRectF titleRect(6, 2, Width - 12, 17);
    painter->drawText(
        titleRect, Qt::AlignLeft | Qt::AlignVCenter,
        QFontMetricsF(titleFont).elidedText(m_id, Qt::ElideMiddle, titleRect.width()));
    QFont small = painter->font();
    small.setBold(false);
    small.setPointSizeF(small.pointSizeF() * 0.9);
    painter->setFont(small);
    painter->setPen(colors::Text);
    const QRectF summaryRect(6, 18, Width - 12, 16);
    const QString summary =
        m_summary.isEmpty() ? m_type : m_type + QStringLiteral(" · ") + m_summary;
    painter->drawText(
        summaryRect, Qt::AlignLeft | Qt::AlignVCenter,
        QFontMetricsF(small).elidedText(summary, Qt::ElideRight, summaryRect.width()));

    // Ports: a filled connector in the port type's colour and the port's name inside.
    for (bool output : {false, true}) {
        const std::vector<PortSpec> &ports = output ? m_outputs : m_inputs;
        for (size_t i = 0; i < ports.size(); ++i) {
            const QPointF p = portPos(int(i), output);
            painter->setPen(QPen(Qt::white, 1.0));
            painter->setBrush(portColor(ports[i].type));
            painter->drawEllipse(p, PortRadius, PortRadius);
            painter->setPen(colors::StrongText);
            const QRectF label(output ? Width / 2 : PortRadius + 4, p.y() - PortSpacing / 2,
                               Width / 2 - PortRadius - 8, PortSpacing);
            painter->drawText(label, (output ? Qt::AlignRight : Qt::AlignLeft) | Qt::AlignVCenter,
                              ports[i].name);
        }
    }

    // Live state: a level bar behind the text, in the warm colour of activity.
    const QRectF stateRect(6, height() - StateHeight - 1, Width - 12, StateHeight - 3);
    if (m_level > 0.0) {
        painter->setPen(Qt::NoPen);
        painter->setBrush(colors::Activity);
        painter->drawRoundedRect(QRectF(stateRect.left(), stateRect.top(),
                                        stateRect.width() * std::min(m_level, 1.0),
                                        stateRect.height()),
                                 3, 3);
    }
    if (!m_state.isEmpty()) {
        painter->setPen(Qt::black);
        painter->drawText(
            stateRect, Qt::AlignLeft | Qt::AlignVCenter,
            QFontMetricsF(small).elidedText(m_state, Qt::ElideRight, stateRect.width()));
    }
}

QVariant RouterNodeItem::itemChange(GraphicsItemChange change, const QVariant &value)
{
    if (change == ItemPositionHasChanged)
        emit moved();
    return QGraphicsObject::itemChange(change, value);
}

} // namespace semhap
