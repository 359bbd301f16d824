// SPDX-License-Identifier: MIT
#include "mainwindow.h"

#include "colors.h"
#include "devicemanager.h"
#include "devicespanel.h"
#include "drawnicon.h"
#include "eventlogpanel.h"
#include "filedialogs.h"
#include "gamepadinput.h"
#include "gripperlibrary.h"
#include "handdrive.h"
#include "keymapdialog.h"
#include "liverigdialog.h"
#include "manualwindow.h"
#include "metricspanel.h"
#include "plotpanel.h"
#include "poseinput.h"
#include "preferencesdialog.h"
#include "recordingimport.h"
#include "replaybar.h"
#include "router.h"
#include "routerdocument.h"
#include "routereditor.h"
#include "routergraph.h"
#include "runtoolbar.h"
#include "scenelibrary.h"
#include "sessionreplay.h"
#include "simviewport.h"
#include "spacemouseinput.h"
#include "statusbar.h"
#include "studio.h"
#include "studiofolders.h"
#include "studydocument.h"
#include "studymenu.h"
#include "studypanel.h"
#include "taskmonitor.h"
#include "teleopsettings.h"
#include "waveformdesigner.h"
#include "windowplacement.h"
#include "workspace.h"
#include "world.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QEventLoop>
#include <QFile>
#include <QFileInfo>
#include <QJsonValue>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QMenuBar>
#include <QMessageBox>
#include <QPainter>
#include <QProgressDialog>
#include <QSettings>
#include <QStandardItemModel>
#include <QStatusBar>
#include <QTimer>
#include <QToolBar>
#include <QToolButton>

#include <algorithm>
#include <atomic>
#include <climits>
#include <functional>
#include <map>
#include <thread>

namespace semhap {

namespace {

/** Layouts saved by another version of the docks are not restored. */
constexpr int LayoutVersion = 3;

/** The record button's red dot. */
QIcon recordIcon()
{
    return drawnIcon([](QPainter &painter) {
        painter.setBrush(colors::Error);
        painter.drawEllipse(QRectF(6, 6, 20, 20));
    });
}

QDockWidget *makeDock(const QString &title, const QString &name, QWidget *content, QWidget *parent)
{
    auto *dock = new QDockWidget(title, parent);
    dock->setObjectName(name);
    dock->setWidget(content);
    return dock;
}

} // namespace

MainWindow::MainWindow(Workspace &workspace, const StudioOptions &options, QWidget *parent)
    : QMainWindow(parent), m_workspace(workspace), m_options(options), m_engine(workspace.engine())
{
    setObjectName(QStringLiteral("mainWindow"));
    m_viewport = new SimViewport(this);
    setCentralWidget(m_viewport);
    m_handDrive = new HandDrive(this);
    m_viewport->setHandDrive(m_handDrive);
    // The world runs on the engine's thread: starting to drive reads it between two ticks.
    m_handDrive->setStartSource([this] { return m_engine.handCommands(); });
    m_poseInput = new PoseInput(this);
    m_gamepad = new GamepadInput(this);
    m_gamepad->setDrive(m_handDrive);
    m_spaceMouse = new SpaceMouseInput(this);
    m_spaceMouse->setDrive(m_handDrive);

    createActions();
    createToolBar();
    createDocks();
    createMenus();
    createStatusBar();
    createReplayBar();
    connectEngine();
    if (options.size.isEmpty())
        setGeometry(WindowPlacement::defaultGeometry(this));
    else
        resize(options.size);
    applyDefaultSizes();
    m_defaultState = saveState(LayoutVersion);
    restoreLayout();
    updateMode(); // a layout saved during a replay does not bring its bar back
    if (m_workspace.study().isOpen())
        showStudy(); // reopened at the start, or the window built again in another language
    if (!options.size.isEmpty())
        resize(options.size);
    else
        new WindowPlacement(this); // the whole window on its screen, also a restored one

    // A modal dialog takes the keyboard from the window, and its shortcuts with it: Stop all
    // must still work from there.
    qApp->installEventFilter(this);
    if (m_engine.isLoaded()) {
        showWorkspace();
    } else {
        m_engine.setSpeed(options.speed);
        if (options.live) {
            // Without the rig, the scene is still there to look at.
            if (!openLiveRig(options.liveRig))
                openRun(options.run);
        } else if (openRun(options.run) && options.autoRun) {
            m_engine.run();
        }
        // A run that did not load (the message says why) leaves the default one to look at,
        // paused, rather than no scene under pickers that name one.
        RunOptions defaults;
        defaults.duration = options.run.duration;
        const bool defaultRun = options.run.toJson() == defaults.toJson() &&
                                options.run.sceneOptions.gripper.isEmpty();
        if (!m_engine.isLoaded() && !defaultRun)
            openRun(defaults);
    }
    applyTeleopSettings();
    applyPublishing();
    connect(m_gamepad, &GamepadInput::triggered, this, [this](GamepadMapping::Action action) {
        if (action == GamepadMapping::HandBack)
            m_driveAction->setChecked(false);
        else if (action == GamepadMapping::NextCamera)
            m_viewport->nextCameraPreset();
    });
    connect(m_gamepad, &GamepadInput::controllersChanged, this, [this] {
        const QStringList pads = m_gamepad->controllers();
        statusBar()->showMessage(pads.isEmpty()
                                     ? tr("No gamepad connected")
                                     : tr("Gamepad: %1").arg(pads.join(QStringLiteral(", "))),
                                 5000);
    });
    connect(m_spaceMouse, &SpaceMouseInput::connectionChanged, this, [this](bool connected) {
        statusBar()->showMessage(connected ? tr("3D mouse: %1").arg(m_spaceMouse->deviceName())
                                           : tr("3D mouse disconnected: the wrist stopped"),
                                 5000);
    });
    if (options.posePort > 0) {
        if (!m_poseInput->listen(quint16(options.posePort)))
            statusBar()->showMessage(
                tr("Network pose input is off: %1").arg(m_poseInput->errorString()), 10000);
    }
}

MainWindow::~MainWindow()
{
    // First: nothing may write to the drive or the engine's operator while the window goes.
    delete m_poseInput;
    m_poseInput = nullptr;
    delete m_gamepad;
    m_gamepad = nullptr;
    delete m_spaceMouse;
    m_spaceMouse = nullptr;
}

void MainWindow::applyTeleopSettings()
{
    const TeleopSettings settings = TeleopSettings::load();
    m_handDrive->setSpeed(settings.speed);
    m_gamepad->setMapping(settings.gamepadMapping);
    m_spaceMouse->setDeadZone(settings.spaceMouseDeadZone);
    if (!settings.spaceMouse)
        m_spaceMouse->stop();
    else if (!m_spaceMouse->isStarted())
        m_spaceMouse->start(); // false only while another window holds libspnav
    if (!settings.gamepad) {
        m_gamepad->stop();
    } else if (!m_gamepad->start()) {
        statusBar()->showMessage(tr("Gamepads are off: %1").arg(m_gamepad->errorString()), 10000);
    }
}

bool MainWindow::openRun(const RunOptions &options, const QString &what)
{
    QString error;
    if (!m_engine.load(options, &error)) {
        const QString &gripper = options.sceneOptions.gripper;
        showError(
            !what.isEmpty() ? what
            : gripper.isEmpty()
                ? tr("Could not load scene %1 with router %2").arg(options.scene, options.router)
                : tr("Could not load scene %1 with gripper %2 and router %3")
                      .arg(options.scene, gripper, options.router),
            error);
        m_runToolBar->sync(m_engine);
        return false;
    }
    m_routerEditor->forgetApplied(); // the run loaded its router from the file or preset
    return true;
}

bool MainWindow::openLiveRig(const LiveRigOptions &options)
{
    QString error;
    if (!m_engine.listen(options, &error)) {
        showError(tr("Could not listen on udp:%1:%2").arg(options.address).arg(options.port),
                  error);
        return false;
    }
    m_routerEditor->forgetApplied(); // the rig loaded its router from the file or preset
    // Frames come when the rig sends them: holding them back is for Pause.
    m_engine.run();
    statusBar()->showMessage(tr("Listening for a live rig on %1").arg(m_engine.liveUri()), 10000);
    return true;
}

void MainWindow::createActions()
{
    const auto action = [this](const QString &text, const QString &name,
                               const QKeySequence &shortcut) {
        auto *a = new QAction(text, this);
        a->setObjectName(name);
        a->setShortcut(shortcut);
        if (!shortcut.isEmpty())
            a->setToolTip(
                QStringLiteral("%1 (%2)").arg(text, shortcut.toString(QKeySequence::NativeText)));
        addAction(a);
        return a;
    };
    m_runAction = action(tr("Run"), QStringLiteral("runAction"), Qt::Key_F5);
    m_runAction->setCheckable(true);
    m_runAction->setIcon(style()->standardIcon(QStyle::SP_MediaPlay));
    connect(m_runAction, &QAction::triggered, this, &MainWindow::toggleRunning);
    m_stepAction = action(tr("Step"), QStringLiteral("stepAction"), Qt::Key_F6);
    m_stepAction->setIcon(style()->standardIcon(QStyle::SP_MediaSeekForward));
    connect(m_stepAction, &QAction::triggered, this, [this] {
        m_designer->stopAudition(); // the run's frames and an audition never mix
        m_engine.step();
    });
    m_resetAction =
        action(tr("Reset"), QStringLiteral("resetAction"), QKeySequence(Qt::CTRL | Qt::Key_R));
    m_resetAction->setIcon(style()->standardIcon(QStyle::SP_MediaSkipBackward));
    connect(m_resetAction, &QAction::triggered, this, [this] {
        QString error;
        if (!m_engine.reset(&error))
            showError(tr("Could not reset the run"), error);
    });
    m_slowerAction = action(tr("Slower"), QStringLiteral("slowerAction"),
                            QKeySequence(Qt::CTRL | Qt::Key_Minus));
    connect(m_slowerAction, &QAction::triggered, this, [this] { m_runToolBar->stepSpeed(-1); });
    m_fasterAction = action(tr("Faster"), QStringLiteral("fasterAction"),
                            QKeySequence(Qt::CTRL | Qt::Key_Plus));
    // Ctrl+= too: the + key's own face on most keyboards, pressed without Shift.
    m_fasterAction->setShortcuts(
        {QKeySequence(Qt::CTRL | Qt::Key_Plus), QKeySequence(Qt::CTRL | Qt::Key_Equal)});
    connect(m_fasterAction, &QAction::triggered, this, [this] { m_runToolBar->stepSpeed(+1); });
    m_realTimeAction = action(tr("Real time"), QStringLiteral("realTimeAction"),
                              QKeySequence(Qt::CTRL | Qt::Key_0));
    connect(m_realTimeAction, &QAction::triggered, this, [this] { m_runToolBar->pickRealTime(); });

    // Stop-all works from anywhere in the application, whatever has the focus.
    m_stopAllAction = action(tr("Stop all"), QStringLiteral("stopAllAction"), Qt::Key_Escape);
    m_stopAllAction->setShortcutContext(Qt::ApplicationShortcut);
    m_stopAllAction->setToolTip(
        tr("Pause the run and send every device to zero now (Esc, from anywhere)"));
    connect(m_stopAllAction, &QAction::triggered, this, [this] {
        m_designer->stopAudition();
        m_engine.stopAll();
        statusBar()->showMessage(tr("Stopped: every device was sent to zero."), 5000);
    });

    m_driveAction =
        action(tr("Drive"), QStringLiteral("driveAction"), QKeySequence(Qt::CTRL | Qt::Key_T));
    m_driveAction->setCheckable(true);
    m_driveAction->setToolTip(tr("Take the grippers over from the scripted operator "
                                 "(Ctrl+T); any key or pose input does it too"));
    connect(m_driveAction, &QAction::toggled, &m_engine, &Engine::setDriving);
    m_forcesAction = action(tr("Contact forces"), QStringLiteral("forcesAction"),
                            QKeySequence(Qt::CTRL | Qt::Key_F));
    m_forcesAction->setCheckable(true);
    m_forcesAction->setToolTip(tr("Show contact forces as arrows in the viewport"));
    connect(m_forcesAction, &QAction::toggled, m_viewport, &SimViewport::setShowForces);
    m_resetCameraAction = action(tr("Reset camera"), QStringLiteral("resetCameraAction"),
                                 QKeySequence(Qt::CTRL | Qt::Key_Home));
    connect(m_resetCameraAction, &QAction::triggered, m_viewport, &SimViewport::resetCamera);

    m_openSceneAction =
        action(tr("Open scene…"), QStringLiteral("openSceneAction"), QKeySequence::Open);
    connect(m_openSceneAction, &QAction::triggered, this, [this] {
        const QString file = FileDialogs::openFile(this, FileKind::Scene, tr("Open scene"),
                                                   tr("MuJoCo scenes (*.xml)"));
        if (file.isEmpty())
            return;
        SceneOptions sceneOptions; // the scene's own cube count; the gripper picked stays
        sceneOptions.gripper = m_engine.options().sceneOptions.gripper;
        loadScene(file, sceneOptions);
    });
    m_gripperAction = new QAction(tr("Gripper"), this);
    m_gripperAction->setObjectName(QStringLiteral("gripperAction"));
    m_openRouterAction = action(tr("Open router…"), QStringLiteral("openRouterAction"),
                                QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_O));
    connect(m_openRouterAction, &QAction::triggered, this, [this] {
        const QString file = FileDialogs::openFile(this, FileKind::Router, tr("Open router"),
                                                   tr("semhap routers (*.json)"));
        if (file.isEmpty())
            return;
        switchRouter(file);
    });
    m_recordAction = action(tr("Record"), QStringLiteral("recordAction"),
                            QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_R));
    m_recordAction->setCheckable(true);
    m_recordAction->setIcon(recordIcon());
    m_recordAction->setToolTip(tr("Record the run into a new session in the sessions folder "
                                  "(Ctrl+Shift+R); again to stop"));
    connect(m_recordAction, &QAction::triggered, this, &MainWindow::toggleRecording);
    m_openSessionAction = action(tr("Open session…"), QStringLiteral("openSessionAction"),
                                 QKeySequence(Qt::CTRL | Qt::ALT | Qt::Key_O));
    connect(m_openSessionAction, &QAction::triggered, this, [this] {
        const QString file = FileDialogs::openFile(
            this, FileKind::Session, tr("Open session"),
            tr("semhap sessions and robot recordings (*.db *.mcap);;semhap sessions "
               "(*.db);;Robot recordings, rosbag2 in MCAP (*.mcap);;All files (*)"));
        if (file.endsWith(QLatin1String(".mcap"), Qt::CaseInsensitive))
            importRecording(file);
        else if (!file.isEmpty())
            openSession(file);
    });
    m_listenAction = action(tr("Listen for a live rig…"), QStringLiteral("listenAction"),
                            QKeySequence(Qt::CTRL | Qt::Key_L));
    m_listenAction->setToolTip(tr("Run another program's contact frames, sent over UDP, "
                                  "instead of the scene (Ctrl+L)"));
    connect(m_listenAction, &QAction::triggered, this, [this] {
        LiveRigDialog dialog(m_engine.options().router, this);
        if (dialog.exec() == QDialog::Accepted)
            openLiveRig(dialog.options());
    });
    // The study feature brings its own actions (File → Study).
    m_studyMenu = new StudyMenu(m_workspace.study(), this);
    connect(m_studyMenu, &StudyMenu::problem, this, &MainWindow::showError);
    connect(m_studyMenu, &StudyMenu::message, this,
            [this](const QString &text) { statusBar()->showMessage(text, 10000); });
    m_preferencesAction = action(tr("Preferences…"), QStringLiteral("preferencesAction"),
                                 QKeySequence(Qt::CTRL | Qt::Key_Comma));
    // Ctrl+, everywhere (Linux desktops define no standard key); the platform's own too.
    if (const QList<QKeySequence> own = QKeySequence::keyBindings(QKeySequence::Preferences);
        !own.isEmpty() && !own.contains(m_preferencesAction->shortcut()))
        m_preferencesAction->setShortcuts(QList<QKeySequence>{m_preferencesAction->shortcut()} +
                                          own);
    m_preferencesAction->setMenuRole(QAction::PreferencesRole);
    connect(m_preferencesAction, &QAction::triggered, this, &MainWindow::showPreferences);
    m_resetLayoutAction = action(tr("Reset layout"), QStringLiteral("resetLayoutAction"), {});
    connect(m_resetLayoutAction, &QAction::triggered, this, &MainWindow::resetLayout);
    m_quitAction = action(tr("Quit"), QStringLiteral("quitAction"), QKeySequence::Quit);
    m_quitAction->setMenuRole(QAction::QuitRole);
    connect(m_quitAction, &QAction::triggered, this, &QWidget::close);
    m_aboutAction = action(tr("About semhap"), QStringLiteral("aboutAction"), {});
    connect(m_aboutAction, &QAction::triggered, this, [this] {
        QMessageBox::about(this, tr("About semhap"),
                           tr("<p><b>semhap studio</b> %1</p><p>Semantic haptic feedback for "
                              "robot teleoperation: contact forces become confirmations and "
                              "exceptions, routed to patterns on wristbands.</p>")
                               .arg(QCoreApplication::applicationVersion()));
    });
}

void MainWindow::createToolBar()
{
    m_runToolBar = new RunToolBar({m_runAction, m_stepAction, m_resetAction, m_gripperAction,
                                   m_driveAction, m_forcesAction, m_recordAction, m_stopAllAction},
                                  m_workspace, this);
    addToolBar(m_runToolBar);
    connect(m_runToolBar, &RunToolBar::speedPicked, &m_engine, &Engine::setSpeed);
    connect(m_runToolBar, &RunToolBar::scenePicked, this, [this](const QString &scene) {
        SceneOptions sceneOptions; // the scene's own cube count; the gripper picked stays
        sceneOptions.gripper = m_engine.options().sceneOptions.gripper;
        loadScene(scene, sceneOptions);
    });
    connect(m_runToolBar, &RunToolBar::liveRigPicked, this, [this] {
        if (!m_engine.isLive())
            m_listenAction->trigger();
        m_runToolBar->sync(m_engine); // cancelled, it shows what runs
    });
    connect(m_runToolBar, &RunToolBar::gripperPicked, this, [this](const QString &gripper) {
        SceneOptions sceneOptions = m_engine.options().sceneOptions;
        sceneOptions.gripper = gripper;
        loadScene(m_engine.options().scene, sceneOptions);
    });
    connect(m_runToolBar, &RunToolBar::routerPicked, this, &MainWindow::switchRouter);
}

void MainWindow::createReplayBar()
{
    m_replayBar = new ReplayBar(m_engine.replay(), this);
    m_replayToolBar = new QToolBar(tr("Replay"), this);
    m_replayToolBar->setObjectName(QStringLiteral("replayToolBar"));
    m_replayToolBar->setMovable(false);
    m_replayToolBar->addWidget(m_replayBar);
    addToolBar(Qt::BottomToolBarArea, m_replayToolBar);
    m_replayToolBar->hide();
    m_replayToolBar->toggleViewAction()->setVisible(false); // shown by a replay only
    connect(m_replayBar, &ReplayBar::closeRequested, this, &MainWindow::closeReplay);
    connect(m_replayBar, &ReplayBar::rerouteRequested, this, &MainWindow::rerouteReplay);
    // The router picker names the router whose events the replay shows.
    connect(&m_engine.replay(), &SessionReplay::streamsChanged, this,
            [this] { m_runToolBar->sync(m_engine); });
}

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

    setDockNestingEnabled(true);
    QDockWidget *plots = makeDock(tr("Plots"), QStringLiteral("plotsDock"), m_plots, this);
    QDockWidget *events = makeDock(tr("Events"), QStringLiteral("eventsDock"), m_eventLog, this);
    QDockWidget *devices =
        makeDock(tr("Devices"), QStringLiteral("devicesDock"), m_devicesPanel, this);
    QDockWidget *metrics =
        makeDock(tr("Task metrics"), QStringLiteral("metricsDock"), m_metricsPanel, this);
    QDockWidget *patterns =
        makeDock(tr("Patterns"), QStringLiteral("patternsDock"), m_designer, this);
    m_studyPanel = new StudyPanel(m_workspace.study(), m_engine, this);
    m_studyPanel->setStudyActions(m_studyMenu->newStudyAction(), m_studyMenu->openStudyAction());
    QDockWidget *study = makeDock(tr("Study"), QStringLiteral("studyDock"), m_studyPanel, this);
    // The plots run the full height on the right; the log, devices and metrics share the
    // space under the viewport.
    setCorner(Qt::BottomRightCorner, Qt::RightDockWidgetArea);
    setCorner(Qt::TopRightCorner, Qt::RightDockWidgetArea);
    QDockWidget *router =
        makeDock(tr("Router"), QStringLiteral("routerDock"), m_routerEditor, this);
    addDockWidget(Qt::RightDockWidgetArea, plots);
    // The router editor and the designer want the plots' height and width: they sit
    // behind them as tabs.
    addDockWidget(Qt::RightDockWidgetArea, router);
    tabifyDockWidget(plots, router);
    addDockWidget(Qt::RightDockWidgetArea, patterns);
    tabifyDockWidget(router, patterns);
    addDockWidget(Qt::RightDockWidgetArea, study);
    tabifyDockWidget(patterns, study);
    plots->raise();
    addDockWidget(Qt::BottomDockWidgetArea, events);
    addDockWidget(Qt::BottomDockWidgetArea, devices);
    addDockWidget(Qt::BottomDockWidgetArea, metrics);
    tabifyDockWidget(events, devices);
    tabifyDockWidget(devices, metrics);
    events->raise();

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

void MainWindow::createMenus()
{
    QMenu *file = menuBar()->addMenu(tr("&File"));
    file->addAction(m_openSceneAction);
    file->addAction(m_gripperAction);
    file->addAction(m_openRouterAction);
    file->addAction(m_openSessionAction);
    file->addAction(m_listenAction);
    file->addSeparator();
    file->addMenu(m_studyMenu);
    file->addSeparator();
    file->addAction(m_preferencesAction);
    file->addSeparator();
    file->addAction(m_quitAction);

    QMenu *run = menuBar()->addMenu(tr("&Run"));
    run->addAction(m_runAction);
    run->addAction(m_stepAction);
    run->addAction(m_resetAction);
    run->addSeparator();
    run->addAction(m_slowerAction);
    run->addAction(m_realTimeAction);
    run->addAction(m_fasterAction);
    run->addSeparator();
    run->addAction(m_driveAction);
    run->addAction(m_recordAction);
    run->addAction(m_stopAllAction);

    QMenu *view = menuBar()->addMenu(tr("&View"));
    view->addAction(m_forcesAction);
    view->addAction(m_resetCameraAction);
    QMenu *camera = view->addMenu(tr("&Camera"));
    for (int preset = 0; preset < CameraPresetCount; ++preset)
        camera->addAction(m_viewport->cameraPresetAction(CameraPreset(preset)));
    view->addSeparator();
    for (QDockWidget *dock : findChildren<QDockWidget *>())
        view->addAction(dock->toggleViewAction());
    view->addSeparator();
    view->addAction(m_resetLayoutAction);

    QMenu *help = menuBar()->addMenu(tr("&Help"));
    addHelpActions(help);
    help->addAction(m_aboutAction);
}

void MainWindow::addHelpActions(QMenu *help)
{
    auto *keyMap = new QAction(tr("Key map"), this);
    keyMap->setObjectName(QStringLiteral("keyMapAction"));
    keyMap->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Slash));
    keyMap->setToolTip(tr("Every shortcut and drive key of the window"));
    connect(keyMap, &QAction::triggered, this, [this] {
        // One map at a time; it stays open beside the window while the user drives.
        auto *dialog = findChild<KeyMapDialog *>();
        if (!dialog) {
            dialog = new KeyMapDialog(this);
            dialog->setAttribute(Qt::WA_DeleteOnClose);
        }
        dialog->show();
        dialog->raise();
        dialog->activateWindow();
    });
    auto *manual = new QAction(tr("Documentation"), this);
    manual->setObjectName(QStringLiteral("documentationAction"));
    manual->setShortcut(QKeySequence::HelpContents);
    manual->setToolTip(tr("Open the studio's manual"));
    connect(manual, &QAction::triggered, this, &MainWindow::showManual);
    for (QAction *action : {keyMap, manual}) {
        addAction(action);
        help->addAction(action);
    }
    help->addSeparator();
}

void MainWindow::showManual()
{
    const QUrl url = Studio::manualUrl();
    if (url.isEmpty()) {
        showError(tr("The manual is not installed"),
                  tr("Read docs/studio.md in semhap's sources."));
        return;
    }
    // Read here: a desktop without a program for .md files opened nothing.
    auto *window = findChild<ManualWindow *>();
    if (!window) {
        window = new ManualWindow(this, url);
        window->setAttribute(Qt::WA_DeleteOnClose);
    }
    window->show();
    window->raise();
    window->activateWindow();
}

void MainWindow::createStatusBar()
{
    setStatusBar(new StatusBar(this));
    const auto label = [this](const QString &name) {
        auto *l = new QLabel(this);
        l->setObjectName(name);
        statusBar()->addPermanentWidget(l);
        return l;
    };
    m_recordLabel = label(QStringLiteral("recordLabel"));
    m_recordLabel->setStyleSheet(
        QStringLiteral("color: %1; font-weight: bold;").arg(colors::css(colors::Error)));
    m_operatorLabel = label(QStringLiteral("operatorLabel"));
    m_devicesLabel = label(QStringLiteral("devicesLabel"));
    m_timeLabel = label(QStringLiteral("timeLabel"));
    m_rateLabel = label(QStringLiteral("rateLabel"));
    m_foxgloveLabel = label(QStringLiteral("foxgloveLabel"));
    m_statusTimer.setInterval(250);
    connect(&m_statusTimer, &QTimer::timeout, this, &MainWindow::updateStatus);
    m_statusTimer.start();
}

void MainWindow::connectEngine()
{
    connect(&m_engine, &Engine::sourceAboutToChange, this, [this] {
        // Everything that holds the old source's world lets go before the engine frees it.
        m_viewport->setScene(nullptr, nullptr);
        m_handDrive->setWorld(nullptr);
        m_poseInput->setWorld(nullptr);
    });
    connect(&m_engine, &Engine::sourceChanged, this, [this] {
        showSource();
        m_routerEditor->updateContext(); // another scene's signals, or a rig's
        if (m_engine.source()->isStreaming())
            syncRouterEditor(); // a replay is re-routed through the editor's graph: keep it
    });
    connect(&m_engine, &Engine::routerChanged, this, [this] {
        m_devicesPanel->refresh();
        syncRouterEditor();
        m_runToolBar->sync(m_engine);
        updateTitle();
    });
    connect(&m_engine, &Engine::runningChanged, this, [this](bool running) {
        if (running)
            m_designer->stopAudition(); // the run's frames and an audition never mix
        showRunning(running);
    });
    connect(&m_engine, &Engine::drivingChanged, this, &MainWindow::showDriving);
    connect(&m_engine, &Engine::recordingChanged, this, &MainWindow::showRecording);
    connect(&m_engine, &Engine::finished, this, [this] {
        // In a study the run ends with its trial, and the study says so.
        if (!m_workspace.study().isOpen())
            statusBar()->showMessage(tr("The run reached its end. Reset to run it again."), 10000);
    });
    connect(&m_engine.history(), &RunHistory::metricsChanged, this, &MainWindow::showTaskDone);
    connect(&m_engine.history(), &RunHistory::reset, this, &MainWindow::showTaskDone);
    // Any drive input hands the grippers to the user.
    connect(m_handDrive, &HandDrive::driveStarted, this, [this] { m_engine.setDriving(true); });
    connect(m_poseInput, &PoseInput::driveStarted, this, [this] { m_engine.setDriving(true); });
}

void MainWindow::toggleRecording()
{
    if (m_engine.isRecording()) {
        const QString path = m_engine.recordingPath();
        m_engine.stopRecording();
        statusBar()->showMessage(tr("Session saved to %1").arg(path), 10000);
        return;
    }
    QString error;
    const QString path = m_engine.newRecordingPath(StudioFolders::sessions(),
                                                   m_runToolBar->sessionNameEdit()->text());
    if (!m_engine.startRecording(path, m_runToolBar->notesEdit()->text(), &error)) {
        m_recordAction->setChecked(false);
        showError(tr("Could not start recording"), error);
    }
}

void MainWindow::showSource()
{
    RunSource &source = *m_engine.source();
    m_viewport->setScene(source.world(), source.sceneFeed());
    m_viewport->setCaption(source.caption());
    m_viewport->setPlaceholder(source.sceneNote());
    // Only a simulation's grippers follow the user; a replay's bodies go where they were.
    const World *drivable = source.isDrivable() ? source.world() : nullptr;
    m_handDrive->setOperator(source.driveOperator());
    m_handDrive->setWorld(drivable);
    m_poseInput->setOperator(source.driveOperator());
    m_poseInput->setWorld(drivable);
    m_shownRejections = 0;
    updateMode();
    m_devicesPanel->refresh();
    m_designer->refreshDevices();
    m_runToolBar->sync(m_engine);
    updateTitle();
    updateStatus();
    const qint64 skipped = m_engine.isReplaying() ? m_engine.replay().skippedRows() : 0;
    if (skipped > 0)
        statusBar()->showMessage(tr("%n row(s) of the session break the stream rules and were "
                                    "skipped (semhap replay lists them)",
                                    nullptr, int(std::min<qint64>(skipped, INT_MAX))),
                                 15000);
}

void MainWindow::showWorkspace()
{
    showSource();
    showRunning(m_engine.isRunning());
    showDriving(m_engine.isDriving());
    showRecording(m_engine.isRecording());
    showTaskDone();
}

void MainWindow::showRunning(bool running)
{
    m_runAction->setChecked(running);
    m_runAction->setText(running ? tr("Pause") : tr("Run"));
    m_runAction->setIcon(
        style()->standardIcon(running ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
    updateMode();
}

void MainWindow::showDriving(bool driving)
{
    m_driveAction->setChecked(driving);
    m_viewport->setDriving(driving);
    updateStatus();
}

void MainWindow::showRecording(bool recording)
{
    m_recordAction->setChecked(recording);
    m_recordAction->setText(recording ? tr("Stop recording") : tr("Record"));
    updateStatus();
}

bool MainWindow::openSession(const QString &path)
{
    QString error;
    if (m_engine.openReplay(path, &error))
        return true;
    showError(tr("Could not open session %1").arg(QFileInfo(path).fileName()), error);
    return false;
}

bool MainWindow::importRecording(const QString &recording)
{
    const QString name = QFileInfo(recording).fileName();
    if (!FileDialogs::hasRemembered(FileKind::TopicMap))
        FileDialogs::remember(FileKind::TopicMap, recording); // maps live beside recordings
    const QString topics =
        FileDialogs::openFile(this, FileKind::TopicMap, tr("Topic map of %1").arg(name),
                              tr("Topic maps (*.json);;All files (*)"));
    if (topics.isEmpty())
        return false;
    // A new session beside the recorded ones, never over one.
    const QDir folder(StudioFolders::sessions());
    folder.mkpath(QStringLiteral("."));
    const QString base = QFileInfo(recording).completeBaseName();
    QString session = folder.filePath(base + QStringLiteral(".db"));
    for (int k = 2; QFileInfo::exists(session); ++k)
        session = folder.filePath(QStringLiteral("%1-%2.db").arg(base).arg(k));
    LoadError loadError;
    const QString routerName = m_engine.options().router;
    std::unique_ptr<Router> router = loadRouter(routerName, {}, &loadError);
    if (!router) {
        showError(tr("Could not import %1").arg(name), loadError.toString());
        return false;
    }
    SessionInfo info;
    info.routerSource = routerName;

    // The import runs beside the window, which shows how far it is and can cancel it.
    QProgressDialog progress(tr("Importing %1 into %2…").arg(name, QFileInfo(session).fileName()),
                             tr("Cancel"), 0, 1000, this);
    progress.setObjectName(QStringLiteral("importProgress"));
    progress.setWindowModality(Qt::WindowModal);
    progress.setMinimumDuration(300);
    std::atomic<int> done{0};
    std::atomic<bool> cancel{false};
    std::atomic<bool> finished{false};
    RecordingImport::Result result;
    bool imported = false;
    std::thread worker([&, router = std::move(router)]() mutable {
        imported = RecordingImport::run(
            recording, topics, std::move(router), info, session,
            [&](double share) {
                done = int(share * 1000);
                return !cancel.load();
            },
            &result);
        finished = true;
    });
    QEventLoop loop;
    QTimer poll;
    connect(&poll, &QTimer::timeout, &loop, [&] {
        progress.setValue(std::min(done.load(), 999));
        if (progress.wasCanceled())
            cancel = true;
        if (finished)
            loop.quit();
    });
    poll.start(50);
    loop.exec();
    worker.join();
    progress.reset();
    if (!imported) {
        showError(tr("Could not import %1").arg(name), result.error);
        return false;
    }
    if (result.cancelled) {
        QFile::remove(session); // the user stopped it: no half session left behind
        statusBar()->showMessage(tr("Import of %1 cancelled").arg(name), 5000);
        return false;
    }
    statusBar()->showMessage(tr("Imported %1: %n frame(s) into %2", nullptr,
                                int(std::min<long long>(result.frames, INT_MAX)))
                                 .arg(name, QDir::toNativeSeparators(session)),
                             10000);
    return openSession(session);
}

void MainWindow::closeReplay()
{
    if (!m_engine.isReplaying())
        return;
    // The run the replay replaced comes back where it was, paused, with its history.
    QString error;
    if (!m_engine.closeReplay(&error))
        showError(tr("Could not reset the run"), error);
}

void MainWindow::rerouteReplay()
{
    QString error;
    if (!m_engine.setRouter(m_routerEditor->graph(), &error))
        showError(tr("Could not re-route the session"), error);
}

void MainWindow::updateMode()
{
    const bool replaying = m_engine.isReplaying();
    const bool simulating = m_engine.source() && m_engine.source()->isDrivable();
    // A trial runs its condition's scene and router into its own recording until it ends.
    const bool trial = m_workspace.study().isTrialRunning();
    m_replayToolBar->setVisible(replaying);
    m_routerEditor->setReplaying(replaying); // Apply re-routes a replay
    m_runAction->setEnabled(!replaying);
    m_recordAction->setEnabled(!replaying && !trial);
    // Another study in place of this one would abort the trial without asking.
    for (QAction *action : {m_resetAction, m_openSceneAction, m_openRouterAction,
                            m_openSessionAction, m_listenAction})
        action->setEnabled(!trial);
    m_runToolBar->scenePicker()->setEnabled(!trial);
    m_runToolBar->routerPicker()->setEnabled(!trial);
    // A live rig keeps its own pace and drives its own grippers.
    for (QAction *action :
         {m_driveAction, m_forcesAction, m_slowerAction, m_fasterAction, m_realTimeAction})
        action->setEnabled(simulating);
    m_runToolBar->speedPicker()->setEnabled(simulating);
    m_gripperAction->setEnabled(!m_engine.isLive() && !trial); // a rig's grippers are its own
    m_stepAction->setEnabled(simulating && !m_engine.isRunning());
    updateStatus();
}

void MainWindow::switchRouter(const QString &router)
{
    const bool running = m_engine.isRunning();
    if (m_engine.isLive()) {
        LiveRigOptions options = m_engine.liveOptions();
        options.router = router;
        openLiveRig(options);
        m_runToolBar->sync(m_engine);
        return;
    }
    RunOptions options = m_engine.options();
    options.router = router;
    options.overrides.clear();
    if (openRun(options, tr("Could not load router %1").arg(router)) && running)
        m_engine.run();
}

void MainWindow::showTaskDone()
{
    // TaskMonitor decides when the task is done (docs/metrics.md); this only says so.
    const QJsonValue done =
        m_engine.history().metrics().value(QLatin1String(TaskMonitor::CompletionTime));
    const QString notice =
        done.isDouble()
            ? tr("Task done\nThe pile was finished after %1 s.\nCarry on with the refilled box, "
                 "or reset (%2) to start over.")
                  .arg(QLocale().toString(done.toDouble(), 'f', 1),
                       m_resetAction->shortcut().toString(QKeySequence::NativeText))
            : QString();
    if (notice != m_viewport->notice())
        m_viewport->setNotice(notice);
}

void MainWindow::toggleRunning()
{
    if (m_engine.isRunning())
        m_engine.pause();
    else
        m_engine.run();
    m_runAction->setChecked(m_engine.isRunning());
}

void MainWindow::loadScene(const QString &scene, const SceneOptions &sceneOptions)
{
    RunOptions options = m_engine.options();
    // Name what changed: the scene, or the gripper put into it.
    const QString what =
        scene != options.scene
            ? tr("Could not load scene %1").arg(scene)
            : tr("Could not load gripper %1 into scene %2").arg(sceneOptions.gripper, scene);
    // A scene may name the router made for it (dish_wiping's wipe): it comes with the scene
    // when the router running is the one the scene before came with; one you picked stays.
    const auto ownRouter = [](const QString &of) {
        const QString preset = SceneLibrary::routerPreset(of);
        return preset.isEmpty() ? RunOptions().router : preset;
    };
    const bool picked = options.router != ownRouter(options.scene) ||
                        m_engine.isRunRouterEdited() || m_engine.isLive();
    const QString own = ownRouter(scene);
    const bool switched = !picked && own != options.router;
    if (switched) {
        options.router = own;
        options.overrides.clear();
    }
    options.scene = scene;
    options.sceneOptions = sceneOptions;
    const bool running = m_engine.isRunning();
    if (!openRun(options, what))
        return;
    const QString name = QFileInfo(scene).completeBaseName();
    if (switched)
        statusBar()->showMessage(tr("%1 runs with its own router, %2").arg(name, own), 10000);
    else if (own != options.router)
        statusBar()->showMessage(
            tr("%1 has a router of its own, %2: pick it under Router").arg(name, own), 15000);
    if (running)
        m_engine.run();
}

void MainWindow::syncRouterEditor()
{
    // After Apply the editor holds the running graph already, with its undo history.
    const RouterGraph &running = m_engine.routerGraph();
    if (running.toJson() == m_routerEditor->graph().toJson())
        return;
    // Edits not saved are never thrown away: they stay in the editor beside what runs.
    if (m_routerEditor->document()->isModified()) {
        statusBar()->showMessage(tr("The router editor keeps your edits, which are not what "
                                    "runs now: Apply runs them."),
                                 10000);
        return;
    }
    m_routerEditor->setGraph(running);
}

void MainWindow::updateTitle()
{
    if (m_engine.isReplaying()) {
        setWindowTitle(tr("semhap studio — replay of %1")
                           .arg(QFileInfo(m_engine.replay().path()).fileName()));
        return;
    }
    if (m_engine.isLive()) {
        setWindowTitle(
            tr("semhap studio — live rig on %1 · %2")
                .arg(m_engine.liveUri(), QFileInfo(m_engine.options().router).completeBaseName()));
        return;
    }
    QString scene = QFileInfo(m_engine.options().scene).completeBaseName();
    if (const QString gripper = m_engine.options().sceneOptions.gripper; !gripper.isEmpty())
        scene = tr("%1 with %2").arg(scene, QFileInfo(gripper).completeBaseName());
    setWindowTitle(tr("semhap studio — %1 · %2")
                       .arg(scene, QFileInfo(m_engine.options().router).completeBaseName()));
}

void MainWindow::updateStatus()
{
    const QLocale locale;
    m_recordLabel->setVisible(m_engine.isRecording());
    if (m_engine.isRecording())
        m_recordLabel->setText(tr("Recording to %1 (%2 dropped)")
                                   .arg(QFileInfo(m_engine.recordingPath()).fileName())
                                   .arg(m_engine.recordingDropped()));
    m_timeLabel->setText(tr("t = %1 s").arg(locale.toString(m_engine.simTime(), 'f', 2)));
    m_foxgloveLabel->setVisible(m_engine.isPublishing());
    if (m_engine.isPublishing()) {
        const FoxgloveServer::Stats served = m_engine.publishingStats();
        m_foxgloveLabel->setText(tr("Foxglove: %n viewer(s)", nullptr, served.clients));
        m_foxgloveLabel->setToolTip(
            tr("Published at %1: %2 message(s) sent, %3 dropped for slow viewers")
                .arg(m_engine.publishingUrl())
                .arg(served.sent)
                .arg(served.dropped));
    }
    m_rateLabel->setToolTip(QString()); // a live rig's says why its datagrams were refused
    if (m_engine.isReplaying()) {
        m_operatorLabel->setText(tr("Replay: nobody drives"));
        m_rateLabel->setText(tr("replay"));
        return;
    }
    if (m_engine.isLive()) {
        updateLiveStatus();
        updateDevicesStatus();
        return;
    }
    m_rateLabel->setText(
        m_engine.isRunning()
            ? tr("%1× real time").arg(locale.toString(m_engine.realtimeFactor(), 'f', 2))
            : tr("paused"));
    m_operatorLabel->setText(m_engine.isDriving()
                                 ? tr("You are driving")
                                 : tr("Operator: %1").arg(m_engine.options().operatorName));
    updateDevicesStatus();
}

void MainWindow::updateLiveStatus()
{
    const QLocale locale;
    const RunSource::LinkStats stats = m_engine.liveStats();
    m_operatorLabel->setText(tr("Live rig on %1").arg(m_engine.liveUri()));
    QString rate = m_engine.isRunning() ? tr("%1 frames/s, jitter %2 ms")
                                              .arg(locale.toString(stats.framesPerSecond, 'f', 0),
                                                   locale.toString(stats.jitter * 1000.0, 'f', 1))
                                        : tr("paused: %n frame(s) held", nullptr,
                                             int(std::min<quint64>(stats.held, INT_MAX)));
    if (stats.rejected > 0)
        rate += tr(" · %n malformed", nullptr, int(std::min<quint64>(stats.rejected, INT_MAX)));
    m_rateLabel->setText(rate);
    // The latest rejection says what was wrong with it, as it comes.
    if (stats.reasons != m_shownRejections) {
        m_shownRejections = stats.reasons;
        statusBar()->showMessage(tr("Malformed datagram: %1").arg(stats.lastRejection), 5000);
    }
    // The message goes after 5 s and a narrow window cuts it: the count's tooltip keeps the
    // reason.
    m_rateLabel->setToolTip(stats.reasons > 0
                                ? tr("Latest malformed datagram: %1").arg(stats.lastRejection)
                                : QString());
}

void MainWindow::updateDevicesStatus()
{
    // Counted by the state the Devices panel shows each band in (TransportStatus::state).
    int virtualCount = 0;
    std::map<LinkState, int> count;
    for (const BoundDevice &device : m_engine.devices().status()) {
        if (device.uri.startsWith(QLatin1String("virtual:")))
            ++virtualCount;
        else
            ++count[device.status.state()];
    }
    QString devices =
        tr("Devices: %1 virtual, %2 connected").arg(virtualCount).arg(count[LinkState::Connected]);
    if (count[LinkState::Connecting] > 0)
        devices += tr(", %1 connecting").arg(count[LinkState::Connecting]);
    if (count[LinkState::Disconnected] > 0)
        devices += tr(", %1 disconnected").arg(count[LinkState::Disconnected]);
    m_devicesLabel->setText(devices);
}

void MainWindow::showError(const QString &what, const QString &error)
{
    statusBar()->showMessage(QStringLiteral("%1: %2").arg(what, error), 15000);
    // Not modal: the window goes on taking keys and clicks (and the run its steps) while
    // the message is read. open() would block the window.
    auto *box =
        new QMessageBox(QMessageBox::Warning, tr("semhap studio"), what, QMessageBox::Ok, this);
    box->setInformativeText(error);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->setWindowModality(Qt::NonModal);
    box->show();
}

bool MainWindow::eventFilter(QObject *watched, QEvent *event)
{
    if (event->type() != QEvent::KeyPress ||
        static_cast<QKeyEvent *>(event)->key() != Qt::Key_Escape || !watched->isWidgetType())
        return QMainWindow::eventFilter(watched, event);
    // Once per key press: at the widget it is delivered to first, inside a modal dialog.
    QWidget *modal = QApplication::activeModalWidget();
    auto *widget = static_cast<QWidget *>(watched);
    if (!modal || modal == this || widget->window() != modal)
        return QMainWindow::eventFilter(watched, event);
    if (widget == (modal->focusWidget() ? modal->focusWidget() : modal))
        m_stopAllAction->trigger();
    return QMainWindow::eventFilter(watched, event);
}

void MainWindow::showPreferences()
{
    PreferencesDialog dialog(this);
    if (dialog.exec() != QDialog::Accepted)
        return;
    applyTeleopSettings();
    applyPublishing();
    if (dialog.languageChanged())
        emit languageChangeRequested(dialog.language());
}

void MainWindow::applyPublishing()
{
    if (!PreferencesDialog::publishesToFoxglove()) {
        m_engine.stopPublishing();
        return;
    }
    // Only this computer's viewers: a door to the network is the command line's to open.
    const auto port = quint16(PreferencesDialog::foxglovePort());
    const QString url = QStringLiteral("ws://127.0.0.1:%1").arg(port);
    if (m_engine.publishingUrl() == url)
        return; // a window rebuilt for a language keeps its viewers
    QString error;
    if (m_engine.startPublishing(QHostAddress::LocalHost, port, &error))
        statusBar()->showMessage(tr("Publishing to Foxglove at %1").arg(url), 10000);
    else
        statusBar()->showMessage(
            tr("Cannot publish to Foxglove on port %1: %2").arg(port).arg(error), 15000);
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

void MainWindow::showStudy()
{
    if (m_workspace.study().isOpen())
        findChild<QDockWidget *>(QStringLiteral("studyDock"))->raise();
    updateMode();
}

void MainWindow::closeEvent(QCloseEvent *event)
{
    m_engine.stopAll();
    saveLayout();
    event->accept();
}

} // namespace semhap
