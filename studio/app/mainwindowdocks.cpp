// SPDX-License-Identifier: MIT
// MainWindow's docks: the panels, where they sit by default, and the layout the user left.
#include "mainwindow.h"

#include "devicespanel.h"
#include "eventlogpanel.h"
#include "metricspanel.h"
#include "plotpanel.h"
#include "routereditor.h"
#include "routergraph.h"
#include "simviewport.h"
#include "studydocument.h"
#include "studymenu.h"
#include "studypanel.h"
#include "waveformdesigner.h"
#include "workspace.h"

#include <QDockWidget>
#include <QSettings>
#include <QStatusBar>

#include <utility>
#include <vector>

namespace semhap {

void MainWindow::createDocks()
{
    m_plots = new PlotPanel(m_engine.history(), this);
    m_eventLog = new EventLogPanel(m_engine.history(), this);
    m_devicesPanel = new DevicesPanel(m_engine.devices(), m_engine.history(), this);
    m_metricsPanel = new MetricsPanel(m_engine.history(), this);
    m_routerEditor = new RouterEditor(&m_workspace.routerDocument(), this);
    m_routerEditor->setHistory(&m_engine.history());
    m_routerEditor->setApplyFunction([this](const RouterGraph &graph, QString *error) {
        return m_engine.setRouter(graph, error);
    });
    m_routerEditor->setContextFunction([this] { return m_engine.routerContext(); });
    m_designer = new WaveformDesigner(&m_engine.devices(), &m_workspace.patternDocument(), this);
    m_designer->setRunClock([this] { return m_engine.readoutTime(); });

    m_studyPanel = new StudyPanel(m_workspace.study(), m_engine, this);
    m_studyPanel->setStudyActions(m_studyMenu->newStudyAction(), m_studyMenu->openStudyAction());

    // Each panel says where it docks; the plots run the full height on the right, the log,
    // devices and metrics share the space under the viewport, and the panels that want the
    // plots' room sit behind them as tabs.
    setDockNestingEnabled(true);
    setCorner(Qt::BottomRightCorner, Qt::RightDockWidgetArea);
    setCorner(Qt::TopRightCorner, Qt::RightDockWidgetArea);
    const std::pair<QWidget *, PanelDock> panels[] = {
        {m_plots, PlotPanel::dock()},           {m_routerEditor, RouterEditor::dock()},
        {m_designer, WaveformDesigner::dock()}, {m_studyPanel, StudyPanel::dock()},
        {m_eventLog, EventLogPanel::dock()},    {m_devicesPanel, DevicesPanel::dock()},
        {m_metricsPanel, MetricsPanel::dock()},
    };
    std::vector<QDockWidget *> front;
    for (const auto &[panel, place] : panels) {
        auto *dock = new QDockWidget(place.title, this);
        dock->setObjectName(place.name);
        dock->setWidget(panel);
        addDockWidget(place.side == PanelDock::Side::Right ? Qt::RightDockWidgetArea
                                                           : Qt::BottomDockWidgetArea,
                      dock);
        if (place.tabbedWith.isEmpty())
            front.push_back(dock);
        else
            tabifyDockWidget(findChild<QDockWidget *>(place.tabbedWith), dock);
    }
    for (QDockWidget *dock : front)
        dock->raise();

    connect(m_eventLog, &EventLogPanel::eventActivated, m_plots, &PlotPanel::setCursorTime);
    connect(m_devicesPanel, &DevicesPanel::addressAdded, &m_workspace,
            &Workspace::saveDeviceAddresses);
    connect(m_devicesPanel, &DevicesPanel::bindRequested, this,
            [this](const QString &name, const QString &uri) {
                QString error;
                if (!m_engine.bindDevice(name, uri, &error))
                    showError(tr("Could not connect %1 to %2").arg(name, uri), error);
                m_devicesPanel->refresh();
                m_designer->refreshDevices();
            });
    // An audition on a bound device plays alone: the run pauses (docs: studio/README.md).
    connect(m_designer, &WaveformDesigner::auditionStarting, this, [this] {
        if (!m_engine.isRunning())
            return;
        m_engine.pause();
        statusBar()->showMessage(tr("The run is paused while you audition a pattern."), 5000);
    });
    connect(m_designer, &WaveformDesigner::message, this,
            [this](const QString &text) { statusBar()->showMessage(text, 8000); });
    connect(m_designer, &WaveformDesigner::patternRenamed, m_routerEditor,
            &RouterEditor::followRenamedPattern);
    connect(m_designer, &WaveformDesigner::patternRenamed, &m_engine,
            &Engine::followRenamedPattern);
    StudyDocument &studyDocument = m_workspace.study();
    connect(&studyDocument, &StudyDocument::studyChanged, this, &MainWindow::showStudy);
    connect(&studyDocument, &StudyDocument::trialChanged, this, [this] {
        if (m_workspace.study().isTrialRunning())
            m_routerEditor->forgetApplied(); // the trial loaded its condition's router
        updateMode();
    });
    connect(&studyDocument, &StudyDocument::message, this,
            [this](const QString &text) { statusBar()->showMessage(text, 10000); });
    connect(&studyDocument, &StudyDocument::failed, this, &MainWindow::showError);
    connect(m_studyPanel, &StudyPanel::problem, this, &MainWindow::showError);
}

void MainWindow::applyDefaultSizes()
{
    // The plots take a bit more than half the width; the docks under the viewport a third
    // of the height.
    resizeDocks({findChild<QDockWidget *>(QStringLiteral("plotsDock"))}, {width() * 52 / 100},
                Qt::Horizontal);
    resizeDocks({findChild<QDockWidget *>(QStringLiteral("eventsDock"))}, {height() * 30 / 100},
                Qt::Vertical);
}

void MainWindow::restoreLayout()
{
    if (!m_options.restoreLayout)
        return;
    QSettings settings;
    restoreGeometry(settings.value(QStringLiteral("window/geometry")).toByteArray());
    restoreState(settings.value(QStringLiteral("window/state")).toByteArray(), LayoutVersion);
    bool ok = false;
    const double seconds = settings.value(QStringLiteral("view/plotWindow")).toDouble(&ok);
    if (ok)
        m_plots->setWindowSeconds(seconds);
    const int preset = settings.value(QStringLiteral("view/cameraPreset")).toInt(&ok);
    if (ok && preset >= 0 && preset < CameraPresetCount)
        m_viewport->setCameraPreset(CameraPreset(preset));
    m_designer->setAuditionDevice(
        settings.value(QStringLiteral("view/auditionDevice")).toString());
    WaveformDesigner::PlaySettings play = m_designer->playSettings();
    play.intensity =
        settings.value(QStringLiteral("view/playIntensity"), play.intensity).toDouble();
    play.endAt = settings.value(QStringLiteral("view/playEndAt"), play.endAt).toDouble();
    play.hold = settings.value(QStringLiteral("view/playHold"), play.hold).toBool();
    m_designer->setPlaySettings(play);
}

void MainWindow::resetLayout()
{
    restoreState(m_defaultState, LayoutVersion);
    for (QDockWidget *dock : findChildren<QDockWidget *>())
        dock->show();
    applyDefaultSizes();
}

void MainWindow::saveLayout()
{
    QSettings settings;
    settings.setValue(QStringLiteral("window/geometry"), saveGeometry());
    settings.setValue(QStringLiteral("window/state"), saveState(LayoutVersion));
    settings.setValue(QStringLiteral("view/plotWindow"), m_plots->windowSeconds());
    settings.setValue(QStringLiteral("view/cameraPreset"), int(m_viewport->cameraPreset()));
    settings.setValue(QStringLiteral("view/auditionDevice"), m_designer->auditionDevice());
    const WaveformDesigner::PlaySettings play = m_designer->playSettings();
    settings.setValue(QStringLiteral("view/playIntensity"), play.intensity);
    settings.setValue(QStringLiteral("view/playEndAt"), play.endAt);
    settings.setValue(QStringLiteral("view/playHold"), play.hold);
}

} // namespace semhap
