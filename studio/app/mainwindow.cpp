// SPDX-License-Identifier: MIT
#include "mainwindow.h"

#include "devicemanager.h"
#include "devicespanel.h"
#include "filedialogs.h"
#include "gamepadinput.h"
#include "gripperlibrary.h"
#include "handdrive.h"
#include "importprogress.h"
#include "plotpanel.h"
#include "poseinput.h"
#include "preferencesdialog.h"
#include "recordingimport.h"
#include "replaybar.h"
#include "router.h"
#include "routerdocument.h"
#include "routereditor.h"
#include "routergraph.h"
#include "runreadouts.h"
#include "runtoolbar.h"
#include "scenelibrary.h"
#include "sessionreplay.h"
#include "simviewport.h"
#include "spacemouseinput.h"
#include "statusbar.h"
#include "studiofolders.h"
#include "studydocument.h"
#include "taskmonitor.h"
#include "teleopsettings.h"
#include "waveformdesigner.h"
#include "windowplacement.h"
#include "workspace.h"
#include "world.h"

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QFileInfo>
#include <QJsonValue>
#include <QKeyEvent>
#include <QLineEdit>
#include <QMessageBox>
#include <QStatusBar>
#include <QStyle>
#include <QToolBar>

#include <algorithm>
#include <climits>

namespace semhap {

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

void MainWindow::createStatusBar()
{
    auto *bar = new StatusBar(this);
    setStatusBar(bar);
    m_readouts = new RunReadouts(bar, m_engine, this);
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
    m_readouts->sourceChanged();
    updateMode();
    m_devicesPanel->refresh();
    m_designer->refreshDevices();
    m_runToolBar->sync(m_engine);
    updateTitle();
    m_readouts->update();
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
    m_readouts->update();
}

void MainWindow::showRecording(bool recording)
{
    m_recordAction->setChecked(recording);
    m_recordAction->setText(recording ? tr("Stop recording") : tr("Record"));
    m_readouts->update();
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
    RecordingImport::Result result;
    const bool imported =
        ImportProgress::run(this, recording, topics, std::move(router), info, session, &result);
    if (!imported) {
        showError(tr("Could not import %1").arg(name), result.error);
        return false;
    }
    if (result.cancelled) {
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
    for (QAction *action : {m_driveAction, m_viewport->showForcesAction(), m_slowerAction,
                            m_fasterAction, m_realTimeAction})
        action->setEnabled(simulating);
    m_runToolBar->speedPicker()->setEnabled(simulating);
    m_gripperAction->setEnabled(!m_engine.isLive() && !trial); // a rig's grippers are its own
    m_stepAction->setEnabled(simulating && !m_engine.isRunning());
    m_readouts->update();
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
