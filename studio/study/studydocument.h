// SPDX-License-Identifier: MIT
#pragma once

#include "studydatabase.h"

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

#include <memory>

namespace semhap {

class Engine;

/**
 * The study open in the studio (docs/studio.md, "Running a study"): its database, the
 * participant the experimenter works with, and the practice round or trial that runs — loaded
 * into the engine, recorded into the study's sessions folder and timed on the run's simulated
 * clock, ended by itself at its seconds (a practice round at its goal) with the task's metrics
 * — and the break after a trial. It lives in the Workspace, so a trial goes on while the
 * window is built again in another language; the views only ask it and listen.
 */
class StudyDocument : public QObject
{
    Q_OBJECT

public:
    using Step = StudyProtocol::Step;

    explicit StudyDocument(Engine &engine, QObject *parent = nullptr);
    /** Closes the study; a trial still running stays so in the database (interrupted). */
    ~StudyDocument() override;

    /**
     * Creates a study at `path` (which must not exist) for the protocol file `protocol` and
     * opens it in place of the one open. False with `FILE: reason` in `error`.
     */
    bool create(const QString &protocol, const QString &path, QString *error);
    /**
     * Opens the study at `path` for writing in place of the one open (the one open stays
     * as it is): refused, with the database's reason in `error`, while another studio
     * holds it.
     */
    bool open(const QString &path, QString *error);
    /**
     * Closes the study. A trial that runs is aborted first (`reason`), its run stopped and
     * its devices sent to zero.
     */
    void close(const QString &reason = QStringLiteral("the study was closed"));
    bool isOpen() const { return m_study != nullptr; }
    /** The open study's database; null when none is open. */
    StudyDatabase *database() const { return m_study.get(); }
    const StudyProtocol &protocol() const { return m_study->protocol(); }

    /** The participant the experimenter works with; empty when none is chosen. */
    QString participant() const { return m_participant; }
    /**
     * Chooses the participant (an id of the study's; another clears the choice); the one a
     * trial runs for stays chosen until it ends.
     */
    void setParticipant(const QString &id);
    /** Adds a participant (the database's rules) and chooses them; false with `error`. */
    bool addParticipant(const QString &id, QString *error);
    /** The chosen participant's next step; Done when none is chosen. */
    Step nextStep() const;

    /**
     * Starts the chosen participant's next step when it is a practice round or a trial: its
     * condition's run is loaded (paused behind it: the run that was there), recorded into a
     * new session tagged with the study's keys, handed to the participant to drive, and run.
     * False with `error` (refused during a break or a trial, or what failed).
     */
    bool startTrial(QString *error);
    bool isTrialRunning() const { return m_trial != 0; }
    /** The step the running trial is. */
    Step runningStep() const { return m_step; }
    /** The running trial's simulated seconds so far. */
    double elapsed() const;
    /** How long the running step may last (s): a trial's seconds, a practice round's at most. */
    double limit() const;
    /** Pauses the running trial, sending every device to zero; run() goes on. */
    void pause();
    /** Goes on with a paused trial. */
    void resume();
    /** Ends the running trial as aborted with `reason`; the step is due again. */
    bool abortTrial(const QString &reason, QString *error);
    /** Marks the done trial `id` invalid with `reason`: its step is due again. */
    bool invalidateTrial(qint64 id, const QString &reason, QString *error);

    /** Whether the break after a trial is on. */
    bool isOnBreak() const { return m_breakTimer.isActive(); }
    /** The break's wall-clock seconds left. */
    double breakLeft() const;
    /** Ends the break now. */
    void skipBreak();

    /**
     * Writes the study's results into the folder `dir` as `semhap study export` and
     * `analyze --report` do: measures.csv, trials.csv, answers.csv, and report/report.md
     * with a box plot per measure, each file the safe way. The files written in `written`;
     * false with `FILE: reason` in `error` (nothing half: a file is whole or not there).
     */
    bool exportResults(const QString &dir, QStringList *written, QString *error) const;

    /** Stores `answer` at once (the database's checks); false with `error`. */
    bool answer(const StudyDatabase::Answer &answer, QString *error);

    /**
     * What `step` is, in words: "Practice — LABEL (until 10 transfers or 300 s)", "Trial 2
     * of 2 — LABEL (120 s)", "Questionnaire after LABEL", "Final questionnaire".
     */
    QString describe(const Step &step) const;

signals:
    /** A study was opened or closed. */
    void studyChanged();
    /** The record changed: a participant, a trial, an answer, or the participant chosen. */
    void changed();
    /** A trial began, was paused or went on, or ended. */
    void trialChanged();
    /** The break began or ended. */
    void breakChanged();
    /** Something the experimenter should know happened by itself (a trial ended). */
    void message(const QString &text);
    /** Something went wrong outside a call the views made (a trial's end not stored). */
    void failed(const QString &what, const QString &error);

private:
    /** The running step reached its end: stored as done with the run's metrics. */
    void finishTrial();
    /**
     * Stops the running trial's run (its devices to zero) and recording; its id and
     * `seconds`, or 0 when none runs.
     */
    qint64 stopTrial(double *seconds);
    /** Ends the running trial as aborted, saying so, for a reason the studio gives. */
    void abortByItself(const QString &reason);
    /** Makes `study` the open one, closing the one before. */
    void install(std::unique_ptr<StudyDatabase> study);

    Engine &m_engine;
    std::unique_ptr<StudyDatabase> m_study;
    QString m_participant;
    qint64 m_trial = 0; ///< the running trial's id; 0 when none runs
    Step m_step;
    QTimer m_breakTimer;
    QElapsedTimer m_breakClock;
};

} // namespace semhap
