// SPDX-License-Identifier: MIT
#pragma once

#include "paneldock.h"

#include <QStringList>
#include <QWidget>

#include <memory>
#include <vector>

class QLabel;
class QLineEdit;
class QSplitter;
class QTimer;
class QScrollArea;
class QTreeWidget;
class QVBoxLayout;

namespace semhap {

class DeviceManager;
class RunHistory;

/**
 * The wristbands of a session: the devices present (hot-plug by polling, plus addresses the
 * user adds), one row per router device to bind it to one of them, with its transport's
 * state, rates and errors and a level meter of its latest output, and arming for all.
 * Binding is only requested (`bindRequested`): the engine rebinds at a tick boundary.
 */
class DevicesPanel : public QWidget
{
    Q_OBJECT

public:
    /** Where the main window docks it by default (PanelDock). */
    static PanelDock dock();
    DevicesPanel(DeviceManager &manager, RunHistory &history, QWidget *parent = nullptr);
    ~DevicesPanel() override;

public slots:
    /** Re-reads the bindings' status (also done a few times a second). */
    void refresh();
    /** Lists the present devices again and offers them to every row. */
    void rescan();

signals:
    /**
     * The user wants router device `name` driven by `uri`; disconnecting asks for
     * `virtual:NAME`, so the run keeps going without the band.
     */
    void bindRequested(const QString &name, const QString &uri);
    /** The user added an address to the listing (DeviceManager::addConfigured). */
    void addressAdded(const QString &uri);

protected:
    void showEvent(QShowEvent *event) override;
    void resizeEvent(QResizeEvent *event) override;
    /**
     * The wheel over a row's address box that has no focus scrolls the rows instead; a
     * notch scrolls them by a row.
     */
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    struct Row;

    void rebuildRows();
    /** Each device's meter beside its controls in a wide dock, under them in a narrow one. */
    void layOutRows();
    void addAddress();
    void requestBind(Row &row, const QString &uri);
    void showLevels();
    void showMessage(const QString &text);

    DeviceManager &m_manager;
    RunHistory &m_history;
    QTreeWidget *m_present = nullptr;
    QLineEdit *m_address = nullptr;
    QLabel *m_message = nullptr;
    QVBoxLayout *m_rowsLayout = nullptr;
    QScrollArea *m_rowsScroll = nullptr;
    QLabel *m_armed = nullptr;
    QTimer *m_pollTimer = nullptr;
    QTimer *m_statusTimer = nullptr;
    QSplitter *m_splitter = nullptr;
    bool m_splitterPlaced = false;
    std::vector<std::unique_ptr<Row>> m_rows;
    QStringList m_presentUris;
};

} // namespace semhap
