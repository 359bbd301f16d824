// SPDX-License-Identifier: MIT
#pragma once

#include "paneldock.h"

#include <QWidget>

class QCheckBox;
class QComboBox;
class QLineEdit;
class QModelIndex;
class QTableView;

namespace semhap {

class EventLogFilter;
class EventLogModel;
class RunHistory;

/**
 * The semantic events of the run as a filterable log: a table (time, gripper, detector,
 * message, phase, intensity) with a text filter and gripper, category and phase choices;
 * it follows the newest event unless told not to, and selecting an event tells the plots
 * where to put their cursor.
 */
class EventLogPanel : public QWidget
{
    Q_OBJECT

public:
    /** Where the main window docks it by default (PanelDock). */
    static PanelDock dock();
    explicit EventLogPanel(RunHistory &history, QWidget *parent = nullptr);
    ~EventLogPanel() override;

    EventLogModel *model() const { return m_model; }
    QTableView *view() const { return m_view; }

signals:
    /** The user picked the event at pipeline time `t` (s). */
    void eventActivated(double t);

private:
    void rowsAppended();
    void activateRow(const QModelIndex &proxyIndex);

    EventLogModel *m_model = nullptr;
    EventLogFilter *m_filter = nullptr;
    QTableView *m_view = nullptr;
    QLineEdit *m_text = nullptr;
    QComboBox *m_gripper = nullptr;
    QComboBox *m_category = nullptr;
    QComboBox *m_phase = nullptr;
    QCheckBox *m_follow = nullptr;
    int m_emittedRow = -1; ///< the proxy row a selection change just reported
};

} // namespace semhap
