// SPDX-License-Identifier: MIT
#pragma once

#include "studyprotocol.h"

#include <QDateTime>
#include <QJsonObject>
#include <QSqlDatabase>
#include <QSqlQuery>
#include <QString>
#include <QStringList>

#include <memory>
#include <vector>

class QLockFile;

namespace semhap {

struct SessionInfo;

/**
 * One study's record (docs/studies.md, "The study database"): a SQLite file holding the
 * protocol it began with, the participants and their orders, every practice round and trial
 * (the session it recorded, its metrics, whether it counts) and every answer. Each change is
 * committed at once (WAL, synchronous=FULL), so a crash or a power cut loses at most the
 * trial that was running; nothing is ever deleted — a redone trial leaves the first one
 * marked invalid with its reason. One writer at a time: a second one is refused while the
 * first holds the study's lock file.
 */
class StudyDatabase
{
public:
    enum class Access
    {
        Write, ///< the experimenter's (one at a time, under the lock)
        Read   ///< export and analysis (any number, even while a writer runs)
    };
    /** What a practice round or trial is now. */
    enum class Status
    {
        Running,    ///< begun, not finished
        Done,       ///< finished; counts
        Aborted,    ///< stopped by the experimenter before its end
        Invalid,    ///< finished, then marked not to count (a reason says why)
        Interrupted ///< the study closed while it ran (a crash, a power cut)
    };

    /** One practice round or trial. */
    struct Trial
    {
        qint64 id = 0;
        QString participant;
        int condition = -1; ///< index into the protocol's conditions
        bool practice = false;
        int number = 0;  ///< 1..trials; 0 for a practice round
        QString session; ///< the recorded session, relative to the database's folder
        QDateTime started;
        QDateTime ended; ///< invalid while running or when interrupted
        Status status = Status::Running;
        QString reason;      ///< why aborted, invalid or interrupted
        double seconds = 0;  ///< how long it ran (simulated seconds)
        QJsonObject metrics; ///< the task's metrics at its end
    };

    /** One answer; the newest answer to a measure is the one that counts. */
    struct Answer
    {
        QString participant;
        int condition = -1; ///< its condition, -1 for the final questionnaire's items
        QString measure;    ///< a Question::measures() name
        double value = 0;   ///< numeric answers
        QString text;       ///< notes
        QDateTime answered;
    };

    ~StudyDatabase();

    /**
     * Creates a study at `path`, which must not exist, for `protocol`; null with `PATH:
     * reason` in `error`.
     */
    static std::unique_ptr<StudyDatabase> create(const QString &path,
                                                 const StudyProtocol &protocol, QString *error);
    /**
     * Opens a study. Write access takes the study's lock (refused while another semhap
     * holds it) and marks a trial left running by a crash as interrupted. Null with
     * `PATH: reason` in `error`.
     */
    static std::unique_ptr<StudyDatabase> open(const QString &path, Access access, QString *error);

    const QString &path() const { return m_path; }
    /** The folder of a study's sessions: `STUDY.sessions` beside `STUDY.db`. */
    static QString sessionsFolder(const QString &path);
    /**
     * The first read that failed since the study was opened (`FILE: cannot read: why`, a
     * damaged file), empty when none did: what was read until then is incomplete.
     */
    const QString &readError() const { return m_readError; }
    const StudyProtocol &protocol() const { return m_protocol; }

    /** The participants, in the order they were added. */
    QStringList participants() const;
    /**
     * Adds a participant with the next order of the scheme. An id is 1–32 of
     * `A-Z a-z 0-9 _ . -` (no names needed); false with the reason in `error`.
     */
    bool addParticipant(const QString &id, QString *error);
    /**
     * Adds a participant with row `position` (0-based) of the scheme, which no one else has:
     * a study simulated in shards gives each participant the row it has on one machine.
     */
    bool addParticipant(const QString &id, int position, QString *error);
    /** The participant's row of the scheme (0-based); -1 for an unknown one. */
    int position(const QString &participant) const;
    /**
     * Copies `participant` of `from` into this study as it is there: its row of the scheme,
     * its trials in their order with their sessions (copied into this study's sessions
     * folder) and its answers, in one transaction; false with `error` and nothing changed.
     */
    bool copyParticipant(const StudyDatabase &from, const QString &participant, QString *error);

    /**
     * Points every trial's session at the file of the same name in `folder`: the sessions
     * folder is about to move there (a merged study renamed into place).
     */
    bool relocateSessions(const QString &folder, QString *error);

    /** A value of the study's own table (`simulation`, `created` …); empty when unset. */
    QString value(const QString &key) const;
    /** Sets a value of the study's own table; false with `error`. */
    bool setValue(const QString &key, const QString &value, QString *error);
    /** The participant's order of conditions (indices); empty for an unknown one. */
    std::vector<int> order(const QString &participant) const;

    /** The participant's trials (practice rounds too), oldest first; all when empty. */
    std::vector<Trial> trials(const QString &participant = QString()) const;
    /** The participant's current answers (the newest per measure); all when empty. */
    std::vector<Answer> answers(const QString &participant = QString()) const;
    /** What the participant does next: the first step not done yet. */
    StudyProtocol::Step nextStep(const QString &participant) const;
    /** Whether `step` is done for the participant. */
    bool isDone(const QString &participant, const StudyProtocol::Step &step) const;

    /**
     * Where the session of the participant's next attempt at `step` is to be recorded: a
     * new file in the study's sessions folder (created here), absolute.
     */
    QString newSessionPath(const QString &participant, const StudyProtocol::Step &step,
                           QString *error) const;
    /** Adds the study's keys to a trial's session: study, participant, condition, phase, trial. */
    void tagSession(const QString &participant, const StudyProtocol::Step &step,
                    SessionInfo *info) const;

    /** Records that `step` (Practice or Trial) began, recording into `session`; its id or 0. */
    qint64 beginTrial(const QString &participant, const StudyProtocol::Step &step,
                      const QString &session, QString *error);
    /** Ends a running trial as done with its metrics after `seconds`. */
    bool finishTrial(qint64 id, double seconds, const QJsonObject &metrics, QString *error);
    /** Ends a running trial as aborted (it does not count; the step is due again). */
    bool abortTrial(qint64 id, double seconds, const QString &reason, QString *error);
    /** Marks a done trial invalid with its reason: the step is due again, to be redone. */
    bool invalidateTrial(qint64 id, const QString &reason, QString *error);

    /**
     * Stores an answer at once. Refused (false, `error`) when the measure is not one the
     * step's items ask, or the value lies outside its scale or between its steps.
     */
    bool answer(const Answer &answer, QString *error);

private:
    StudyDatabase() = default;
    bool exec(const QString &sql, const QVariantList &values, QString *error);
    /** Runs a prepared read; false (the error noted) when it failed. */
    bool readAll(QSqlQuery &query) const;
    /** Notes the query's error as readError() unless one is noted already. */
    void noteReadError(const QSqlQuery &query) const;
    bool setStatus(qint64 id, Status from, Status to, double seconds, const QJsonObject *metrics,
                   const QString &reason, QString *error);
    /** The item of the step's questionnaire that asks `measure`, or null. */
    const StudyProtocol::Question *question(int condition, const QString &measure) const;

    QString m_path;
    QString m_connection;
    QSqlDatabase m_db;
    StudyProtocol m_protocol;
    std::unique_ptr<QLockFile> m_lock;
    mutable QString m_readError;
};

/** The name the database stores a status as (`running`, `done`, …). */
QString statusName(StudyDatabase::Status status);

} // namespace semhap
