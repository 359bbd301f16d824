// SPDX-License-Identifier: MIT
#pragma once

#include <QToolBar>

class QActionGroup;
class QComboBox;
class QLineEdit;
class QMenu;

namespace semhap {

class Engine;
class Workspace;

/**
 * The window's run toolbar: Run, Step and Reset; the speed; the scene (or a live rig), the
 * gripper put into it and the router; driving and contact forces; recording, with the next
 * session's name and notes; and Stop all, apart in a colour of its own. The pickers show what
 * the engine runs (sync()) and say what the user picked; the window loads it.
 */
class RunToolBar : public QToolBar
{
    Q_OBJECT

public:
    /** The window's actions it shows; the gripper action gets the gripper menu. */
    struct Actions
    {
        QAction *run;
        QAction *step;
        QAction *reset;
        QAction *gripper;
        QAction *drive;
        QAction *forces;
        QAction *record;
        QAction *stopAll;
    };

    /** The session name and notes edit `workspace`'s. */
    RunToolBar(const Actions &actions, Workspace &workspace, QWidget *parent);

    /**
     * Shows what `engine` runs: its scene (or the live rig), gripper, router (`*` when edited;
     * during a replay, the one it shows, which cannot be picked) and speed.
     */
    void sync(const Engine &engine);
    /** Picks the speed `steps` entries faster (or slower), within the list's ends. */
    void stepSpeed(int steps);
    void pickRealTime();

    QComboBox *scenePicker() const { return m_scene; }
    QComboBox *routerPicker() const { return m_router; }
    QComboBox *speedPicker() const { return m_speed; }
    QLineEdit *sessionNameEdit() const { return m_sessionName; }
    QLineEdit *notesEdit() const { return m_notes; }

signals:
    void speedPicked(double speed);
    void scenePicked(const QString &scene);
    void liveRigPicked();
    void routerPicked(const QString &router);
    /** A gripper adapter's name or file; empty: the scene's own grippers. */
    void gripperPicked(const QString &gripper);

private:
    void pickSpeed(int index);
    void fillGripperMenu();
    void pickGripper(const QString &choice);

    Actions m_actions;
    QComboBox *m_speed = nullptr;
    QComboBox *m_scene = nullptr;
    QComboBox *m_router = nullptr;
    QLineEdit *m_sessionName = nullptr;
    QLineEdit *m_notes = nullptr;
    QMenu *m_gripperMenu;
    QActionGroup *m_gripperChoices = nullptr; ///< the Gripper menu's entries, refilled on show
    QString m_gripper;                        ///< the gripper that runs, as sync() saw it
};

} // namespace semhap
