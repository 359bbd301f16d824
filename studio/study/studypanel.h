// SPDX-License-Identifier: MIT
#pragma once

#include "paneldock.h"
#include "studyprotocol.h"

#include <QPointer>
#include <QTimer>
#include <QWidget>

class QAction;
class QLabel;
class QLineEdit;
class QListWidget;
class QPushButton;
class QStackedWidget;
class QTreeWidget;
class QTreeWidgetItem;

namespace semhap {

class Engine;
class MetricsPanel;
class QuestionnaireWindow;
class StudyDocument;

/**
 * The experimenter's view of the open study (the Study dock, docs/studio.md "Running a
 * study"): the protocol's name; the participants (ids) with a field to add one; the chosen
 * participant's order of conditions with each step's state and attempts; the next step in
 * words; Start, Pause/Resume, Abort… and Mark invalid…; the countdown of the running trial (a
 * practice round's time and transfers), the break's with Skip; and the task metrics live.
 * Start on a questionnaire step opens the participant's QuestionnaireWindow.
 */
class StudyPanel : public QWidget
{
    Q_OBJECT

public:
    /** Where the main window docks it by default (PanelDock). */
    static PanelDock dock();
    StudyPanel(StudyDocument &study, Engine &engine, QWidget *parent = nullptr);
    /** Closes the participant's questionnaire first: it tells the panel when it goes. */
    ~StudyPanel() override;

    /** What the panel offers while no study is open (File → Study's New and Open). */
    void setStudyActions(QAction *newStudy, QAction *openStudy);
    /** The participant's questionnaire, while it is open. */
    QuestionnaireWindow *questionnaire() const;
    /** Starts the chosen participant's next step: its run, or its questionnaire. */
    void start();
    /** How a countdown shows `seconds`: `mm:ss` (rounded up), `h:mm:ss` from an hour on. */
    static QString clock(double seconds);

signals:
    /** Something went wrong that the window should say. */
    void problem(const QString &what, const QString &error);

private:
    QWidget *createStudyPage();
    /** Shows the study again: participants, steps, the next step, the buttons. */
    void refresh();
    void refreshParticipants();
    void refreshSteps();
    /** The countdown, the break and the buttons, as the trial and the engine are now. */
    void refreshTrial();
    void addParticipant();
    void abort();
    void markInvalid();
    /** The trial the selected step row stands for when it is done; 0 else. */
    qint64 selectedDoneTrial() const;

    StudyDocument &m_study;
    Engine &m_engine;
    QStackedWidget *m_pages = nullptr;
    QWidget *m_noStudy = nullptr;
    QLabel *m_name = nullptr;
    QLabel *m_file = nullptr;
    QListWidget *m_participants = nullptr;
    QLineEdit *m_participantEdit = nullptr;
    QPushButton *m_add = nullptr;
    QLabel *m_participantProblem = nullptr;
    QLabel *m_order = nullptr;
    QTreeWidget *m_steps = nullptr;
    QLabel *m_nextLabel = nullptr;
    QLabel *m_countdown = nullptr;
    QLabel *m_countdownCaption = nullptr;
    QPushButton *m_skipBreak = nullptr;
    QPushButton *m_start = nullptr;
    QPushButton *m_pause = nullptr;
    QPushButton *m_abort = nullptr;
    QPushButton *m_invalid = nullptr;
    MetricsPanel *m_metrics = nullptr;
    QPointer<QuestionnaireWindow> m_questionnaire;
    StudyProtocol::Step m_next; ///< the chosen participant's, as of the last change
    QTimer m_clockTimer;        ///< the countdown's, while a trial or a break is on
};

} // namespace semhap
