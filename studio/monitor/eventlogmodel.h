// SPDX-License-Identifier: MIT
#pragma once

#include "semanticevent.h"

#include <QAbstractTableModel>

#include <deque>

namespace semhap {

class RunHistory;

/**
 * The semantic events of the live history as table rows, newest last: rows are appended in
 * one batch per history update (the history is read by running index) and the oldest are
 * dropped beyond `maxRows()`, so a long run stays cheap to show.
 */
class EventLogModel : public QAbstractTableModel
{
    Q_OBJECT

public:
    enum Column
    {
        TimeColumn,
        GripperColumn,
        DetectorColumn,
        MessageColumn,
        PhaseColumn,
        IntensityColumn,
        ColumnCount
    };
    /** Raw values for filters and the time cursor, on every column. */
    enum Role
    {
        TimeRole = Qt::UserRole + 1, ///< double, s
        GripperRole,                 ///< int(Gripper)
        CategoryRole,                ///< int(Category)
        PhaseRole,                   ///< int(EventPhase)
    };

    explicit EventLogModel(RunHistory &history, QObject *parent = nullptr);

    /** The most rows kept; older ones are dropped as new ones come. */
    int maxRows() const { return m_maxRows; }
    void setMaxRows(int rows);

    int rowCount(const QModelIndex &parent = QModelIndex()) const override;
    int columnCount(const QModelIndex &parent = QModelIndex()) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

private:
    struct Row
    {
        SemanticEvent event;
        QString node; ///< resolved once: the history may forget the run's node table
    };

    void clear();
    void appendNew();
    void trim();
    QString displayText(const Row &row, int column) const;

    RunHistory &m_history;
    std::deque<Row> m_rows;
    qint64 m_next = 0; ///< the history's running index of the next event to take
    int m_maxRows = 10000;
};

} // namespace semhap
