// SPDX-License-Identifier: MIT
#include "studydatabase.h"

#include "sessioninfo.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QLockFile>
#include <QRegularExpression>
#include <QSqlError>
#include <QSqlQuery>
#include <QUrl>

#include <atomic>
#include <cmath>

namespace semhap {

namespace {

constexpr const char *Format = "semhap.studydb/1";

const char *const Schema[] = {
    "CREATE TABLE study (key TEXT PRIMARY KEY, value TEXT NOT NULL)",
    "CREATE TABLE participants (id TEXT PRIMARY KEY, position INTEGER NOT NULL UNIQUE, "
    "conditions TEXT NOT NULL, added TEXT NOT NULL)",
    "CREATE TABLE trials (id INTEGER PRIMARY KEY, participant TEXT NOT NULL REFERENCES "
    "participants(id), condition TEXT NOT NULL, phase TEXT NOT NULL, number INTEGER NOT NULL, "
    "session TEXT NOT NULL, started TEXT NOT NULL, ended TEXT, status TEXT NOT NULL, "
    "reason TEXT NOT NULL DEFAULT '', seconds REAL NOT NULL DEFAULT 0, metrics TEXT NOT NULL "
    "DEFAULT '{}')",
    "CREATE TABLE answers (id INTEGER PRIMARY KEY, participant TEXT NOT NULL REFERENCES "
    "participants(id), condition TEXT NOT NULL, measure TEXT NOT NULL, value REAL, text TEXT, "
    "answered TEXT NOT NULL)",
};

QString now()
{
    return QDateTime::currentDateTimeUtc().toString(Qt::ISODateWithMs);
}

QString phaseName(bool practice)
{
    return practice ? QStringLiteral("practice") : QStringLiteral("trial");
}

QString newConnectionName()
{
    static std::atomic<int> counter{0};
    return QStringLiteral("semhap-study-%1").arg(counter++);
}

/** `path: reason`, the way every study error reads. */
QString located(const QString &path, const QString &reason)
{
    return QStringLiteral("%1: %2").arg(path, reason);
}

/** `text` bound as text: Qt binds a null QString as NULL, which equals nothing. */
QVariant text(const QString &text)
{
    return text.isNull() ? QVariant(QStringLiteral("")) : QVariant(text);
}

} // namespace

QString statusName(StudyDatabase::Status status)
{
    switch (status) {
    case StudyDatabase::Status::Running:
        return QStringLiteral("running");
    case StudyDatabase::Status::Done:
        return QStringLiteral("done");
    case StudyDatabase::Status::Aborted:
        return QStringLiteral("aborted");
    case StudyDatabase::Status::Invalid:
        return QStringLiteral("invalid");
    case StudyDatabase::Status::Interrupted:
        break;
    }
    return QStringLiteral("interrupted");
}

StudyDatabase::~StudyDatabase()
{
    if (m_db.isValid())
        m_db.close();
    m_db = QSqlDatabase();
    if (!m_connection.isEmpty())
        QSqlDatabase::removeDatabase(m_connection);
}

std::unique_ptr<StudyDatabase> StudyDatabase::create(const QString &path,
                                                     const StudyProtocol &protocol, QString *error)
{
    if (QFileInfo::exists(path)) {
        *error = located(path, QStringLiteral("already exists (a study is never overwritten; "
                                              "open it to go on)"));
        return nullptr;
    }
    // What a deleted study left would be taken for this one's: its journal, its sessions.
    for (const QString &left : QStringList{path + QStringLiteral("-wal"),
                                           path + QStringLiteral("-shm"), sessionsFolder(path)}) {
        if (QFileInfo::exists(left) &&
            !(QFileInfo(left).isDir() &&
              QDir(left).isEmpty(QDir::NoDotAndDotDot | QDir::AllEntries))) {
            *error = located(path, QStringLiteral("%1 is left from another study: move it away "
                                                  "first")
                                       .arg(QFileInfo(left).fileName()));
            return nullptr;
        }
    }
    {
        const QString connection = newConnectionName();
        bool ok = true;
        QString reason;
        {
            QSqlDatabase db = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), connection);
            db.setDatabaseName(path);
            ok = db.open();
            if (!ok)
                reason = db.lastError().text();
            QSqlQuery query(db);
            const auto run = [&](const QString &sql) {
                if (ok && !query.exec(sql)) {
                    ok = false;
                    reason = query.lastError().text();
                }
            };
            run(QStringLiteral("PRAGMA journal_mode=WAL"));
            run(QStringLiteral("BEGIN"));
            for (const char *statement : Schema)
                run(QLatin1String(statement));
            const QList<QPair<QString, QString>> rows{
                {QStringLiteral("format"), QLatin1String(Format)},
                {QStringLiteral("protocol_file"), QFileInfo(protocol.file).absoluteFilePath()},
                {QStringLiteral("protocol"), QString::fromUtf8(protocol.source)},
                {QStringLiteral("created"), now()}};
            for (const auto &row : rows) {
                if (!ok)
                    break;
                query.prepare(QStringLiteral("INSERT INTO study VALUES (?, ?)"));
                query.addBindValue(row.first);
                query.addBindValue(row.second);
                if (!query.exec()) {
                    ok = false;
                    reason = query.lastError().text();
                }
            }
            run(QStringLiteral("COMMIT"));
            db.close();
        }
        QSqlDatabase::removeDatabase(connection);
        if (!ok) {
            *error = located(path, QStringLiteral("cannot write: %1").arg(reason));
            return nullptr;
        }
    }
    return open(path, Access::Write, error);
}

std::unique_ptr<StudyDatabase> StudyDatabase::open(const QString &path, Access access,
                                                   QString *error)
{
    if (!QFileInfo(path).isFile()) {
        *error = located(path, QStringLiteral("no such study"));
        return nullptr;
    }
    std::unique_ptr<StudyDatabase> study(new StudyDatabase);
    study->m_path = path;
    if (access == Access::Write) {
        // The lock file names the process holding it: a crashed one's lock is taken over,
        // a live one's never, however old (so no stale time).
        // One lock per file, however it is reached (a link, another mount path).
        study->m_lock = std::make_unique<QLockFile>(QFileInfo(path).canonicalFilePath() +
                                                    QStringLiteral(".lock"));
        study->m_lock->setStaleLockTime(0);
        if (!study->m_lock->tryLock(0)) {
            qint64 pid = 0;
            QString host, application;
            study->m_lock->getLockInfo(&pid, &host, &application);
            *error = study->m_lock->error() == QLockFile::LockFailedError
                         ? located(path, QStringLiteral("already open in %1 (process %2 on %3); "
                                                        "close it there first")
                                             .arg(application.isEmpty() ? QStringLiteral("semhap")
                                                                        : application)
                                             .arg(pid)
                                             .arg(host))
                         : located(path, QStringLiteral("cannot write its lock file %1.lock")
                                             .arg(QFileInfo(path).fileName()));
            return nullptr;
        }
    }
    study->m_connection = newConnectionName();
    study->m_db = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), study->m_connection);
    study->m_db.setDatabaseName(path);
    if (access == Access::Read)
        study->m_db.setConnectOptions(QStringLiteral("QSQLITE_OPEN_READONLY"));
    if (!study->m_db.open()) {
        *error =
            located(path, QStringLiteral("cannot open: %1").arg(study->m_db.lastError().text()));
        return nullptr;
    }
    QSqlQuery query(study->m_db);
    QMap<QString, QString> rows;
    if (query.exec(QStringLiteral("SELECT key, value FROM study"))) {
        while (query.next())
            rows.insert(query.value(0).toString(), query.value(1).toString());
    }
    if (rows.value(QStringLiteral("format")) != QLatin1String(Format)) {
        *error =
            located(path, QStringLiteral("not a semhap study (%1)").arg(QLatin1String(Format)));
        return nullptr;
    }
    // The protocol the study began with, whatever became of its file since; routers and
    // scene files it names are found beside where it was.
    // Reading results needs only the protocol's structure; running it, its routers and scene.
    LoadError protocolError;
    if (!StudyProtocol::parse(rows.value(QStringLiteral("protocol")).toUtf8(),
                              rows.value(QStringLiteral("protocol_file")), &study->m_protocol,
                              &protocolError,
                              access == Access::Write ? StudyProtocol::Checks::Full
                                                      : StudyProtocol::Checks::Structure)) {
        *error = located(
            path,
            QStringLiteral("its protocol no longer loads: %1").arg(protocolError.toString()));
        return nullptr;
    }
    if (access == Access::Write) {
        // Each answer and trial is committed when it happens, to the platter (FULL).
        const bool ok =
            query.exec(QStringLiteral("PRAGMA journal_mode=WAL")) &&
            query.exec(QStringLiteral("PRAGMA synchronous=FULL")) &&
            study->exec(
                QStringLiteral("UPDATE trials SET status = ?, reason = ? WHERE status = ?"),
                {statusName(Status::Interrupted), QStringLiteral("the study closed while it ran"),
                 statusName(Status::Running)},
                error);
        if (!ok) {
            if (error->isEmpty())
                *error = located(path, query.lastError().text());
            return nullptr;
        }
    }
    return study;
}

bool StudyDatabase::exec(const QString &sql, const QVariantList &values, QString *error)
{
    QSqlQuery query(m_db);
    query.prepare(sql);
    for (const QVariant &value : values)
        query.addBindValue(value);
    if (query.exec())
        return true;
    *error = located(m_path, QStringLiteral("cannot write: %1").arg(query.lastError().text()));
    return false;
}

bool StudyDatabase::readAll(QSqlQuery &query) const
{
    if (!query.exec()) {
        noteReadError(query);
        return false;
    }
    return true;
}

void StudyDatabase::noteReadError(const QSqlQuery &query) const
{
    if (m_readError.isEmpty() && query.lastError().isValid())
        m_readError = located(
            m_path, QStringLiteral("cannot read: %1").arg(query.lastError().databaseText()));
}

QStringList StudyDatabase::participants() const
{
    QStringList ids;
    QSqlQuery query(m_db);
    query.prepare(QStringLiteral("SELECT id FROM participants ORDER BY position"));
    if (!readAll(query))
        return ids;
    while (query.next())
        ids.append(query.value(0).toString());
    noteReadError(query);
    return ids;
}

bool StudyDatabase::addParticipant(const QString &id, QString *error)
{
    return addParticipant(id, int(participants().size()), error);
}

int StudyDatabase::position(const QString &participant) const
{
    QSqlQuery query(m_db);
    query.prepare(QStringLiteral("SELECT position FROM participants WHERE id = ?"));
    query.addBindValue(participant);
    if (readAll(query) && query.next())
        return query.value(0).toInt();
    return -1;
}

bool StudyDatabase::relocateSessions(const QString &folder, QString *error)
{
    QSqlQuery query(m_db);
    query.prepare(QStringLiteral("SELECT id, session FROM trials"));
    if (!readAll(query)) {
        *error = m_readError;
        return false;
    }
    std::vector<std::pair<qint64, QString>> moved;
    const QDir home = QFileInfo(m_path).absoluteDir();
    while (query.next())
        moved.emplace_back(query.value(0).toLongLong(),
                           home.relativeFilePath(QDir(folder).filePath(
                               QFileInfo(query.value(1).toString()).fileName())));
    if (!m_db.transaction()) {
        *error = located(m_path, QStringLiteral("cannot write: %1").arg(m_db.lastError().text()));
        return false;
    }
    for (const auto &[id, session] : moved) {
        if (!exec(QStringLiteral("UPDATE trials SET session = ? WHERE id = ?"), {session, id},
                  error)) {
            m_db.rollback();
            return false;
        }
    }
    if (!m_db.commit()) {
        *error = located(m_path, QStringLiteral("cannot write: %1").arg(m_db.lastError().text()));
        return false;
    }
    return true;
}

QString StudyDatabase::value(const QString &key) const
{
    QSqlQuery query(m_db);
    query.prepare(QStringLiteral("SELECT value FROM study WHERE key = ?"));
    query.addBindValue(key);
    if (readAll(query) && query.next())
        return query.value(0).toString();
    return QString();
}

bool StudyDatabase::setValue(const QString &key, const QString &value, QString *error)
{
    return exec(QStringLiteral("INSERT OR REPLACE INTO study VALUES (?, ?)"), {key, value}, error);
}

bool StudyDatabase::copyParticipant(const StudyDatabase &from, const QString &participant,
                                    QString *error)
{
    QSqlQuery row(from.m_db);
    row.prepare(
        QStringLiteral("SELECT position, conditions, added FROM participants WHERE id = ?"));
    row.addBindValue(participant);
    if (!from.readAll(row) || !row.next()) {
        *error = located(from.m_path, QStringLiteral("no participant '%1'").arg(participant));
        return false;
    }
    QSqlQuery trials(from.m_db);
    trials.prepare(QStringLiteral("SELECT condition, phase, number, session, started, ended, "
                                  "status, reason, seconds, metrics FROM trials WHERE "
                                  "participant = ? ORDER BY id"));
    trials.addBindValue(participant);
    QSqlQuery answers(from.m_db);
    answers.prepare(QStringLiteral("SELECT condition, measure, value, text, answered FROM "
                                   "answers WHERE participant = ? ORDER BY id"));
    answers.addBindValue(participant);
    if (!from.readAll(trials) || !from.readAll(answers)) {
        *error = from.readError();
        return false;
    }
    const QString folder = sessionsFolder(m_path);
    if (!QDir().mkpath(folder)) {
        *error = located(folder, QStringLiteral("cannot create the sessions folder"));
        return false;
    }
    QStringList copied;
    const auto fail = [&](const QString &reason) {
        m_db.rollback();
        for (const QString &file : copied)
            QFile::remove(file);
        *error = reason;
        return false;
    };
    if (!m_db.transaction())
        return fail(
            located(m_path, QStringLiteral("cannot write: %1").arg(m_db.lastError().text())));
    if (!exec(QStringLiteral("INSERT INTO participants VALUES (?, ?, ?, ?)"),
              {participant, row.value(0), row.value(1), row.value(2)}, error))
        return fail(*error);
    while (trials.next()) {
        // The session goes beside this study under its own name; a study names its sessions
        // relative to its own folder.
        const QString source =
            QFileInfo(from.m_path).absoluteDir().filePath(trials.value(3).toString());
        const QString target = QDir(folder).filePath(QFileInfo(source).fileName());
        if (QFileInfo::exists(target))
            return fail(located(target, QStringLiteral("already exists")));
        QFile file(source);
        if (!file.copy(target))
            return fail(
                located(target, QStringLiteral("cannot write: %1").arg(file.errorString())));
        copied.append(target);
        QVariantList values{participant};
        const QString relative = QFileInfo(m_path).absoluteDir().relativeFilePath(target);
        for (int column = 0; column < 10; ++column)
            values.append(column == 3 ? QVariant(relative) : trials.value(column));
        if (!exec(QStringLiteral("INSERT INTO trials (participant, condition, phase, number, "
                                 "session, started, ended, status, reason, seconds, metrics) "
                                 "VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)"),
                  values, error))
            return fail(*error);
    }
    while (answers.next()) {
        if (!exec(QStringLiteral("INSERT INTO answers (participant, condition, measure, value, "
                                 "text, answered) VALUES (?, ?, ?, ?, ?, ?)"),
                  {participant, answers.value(0), answers.value(1), answers.value(2),
                   answers.value(3), answers.value(4)},
                  error))
            return fail(*error);
    }
    if (!m_db.commit())
        return fail(
            located(m_path, QStringLiteral("cannot write: %1").arg(m_db.lastError().text())));
    return true;
}

bool StudyDatabase::addParticipant(const QString &id, int position, QString *error)
{
    if (!StudyProtocol::isId(id)) {
        *error =
            QStringLiteral("a participant's id is 1 to 32 of A-Z a-z 0-9 _ . -, got '%1'").arg(id);
        return false;
    }
    if (participants().contains(id)) {
        *error = QStringLiteral("'%1' is already a participant").arg(id);
        return false;
    }
    if (position < 0) {
        *error =
            QStringLiteral("a participant's row of the scheme is 0 or more, got %1").arg(position);
        return false;
    }
    QStringList ids;
    for (int condition : m_protocol.order().order(position))
        ids.append(m_protocol.conditions[size_t(condition)].id);
    return exec(QStringLiteral("INSERT INTO participants VALUES (?, ?, ?, ?)"),
                {id, position, ids.join(QLatin1Char(' ')), now()}, error);
}

std::vector<int> StudyDatabase::order(const QString &participant) const
{
    QSqlQuery query(m_db);
    query.prepare(QStringLiteral("SELECT conditions FROM participants WHERE id = ?"));
    query.addBindValue(participant);
    std::vector<int> order;
    if (query.exec() && query.next()) {
        for (const QString &id :
             query.value(0).toString().split(QLatin1Char(' '), Qt::SkipEmptyParts))
            order.push_back(m_protocol.conditionIndex(id));
    }
    return order;
}

std::vector<StudyDatabase::Trial> StudyDatabase::trials(const QString &participant) const
{
    QSqlQuery query(m_db);
    query.prepare(QStringLiteral(
        "SELECT id, participant, condition, phase, number, session, started, ended, status, "
        "reason, seconds, metrics FROM trials WHERE ? = '' OR participant = ? ORDER BY id"));
    query.addBindValue(text(participant));
    query.addBindValue(text(participant));
    std::vector<Trial> out;
    if (!readAll(query))
        return out;
    while (query.next()) {
        Trial t;
        t.id = query.value(0).toLongLong();
        t.participant = query.value(1).toString();
        t.condition = m_protocol.conditionIndex(query.value(2).toString());
        t.practice = query.value(3).toString() == phaseName(true);
        t.number = query.value(4).toInt();
        t.session = query.value(5).toString();
        t.started = QDateTime::fromString(query.value(6).toString(), Qt::ISODateWithMs);
        t.ended = QDateTime::fromString(query.value(7).toString(), Qt::ISODateWithMs);
        const QString status = query.value(8).toString();
        for (Status s : {Status::Running, Status::Done, Status::Aborted, Status::Invalid,
                         Status::Interrupted}) {
            if (statusName(s) == status)
                t.status = s;
        }
        t.reason = query.value(9).toString();
        t.seconds = query.value(10).toDouble();
        t.metrics = QJsonDocument::fromJson(query.value(11).toByteArray()).object();
        out.push_back(t);
    }
    noteReadError(query);
    return out;
}

std::vector<StudyDatabase::Answer> StudyDatabase::answers(const QString &participant) const
{
    // The newest row of each (participant, condition, measure): the answer that counts.
    QSqlQuery query(m_db);
    query.prepare(QStringLiteral(
        "SELECT participant, condition, measure, value, text, answered FROM answers a "
        "WHERE (? = '' OR participant = ?) AND id = (SELECT MAX(id) FROM answers b "
        "WHERE b.participant = a.participant AND b.condition = a.condition "
        "AND b.measure = a.measure) ORDER BY id"));
    query.addBindValue(text(participant));
    query.addBindValue(text(participant));
    std::vector<Answer> out;
    if (!readAll(query))
        return out;
    while (query.next()) {
        Answer a;
        a.participant = query.value(0).toString();
        a.condition = m_protocol.conditionIndex(query.value(1).toString());
        a.measure = query.value(2).toString();
        a.value = query.value(3).isNull() ? std::nan("") : query.value(3).toDouble();
        a.text = query.value(4).toString();
        a.answered = QDateTime::fromString(query.value(5).toString(), Qt::ISODateWithMs);
        out.push_back(a);
    }
    noteReadError(query);
    return out;
}

bool StudyDatabase::isDone(const QString &participant, const StudyProtocol::Step &step) const
{
    using Kind = StudyProtocol::Step::Kind;
    if (step.kind == Kind::Done)
        return true;
    if (step.kind == Kind::Practice || step.kind == Kind::Trial) {
        QSqlQuery query(m_db);
        query.prepare(QStringLiteral("SELECT COUNT(*) FROM trials WHERE participant = ? AND "
                                     "condition = ? AND phase = ? AND number = ? AND status = ?"));
        query.addBindValue(participant);
        query.addBindValue(m_protocol.conditions[size_t(step.condition)].id);
        query.addBindValue(phaseName(step.kind == Kind::Practice));
        query.addBindValue(step.trial);
        query.addBindValue(statusName(Status::Done));
        return query.exec() && query.next() && query.value(0).toInt() > 0;
    }
    // A questionnaire is done when each of its measures has an answer.
    const std::vector<Answer> given = answers(participant);
    const auto answered = [&](int condition, const QString &measure) {
        return std::any_of(given.begin(), given.end(), [&](const Answer &a) {
            return a.condition == condition && a.measure == measure;
        });
    };
    const bool final = step.kind == Kind::Final;
    for (const StudyProtocol::Question &q :
         final ? m_protocol.atTheEnd : m_protocol.questionsAfter(step.condition)) {
        for (const QString &measure : q.measures()) {
            if (q.kind == StudyProtocol::Question::Kind::Ranking) {
                for (const QString &id : q.conditions) {
                    if (!answered(m_protocol.conditionIndex(id), measure))
                        return false;
                }
            } else if (!answered(final ? -1 : step.condition, measure)) {
                return false;
            }
        }
    }
    return true;
}

StudyProtocol::Step StudyDatabase::nextStep(const QString &participant) const
{
    for (const StudyProtocol::Step &step : m_protocol.steps(order(participant))) {
        if (!isDone(participant, step))
            return step;
    }
    return {};
}

QString StudyDatabase::sessionsFolder(const QString &path)
{
    const QFileInfo file(path);
    return file.absoluteDir().filePath(file.completeBaseName() + QStringLiteral(".sessions"));
}

QString StudyDatabase::newSessionPath(const QString &participant, const StudyProtocol::Step &step,
                                      QString *error) const
{
    const QString folder = sessionsFolder(m_path);
    if (!QDir().mkpath(folder)) {
        *error = located(folder, QStringLiteral("cannot create the sessions folder"));
        return QString();
    }
    const bool practice = step.kind == StudyProtocol::Step::Kind::Practice;
    const QString stem =
        QStringLiteral("%1/%2-%3-%4")
            .arg(folder, participant, m_protocol.conditions[size_t(step.condition)].id,
                 practice ? QStringLiteral("practice")
                          : QStringLiteral("trial%1").arg(step.trial));
    // A redone trial gets a file of its own; the first attempt's session stays.
    QString path = stem + QStringLiteral(".db");
    for (int attempt = 2; QFileInfo::exists(path); ++attempt)
        path = QStringLiteral("%1-%2.db").arg(stem).arg(attempt);
    return path;
}

void StudyDatabase::tagSession(const QString &participant, const StudyProtocol::Step &step,
                               SessionInfo *info) const
{
    const bool practice = step.kind == StudyProtocol::Step::Kind::Practice;
    info->extra.insert(QStringLiteral("study"), m_protocol.name);
    info->extra.insert(QStringLiteral("participant"), participant);
    info->extra.insert(QStringLiteral("condition"),
                       m_protocol.conditions[size_t(step.condition)].id);
    info->extra.insert(QStringLiteral("phase"), phaseName(practice));
    info->extra.insert(QStringLiteral("trial"), QString::number(step.trial));
}

qint64 StudyDatabase::beginTrial(const QString &participant, const StudyProtocol::Step &step,
                                 const QString &session, QString *error)
{
    using Kind = StudyProtocol::Step::Kind;
    if ((step.kind != Kind::Practice && step.kind != Kind::Trial) || step.condition < 0 ||
        step.condition >= int(m_protocol.conditions.size()) || order(participant).empty()) {
        *error = QStringLiteral("no such practice round or trial of '%1'").arg(participant);
        return 0;
    }
    const QString relative = QFileInfo(m_path).absoluteDir().relativeFilePath(session);
    QSqlQuery query(m_db);
    query.prepare(QStringLiteral("INSERT INTO trials (participant, condition, phase, number, "
                                 "session, started, status) VALUES (?, ?, ?, ?, ?, ?, ?)"));
    for (const QVariant &value :
         QVariantList{participant, m_protocol.conditions[size_t(step.condition)].id,
                      phaseName(step.kind == Kind::Practice), step.trial, relative, now(),
                      statusName(Status::Running)})
        query.addBindValue(value);
    if (!query.exec()) {
        *error = located(m_path, QStringLiteral("cannot write: %1").arg(query.lastError().text()));
        return 0;
    }
    return query.lastInsertId().toLongLong();
}

bool StudyDatabase::setStatus(qint64 id, Status from, Status to, double seconds,
                              const QJsonObject *metrics, const QString &reason, QString *error)
{
    QSqlQuery query(m_db);
    query.prepare(QStringLiteral("SELECT status FROM trials WHERE id = ?"));
    query.addBindValue(id);
    if (!query.exec() || !query.next()) {
        *error = QStringLiteral("no trial %1").arg(id);
        return false;
    }
    if (query.value(0).toString() != statusName(from)) {
        *error = QStringLiteral("trial %1 is %2, not %3")
                     .arg(id)
                     .arg(query.value(0).toString(), statusName(from));
        return false;
    }
    if (to == Status::Invalid)
        return exec(QStringLiteral("UPDATE trials SET status = ?, reason = ? WHERE id = ?"),
                    {statusName(to), text(reason), id}, error);
    const QString json =
        metrics ? QString::fromUtf8(QJsonDocument(*metrics).toJson(QJsonDocument::Compact))
                : QStringLiteral("{}");
    return exec(QStringLiteral("UPDATE trials SET status = ?, reason = ?, ended = ?, seconds = ?, "
                               "metrics = ? WHERE id = ?"),
                {statusName(to), text(reason), now(), seconds, json, id}, error);
}

bool StudyDatabase::finishTrial(qint64 id, double seconds, const QJsonObject &metrics,
                                QString *error)
{
    return setStatus(id, Status::Running, Status::Done, seconds, &metrics, QString(), error);
}

bool StudyDatabase::abortTrial(qint64 id, double seconds, const QString &reason, QString *error)
{
    return setStatus(id, Status::Running, Status::Aborted, seconds, nullptr, reason, error);
}

bool StudyDatabase::invalidateTrial(qint64 id, const QString &reason, QString *error)
{
    if (reason.trimmed().isEmpty()) {
        *error = QStringLiteral("say why the trial does not count");
        return false;
    }
    return setStatus(id, Status::Done, Status::Invalid, 0, nullptr, reason, error);
}

const StudyProtocol::Question *StudyDatabase::question(int condition, const QString &measure) const
{
    using Kind = StudyProtocol::Question::Kind;
    for (const StudyProtocol::Question &q : m_protocol.afterCondition) {
        if (condition >= 0 && q.measures().contains(measure) &&
            condition < int(m_protocol.conditions.size()) &&
            q.asksAfter(m_protocol.conditions[size_t(condition)].id))
            return &q;
    }
    for (const StudyProtocol::Question &q : m_protocol.atTheEnd) {
        // A ranking's answers are about a condition each; the final items' others, none.
        if (q.measures().contains(measure) && (q.kind == Kind::Ranking) == (condition >= 0))
            return &q;
    }
    return nullptr;
}

bool StudyDatabase::answer(const Answer &a, QString *error)
{
    if (order(a.participant).empty()) {
        *error = QStringLiteral("no participant '%1'").arg(a.participant);
        return false;
    }
    if (a.condition >= int(m_protocol.conditions.size())) {
        *error = QStringLiteral("no condition %1").arg(a.condition);
        return false;
    }
    const StudyProtocol::Question *q = question(a.condition, a.measure);
    if (!q) {
        *error = QStringLiteral("no questionnaire item asks '%1' here").arg(a.measure);
        return false;
    }
    QVariant value;
    if (!q->isText()) {
        if (!std::isfinite(a.value) || a.value < q->lowest() || a.value > q->highest() ||
            a.value != std::floor(a.value)) {
            *error = QStringLiteral("'%1' takes a whole number from %2 to %3, got %4")
                         .arg(a.measure)
                         .arg(q->lowest())
                         .arg(q->highest())
                         .arg(a.value);
            return false;
        }
        value = a.value;
    }
    const QString condition =
        a.condition >= 0 ? m_protocol.conditions[size_t(a.condition)].id : QString();
    return exec(QStringLiteral("INSERT INTO answers (participant, condition, measure, value, "
                               "text, answered) VALUES (?, ?, ?, ?, ?, ?)"),
                {a.participant, text(condition), a.measure, value,
                 q->isText() ? text(a.text) : QVariant(), now()},
                error);
}

} // namespace semhap
