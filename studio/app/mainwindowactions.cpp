// SPDX-License-Identifier: MIT
// MainWindow's actions, menus and tool bar: what each does, on the window so its shortcut
// works anywhere in it.
#include "mainwindow.h"

#include "colors.h"
#include "drawnicon.h"
#include "filedialogs.h"
#include "helpactions.h"
#include "liverigdialog.h"
#include "runtoolbar.h"
#include "sessionexport.h"
#include "simviewport.h"
#include "studymenu.h"
#include "waveformdesigner.h"
#include "workspace.h"

#include <QAction>
#include <QCoreApplication>
#include <QDir>
#include <QDockWidget>
#include <QFileInfo>
#include <QMenuBar>
#include <QMessageBox>
#include <QPainter>
#include <QStatusBar>
#include <QStyle>

namespace semhap {

namespace {

/** The record button's red dot. */
QIcon recordIcon()
{
    return drawnIcon([](QPainter &painter) {
        painter.setBrush(colors::Error);
        painter.drawEllipse(QRectF(6, 6, 20, 20));
    });
}

} // namespace

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
    m_exportSessionAction =
        action(tr("Export session…"), QStringLiteral("exportSessionAction"), {});
    m_exportSessionAction->setToolTip(
        tr("Write the session replayed, or one you pick, as XDF for labs synchronised by the "
           "Lab Streaming Layer or as MCAP for Foxglove, PlotJuggler and Rerun"));
    m_sessionExport = new SessionExport(this);
    connect(m_exportSessionAction, &QAction::triggered, this, [this] {
        QString session = m_engine.isReplaying() ? m_engine.replay().path() : QString();
        if (session.isEmpty())
            session = FileDialogs::openFile(this, FileKind::Session, tr("Session to export"),
                                            tr("semhap sessions (*.db);;All files (*)"));
        if (!session.isEmpty() && m_sessionExport->start(session)) {
            m_exportSessionAction->setEnabled(false);
            statusBar()->showMessage(tr("Exporting %1…").arg(QFileInfo(session).fileName()));
        }
    });
    connect(m_sessionExport, &SessionExport::finished, this,
            [this](const QString &target, const QString &error, const QString &notes) {
                m_exportSessionAction->setEnabled(true);
                if (!error.isEmpty()) {
                    statusBar()->clearMessage();
                    showError(tr("Could not export the session"), error);
                    return;
                }
                const QString done = tr("Exported %1").arg(QDir::toNativeSeparators(target));
                statusBar()->showMessage(done, 10000);
                // What the file cannot do (line up with an LSL recording) is worth a stop.
                if (!notes.isEmpty())
                    QMessageBox::information(this, tr("Session exported"),
                                             done + QStringLiteral("\n\n") + notes);
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

void MainWindow::createMenus()
{
    QMenu *file = menuBar()->addMenu(tr("&File"));
    file->addAction(m_openSceneAction);
    file->addAction(m_gripperAction);
    file->addAction(m_openRouterAction);
    file->addAction(m_openSessionAction);
    file->addAction(m_exportSessionAction);
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
    // The viewport brings its own (as the study feature brings File → Study).
    view->addAction(m_viewport->showForcesAction());
    view->addAction(m_viewport->resetCameraAction());
    QMenu *camera = view->addMenu(tr("&Camera"));
    for (int preset = 0; preset < CameraPresetCount; ++preset)
        camera->addAction(m_viewport->cameraPresetAction(CameraPreset(preset)));
    view->addSeparator();
    for (QDockWidget *dock : findChildren<QDockWidget *>())
        view->addAction(dock->toggleViewAction());
    view->addSeparator();
    view->addAction(m_resetLayoutAction);

    QMenu *help = menuBar()->addMenu(tr("&Help"));
    connect(new HelpActions(this, help), &HelpActions::problem, this, &MainWindow::showError);
    help->addAction(m_aboutAction);
}

void MainWindow::createToolBar()
{
    m_runToolBar =
        new RunToolBar({m_runAction, m_stepAction, m_resetAction, m_gripperAction, m_driveAction,
                        m_viewport->showForcesAction(), m_recordAction, m_stopAllAction},
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

} // namespace semhap
