// SPDX-License-Identifier: MIT
#include "eventlogmodel.h"

#include "colors.h"
#include "runhistory.h"

#include <QColor>
#include <QLocale>
#include <QPainter>
#include <QPixmap>

#include <algorithm>

namespace semhap {

namespace {

/** A shape as well as a colour, so the category reads without colour vision. */
QPixmap categorySwatch(Category category)
{
    const int size = 12;
    QPixmap pixmap(size, size);
    pixmap.fill(Qt::transparent);
    QPainter painter(&pixmap);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setPen(QPen(colors::Black, 1.0));
    painter.setBrush(colors::category(category));
    if (category == Category::Confirmation) {
        painter.drawEllipse(QRectF(1.5, 1.5, size - 3.0, size - 3.0));
    } else {
        const QPointF triangle[3] = {
            {size / 2.0, 1.0}, {size - 1.0, size - 1.5}, {1.0, size - 1.5}};
        painter.drawPolygon(triangle, 3);
    }
    return pixmap;
}

} // namespace

EventLogModel::EventLogModel(RunHistory &history, QObject *parent)
    : QAbstractTableModel(parent), m_history(history)
{
    connect(&history, &RunHistory::reset, this, &EventLogModel::clear);
    connect(&history, &RunHistory::updated, this, &EventLogModel::appendNew);
    m_next = history.events().begin();
    appendNew();
}

void EventLogModel::setMaxRows(int rows)
{
    m_maxRows = std::max(1, rows);
    trim();
}

void EventLogModel::clear()
{
    beginResetModel();
    m_rows.clear();
    m_next = m_history.events().end();
    endResetModel();
}

void EventLogModel::appendNew()
{
    const RunSeries<SemanticEvent> &events = m_history.events();
    const qint64 first = std::max(m_next, events.begin());
    const qint64 last = events.end();
    m_next = last;
    if (first >= last)
        return;
    // Events the cap would drop at once are never inserted.
    const qint64 from = std::max(first, last - qint64(m_maxRows));
    const int count = int(last - from);
    const int at = int(m_rows.size());
    beginInsertRows(QModelIndex(), at, at + count - 1);
    for (qint64 i = from; i < last; ++i) {
        const SemanticEvent &event = events.at(i);
        m_rows.push_back({event, m_history.nodeName(event.node)});
    }
    endInsertRows();
    trim();
}

void EventLogModel::trim()
{
    const int excess = int(m_rows.size()) - m_maxRows;
    if (excess <= 0)
        return;
    beginRemoveRows(QModelIndex(), 0, excess - 1);
    m_rows.erase(m_rows.begin(), m_rows.begin() + excess);
    endRemoveRows();
}

int EventLogModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(m_rows.size());
}

int EventLogModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QString EventLogModel::displayText(const Row &row, int column) const
{
    const SemanticEvent &event = row.event;
    switch (column) {
    case TimeColumn:
        return QLocale().toString(event.t, 'f', 3);
    case GripperColumn:
        return gripperName(event.gripper);
    case DetectorColumn:
        return row.node.isEmpty() ? detectorKindName(event.detector)
                                  : tr("%1 (%2)").arg(row.node, detectorKindName(event.detector));
    case MessageColumn:
        return messageName(event.message);
    case PhaseColumn:
        return eventPhaseName(event.phase);
    case IntensityColumn:
        return QLocale().toString(event.intensity, 'f', 2);
    default:
        return QString();
    }
}

QVariant EventLogModel::data(const QModelIndex &index, int role) const
{
    if (!index.isValid() || index.row() >= int(m_rows.size()))
        return {};
    const Row &row = m_rows[size_t(index.row())];
    const SemanticEvent &event = row.event;
    switch (role) {
    case Qt::DisplayRole:
        return displayText(row, index.column());
    case Qt::DecorationRole:
        if (index.column() == MessageColumn) {
            static const QPixmap swatches[2] = {categorySwatch(Category::Confirmation),
                                                categorySwatch(Category::Exception)};
            return swatches[int(event.category)];
        }
        return {};
    case Qt::ToolTipRole:
        if (index.column() == MessageColumn)
            return tr("%1: %2").arg(messageName(event.message), categoryName(event.category));
        return {};
    case Qt::TextAlignmentRole:
        if (index.column() == TimeColumn || index.column() == IntensityColumn)
            return int(Qt::AlignRight | Qt::AlignVCenter);
        return {};
    case TimeRole:
        return event.t;
    case GripperRole:
        return int(event.gripper);
    case CategoryRole:
        return int(event.category);
    case PhaseRole:
        return int(event.phase);
    default:
        return {};
    }
}

QVariant EventLogModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return QAbstractTableModel::headerData(section, orientation, role);
    switch (section) {
    case TimeColumn:
        return tr("Time (s)");
    case GripperColumn:
        return tr("Gripper");
    case DetectorColumn:
        return tr("Detector");
    case MessageColumn:
        return tr("Message");
    case PhaseColumn:
        return tr("Phase");
    case IntensityColumn:
        return tr("Intensity");
    default:
        return {};
    }
}

} // namespace semhap
