// SPDX-License-Identifier: MIT
#pragma once

#include "engine.h"
#include "studiooptions.h"

#include <QMainWindow>

class QActionGroup;
class QComboBox;
class QLineEdit;
class QMenu;
class QToolBar;

namespace semhap {

class DevicesPanel;
class EventLogPanel;
class GamepadInput;
class SpaceMouseInput;
class HandDrive;
class MetricsPanel;
class PlotPanel;
class PoseInput;
class ReplayBar;
class RouterEditor;
class SessionExport;
class SessionReplay;
class SimViewport;
class RunReadouts;
class RunToolBar;
class StudyMenu;
class StudyPanel;
class WaveformDesigner;
class Workspace;

/**
 * The studio's window: the simulation viewport in the middle, docks for the live plots,
 * the event log, the devices, the task metrics and the waveform designer, a toolbar that runs,
 * pauses, steps, resets and paces the run and picks scene and router, and a stop-all that always
 * works. The dock layout is saved on close and restored on the next start.
 *
 * The window is a view of a Workspace: the run, the devices, the recording and the editors'
 * documents live there, so a window built again around the same workspace (another
 * interface language) goes on where the last one was.
 */
class MainWindow : public QMainWindow
{
    Q_OBJECT

public:
    /**
     * Shows `workspace`, which must outlive the window. An empty workspace gets the run
     * `options` asks for; a loaded one is shown as it is.
     */
    MainWindow(Workspace &workspace, const StudioOptions &options, QWidget *parent = nullptr);
    ~MainWindow() override;

    Workspace &workspace() { return m_workspace; }
    Engine &engine() { return m_engine; }
    SimViewport *viewport() const { return m_viewport; }
    PlotPanel *plots() const { return m_plots; }
    EventLogPanel *eventLog() const { return m_eventLog; }
    DevicesPanel *devicesPanel() const { return m_devicesPanel; }
    MetricsPanel *metricsPanel() const { return m_metricsPanel; }
    RouterEditor *routerEditor() const { return m_routerEditor; }
    WaveformDesigner *waveformDesigner() const { return m_designer; }
    /** The experimenter's view of the open study (the Study dock). */
    StudyPanel *studyPanel() const { return m_studyPanel; }
    /** The run toolbar: its pickers, the session's name and notes. */
    RunToolBar *runToolBar() const { return m_runToolBar; }
    SessionReplay *replay() { return &m_engine.replay(); }
    ReplayBar *replayBar() const { return m_replayBar; }

    /**
     * Loads a run (scene, router, ...) and shows what went wrong, if anything, as `what`
     * (empty: naming the scene, the gripper and the router).
     */
    bool openRun(const RunOptions &options, const QString &what = QString());
    /**
     * Opens a recorded session read-only: the run pauses, the replay bar appears and the
     * plots and the event log follow its scrubber. Shows what went wrong, if anything.
     */
    bool openSession(const QString &path);
    /**
     * Asks for the topic map of a robot's recording (REC.mcap), imports it into a new
     * session in the sessions folder, routed by the run's router, with a progress dialog
     * that can cancel, then opens that session; false when it did not.
     */
    bool importRecording(const QString &recording);
    /** Back from a replay to the simulation (or live rig) it replaced, where it was. */
    void closeReplay();
    /**
     * Listens for a live rig's contact frames instead of running the scene, and runs them.
     * Shows what went wrong (a port in use), if anything.
     */
    bool openLiveRig(const LiveRigOptions &options);

    /**
     * Saves the window's geometry and dock layout, with the views' settings (the plots' time
     * window, the camera preset, the audition device), for the next window.
     */
    void saveLayout();
    /** Says what went wrong, in the status bar and a message box that does not block. */
    void showError(const QString &what, const QString &error);

signals:
    /** The user chose another interface language (its code, empty: the system's). */
    void languageChangeRequested(const QString &language);

protected:
    void closeEvent(QCloseEvent *event) override;
    /** Esc in a modal dialog stops everything too (the dialog closes as usual). */
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    /** Layouts saved by another version of the docks are not restored. */
    static constexpr int LayoutVersion = 3;

    void createActions();
    void createToolBar();
    void createDocks();
    void createMenus();
    void createStatusBar();
    void createReplayBar();
    void connectEngine();
    /** Shows what the engine's new source has: its scene, what can be done with it. */
    void showSource();
    void applyDefaultSizes();
    void restoreLayout();
    void resetLayout();
    void updateTitle();
    /** Shows the running router in the editor unless the editor already holds it. */
    void syncRouterEditor();
    /**
     * Loads `scene` with `sceneOptions` in place of the run's, keeping a running session
     * running; a scene that does not load is said and the run that was there stays.
     */
    void loadScene(const QString &scene, const SceneOptions &sceneOptions);
    void showPreferences();
    /** Applies the saved driving settings: speed, the gamepad and the 3D mouse. */
    void applyTeleopSettings();
    /** Serves the run to Foxglove, or stops, as the preferences say; a server kept as is. */
    void applyPublishing();
    void toggleRunning();
    void toggleRecording();
    void rerouteReplay();
    /** Enables what only makes sense on the simulation (step, speed, drive) or not in a replay. */
    void updateMode();
    /** Runs `router` on what runs now: the scene, or the live rig. */
    void switchRouter(const QString &router);
    /** Says over the viewport that the task is done, once its metrics say so; else nothing. */
    void showTaskDone();
    /** The Study dock comes forward when a study opens; its actions follow. */
    void showStudy();

    /** Shows what the engine holds when the window opens on a loaded workspace. */
    void showWorkspace();
    void showRunning(bool running);
    void showDriving(bool driving);
    void showRecording(bool recording);

    Workspace &m_workspace;
    StudioOptions m_options;
    Engine &m_engine;
    SimViewport *m_viewport = nullptr;
    HandDrive *m_handDrive = nullptr;
    PoseInput *m_poseInput = nullptr;
    GamepadInput *m_gamepad = nullptr;
    SpaceMouseInput *m_spaceMouse = nullptr;
    PlotPanel *m_plots = nullptr;
    EventLogPanel *m_eventLog = nullptr;
    DevicesPanel *m_devicesPanel = nullptr;
    MetricsPanel *m_metricsPanel = nullptr;
    RouterEditor *m_routerEditor = nullptr;
    WaveformDesigner *m_designer = nullptr;
    StudyPanel *m_studyPanel = nullptr;
    RunToolBar *m_runToolBar = nullptr;
    ReplayBar *m_replayBar = nullptr;
    QToolBar *m_replayToolBar = nullptr;
    RunReadouts *m_readouts = nullptr;
    QByteArray m_defaultState;     ///< the dock layout as built, for "Reset layout"

    QAction *m_runAction = nullptr;
    QAction *m_stepAction = nullptr;
    QAction *m_resetAction = nullptr;
    QAction *m_slowerAction = nullptr;
    QAction *m_fasterAction = nullptr;
    QAction *m_realTimeAction = nullptr;
    QAction *m_stopAllAction = nullptr;
    QAction *m_driveAction = nullptr;
    QAction *m_openSceneAction = nullptr;
    QAction *m_gripperAction = nullptr; ///< the Gripper menu, in the toolbar and File menu
    QAction *m_openRouterAction = nullptr;
    QAction *m_recordAction = nullptr;
    QAction *m_openSessionAction = nullptr;
    QAction *m_exportSessionAction = nullptr;
    SessionExport *m_sessionExport = nullptr;
    QAction *m_listenAction = nullptr;
    StudyMenu *m_studyMenu = nullptr;
    QAction *m_preferencesAction = nullptr;
    QAction *m_resetLayoutAction = nullptr;
    QAction *m_quitAction = nullptr;
    QAction *m_aboutAction = nullptr;
};

} // namespace semhap
