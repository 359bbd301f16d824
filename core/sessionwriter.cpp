// SPDX-License-Identifier: MIT
#include "sessionwriter.h"

#include "actortable.h"
#include "nametable.h"
#include "router.h"
#include "sessionschema.h"

#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSqlDatabase>
#include <QSqlError>
#include <QSqlQuery>
#include <QTemporaryFile>
#include <QtEndian>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <future>
#include <mutex>
#include <pthread.h>
#include <thread>
#include <time.h>
#include <unistd.h>
#include <variant>
#include <vector>

namespace semhap {

namespace {

/** One queued value; `arrival` only means something for contact frames. */
struct Record
{
    std::variant<ContactFrame, SemanticEvent, DeviceFrame, HandCommand, SceneState> value;
    double arrival = 0.0;
};

/** A device as the devices table and the device_frames rows name it. */
struct DeviceRow
{
    QString name;
    QString model;
    double rate = 0.0;
    QStringList channels;
};

QVariant optional(double value)
{
    return std::isfinite(value) ? QVariant(value) : QVariant();
}

QString sqlError(const QSqlError &error)
{
    return error.databaseText().isEmpty() ? error.text() : error.databaseText();
}

} // namespace

/** The writer thread: owns the database connection (Qt SQL connections are per thread). */
class SessionWriter::Thread
{
public:
    Thread(SessionWriter &owner, const QString &path, const Options &options)
        : m_owner(owner), m_path(path), m_options(options),
          m_connection(QStringLiteral("semhap.session.%1").arg(quintptr(this)))
    {
        m_front.reserve(size_t(options.capacity));
        m_back.reserve(size_t(options.capacity));
    }

    ~Thread() { stop(); }

    /** Starts the thread and waits until the database is created; false with the reason. */
    bool start(const SessionInfo &info, std::vector<DeviceRow> devices, QStringList nodes,
               QString *error)
    {
        m_devices = std::move(devices);
        m_nodes = std::move(nodes);
        std::promise<QString> opened;
        std::future<QString> result = opened.get_future();
        m_thread = std::thread([this, &info, &opened] { run(info, opened); });
        *error = result.get();
        if (error->isEmpty())
            return true;
        m_thread.join();
        return false;
    }

    /**
     * Producer side: copies `record` into the batch; false when it is full, unless the
     * options say to wait for the writer to take the batch.
     */
    bool push(const Record &record)
    {
        std::unique_lock<std::mutex> lock(m_mutex);
        while (m_front.size() >= size_t(m_options.capacity)) {
            if (!m_options.waitWhenFull)
                return false;
            m_full = true;
            m_wake.notify_one();
            m_room.wait(lock);
        }
        m_front.push_back(record);
        return true;
    }

    /** Names actors in id order, before any frame that uses them is pushed. */
    void pushActor(const QString &name)
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        m_frontActors.append(name);
    }

    /** Commits the rest, stamps the end and joins; the first write error, if any. */
    QString stop()
    {
        if (m_thread.joinable()) {
            {
                std::lock_guard<std::mutex> lock(m_mutex);
                m_stopping = true;
            }
            m_wake.notify_one();
            m_thread.join();
        }
        return m_error;
    }

    double cpuSeconds() const
    {
        clockid_t clock;
        timespec spent{};
        if (!m_done.load() && pthread_getcpuclockid(m_handle, &clock) == 0 &&
            clock_gettime(clock, &spent) == 0)
            return double(spent.tv_sec) + double(spent.tv_nsec) * 1e-9;
        return m_cpuAtEnd.load();
    }

private:
    void run(const SessionInfo &info, std::promise<QString> &opened)
    {
        m_handle = pthread_self();
        {
            QSqlDatabase db = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), m_connection);
            QString error;
            QString temporary;
            if (!create(db, info, &temporary, &error)) {
                db.close();
                db = QSqlDatabase();
                QSqlDatabase::removeDatabase(m_connection);
                // Leave nothing half made behind: the session's own name was never taken.
                if (!temporary.isEmpty()) {
                    for (const char *suffix : {"", "-wal", "-shm", "-journal"})
                        QFile::remove(temporary + QLatin1String(suffix));
                }
                m_done = true;
                opened.set_value(m_path + QStringLiteral(": ") + error);
                return;
            }
            opened.set_value(QString());
            loop(db);
            QSqlQuery stamp(db);
            stamp.prepare(QStringLiteral("INSERT OR REPLACE INTO metadata VALUES (?, ?)"));
            stamp.addBindValue(QStringLiteral("ended_utc"));
            stamp.addBindValue(QDateTime::currentDateTimeUtc().toString(Qt::ISODateWithMs));
            check(stamp.exec(), stamp);
            stamp.addBindValue(QStringLiteral("dropped"));
            stamp.addBindValue(QString::number(m_owner.dropped()));
            check(stamp.exec(), stamp);
            stamp.clear();
            m_frameInsert.clear();
            m_eventInsert.clear();
            m_deviceInsert.clear();
            m_inputInsert.clear();
            m_sceneInsert.clear();
            // A finished session is one file: back to a rollback journal, so readers (the
            // studio's replay, `semhap replay`, opening it read-only) leave no -wal or -shm
            // beside it. WAL was for recording; a killed recording keeps it and recovers.
            QSqlQuery journal(db);
            check(journal.exec(QStringLiteral("PRAGMA journal_mode=DELETE")), journal);
            journal.clear();
            db.close();
        }
        QSqlDatabase::removeDatabase(m_connection);
        m_cpuAtEnd = cpuSeconds();
        m_done = true;
    }

    /**
     * Creates the database under a temporary name beside the session's (`temporary`), with
     * its schema and metadata, and only then gives it the session's name, which must still be
     * free: a process killed on the way leaves a stray temporary, never a session that will
     * not open, and no file is ever replaced.
     */
    bool create(QSqlDatabase &db, const SessionInfo &info, QString *temporary, QString *error)
    {
        if (!db.isValid()) {
            *error = QStringLiteral("the Qt SQLite driver (QSQLITE) is not available");
            return false;
        }
        {
            const QFileInfo target(m_path);
            QTemporaryFile reserve(target.absolutePath() + QStringLiteral("/.") +
                                   target.fileName() + QStringLiteral(".XXXXXX"));
            reserve.setAutoRemove(false);
            if (!reserve.open()) {
                *error = QStringLiteral("cannot create: ") + reserve.errorString();
                return false;
            }
            *temporary = reserve.fileName();
        }
        db.setDatabaseName(*temporary);
        if (!db.open()) {
            *error = QStringLiteral("cannot create: ") + sqlError(db.lastError());
            return false;
        }
        QSqlQuery query(db);
        // WAL: a commit is one append, readers never block the writer, and a killed
        // process leaves a database that opens. The mode is kept in the file.
        if (!query.exec(QStringLiteral("PRAGMA journal_mode=WAL")) || !query.next() ||
            query.value(0).toString() != QLatin1String("wal")) {
            *error =
                QStringLiteral("cannot use write-ahead logging: ") + sqlError(query.lastError());
            return false;
        }
        db.transaction();
        for (const QString &statement : SessionSchema::createStatements()) {
            if (!query.exec(statement)) {
                *error = QStringLiteral("cannot create: ") + sqlError(query.lastError());
                return false;
            }
        }
        const QMap<QString, QString> rows = info.toMetadata();
        query.prepare(QStringLiteral("INSERT INTO metadata VALUES (?, ?)"));
        for (auto it = rows.begin(); it != rows.end(); ++it) {
            query.addBindValue(it.key());
            // A null QString binds as NULL; the column wants text, even empty.
            query.addBindValue(it.value().isNull() ? QStringLiteral("") : it.value());
            if (!query.exec()) {
                *error = QStringLiteral("cannot write: ") + sqlError(query.lastError());
                return false;
            }
        }
        query.prepare(QStringLiteral("INSERT INTO devices VALUES (?, ?, ?, ?, ?)"));
        for (size_t d = 0; d < m_devices.size(); ++d) {
            query.addBindValue(int(d));
            query.addBindValue(m_devices[d].name);
            query.addBindValue(m_devices[d].model);
            query.addBindValue(m_devices[d].rate);
            query.addBindValue(
                QString::fromUtf8(QJsonDocument(QJsonArray::fromStringList(m_devices[d].channels))
                                      .toJson(QJsonDocument::Compact)));
            if (!query.exec()) {
                *error = QStringLiteral("cannot write: ") + sqlError(query.lastError());
                return false;
            }
        }
        if (!db.commit()) {
            *error = QStringLiteral("cannot write: ") + sqlError(db.lastError());
            return false;
        }
        // Closing checkpoints the log into the file, which can then be renamed whole.
        query = QSqlQuery();
        db.close();
        const QByteArray from = QFile::encodeName(*temporary);
        const QByteArray to = QFile::encodeName(m_path);
        if (::renameat2(AT_FDCWD, from.constData(), AT_FDCWD, to.constData(), RENAME_NOREPLACE) !=
            0) {
            // Some file systems cannot rename without replacing; a hard link cannot replace.
            const bool unsupported = errno == EINVAL || errno == ENOSYS;
            if (!unsupported || ::link(from.constData(), to.constData()) != 0) {
                *error = errno == EEXIST ? QStringLiteral("already exists (a session is never "
                                                          "overwritten)")
                                         : QStringLiteral("cannot create: ") +
                                               QString::fromLocal8Bit(std::strerror(errno));
                return false;
            }
            ::unlink(from.constData());
        }
        temporary->clear();
        db.setDatabaseName(m_path);
        if (!db.open()) {
            *error = QStringLiteral("cannot open: ") + sqlError(db.lastError());
            return false;
        }
        // NORMAL: no fsync per commit (a connection's setting, not the file's).
        query = QSqlQuery(db);
        if (!query.exec(QStringLiteral("PRAGMA synchronous=NORMAL"))) {
            *error = QStringLiteral("cannot open: ") + sqlError(query.lastError());
            return false;
        }
        return prepare(db, error);
    }

    bool prepare(QSqlDatabase &db, QString *error)
    {
        m_frameInsert = QSqlQuery(db);
        m_eventInsert = QSqlQuery(db);
        m_deviceInsert = QSqlQuery(db);
        m_inputInsert = QSqlQuery(db);
        m_sceneInsert = QSqlQuery(db);
        const std::array<std::pair<QSqlQuery *, int>, 5> inserts{{
            {&m_frameInsert, 18},
            {&m_eventInsert, 8},
            {&m_deviceInsert, 2 + MaxChannels},
            {&m_inputInsert, 10},
            {&m_sceneInsert, 6},
        }};
        const QStringList tables = SessionSchema::tables().mid(2);
        for (size_t i = 0; i < inserts.size(); ++i) {
            QSqlQuery &query = *inserts[i].first;
            const QString marks = QStringLiteral("?, ").repeated(inserts[i].second - 1);
            if (!query.prepare(
                    QStringLiteral("INSERT INTO %1 VALUES (%2?)").arg(tables.at(int(i)), marks))) {
                *error = QStringLiteral("cannot prepare: ") + sqlError(query.lastError());
                return false;
            }
        }
        for (Gripper g : {Gripper::Left, Gripper::Right})
            m_grippers[size_t(g)] = gripperName(g);
        return true;
    }

    void loop(QSqlDatabase &db)
    {
        std::unique_lock<std::mutex> lock(m_mutex);
        for (;;) {
            m_wake.wait_for(lock, std::chrono::milliseconds(m_options.commitMs),
                            [this] { return m_stopping || m_full; });
            std::swap(m_front, m_back);
            std::swap(m_frontActors, m_backActors);
            m_full = false;
            m_room.notify_all();
            const bool stopping = m_stopping;
            lock.unlock();
            write(db);
            lock.lock();
            if (stopping)
                return;
        }
    }

    void write(QSqlDatabase &db)
    {
        m_actorNames.append(m_backActors);
        m_backActors.clear();
        if (m_back.empty())
            return;
        db.transaction();
        for (const Record &record : m_back)
            std::visit([this, &record](const auto &value) { insert(value, record.arrival); },
                       record.value);
        if (!db.commit() && m_error.isEmpty())
            m_error = m_path + QStringLiteral(": cannot write: ") + sqlError(db.lastError());
        else
            m_owner.m_committed.fetch_add(m_back.size(), std::memory_order_relaxed);
        m_back.clear();
    }

    QVariant actor(int id) const
    {
        return id >= 0 && id < m_actorNames.size() ? QVariant(m_actorNames.at(id)) : QVariant();
    }

    void bindFingertip(const Fingertip &tip)
    {
        m_frameInsert.addBindValue(tip.f);
        m_frameInsert.addBindValue(tip.n);
        m_frameInsert.addBindValue(actor(tip.actor));
        for (double component : tip.fxyz)
            m_frameInsert.addBindValue(tip.hasFxyz ? QVariant(component) : QVariant());
    }

    void insert(const ContactFrame &frame, double arrival)
    {
        m_frameInsert.addBindValue(frame.t);
        m_frameInsert.addBindValue(m_grippers[size_t(frame.gripper)]);
        bindFingertip(frame.left);
        bindFingertip(frame.right);
        m_frameInsert.addBindValue(optional(arrival));
        for (const Fingertip *tip : {&frame.left, &frame.right})
            m_frameInsert.addBindValue(tip->mu > 0.0 ? QVariant(tip->mu) : QVariant());
        m_frameInsert.addBindValue(signalsText(frame.signalValues));
        check(m_frameInsert.exec(), m_frameInsert);
    }

    /** The frame's signals as the stream writes them (a JSON object), NULL for none. */
    static QVariant signalsText(const FrameSignals &signalValues)
    {
        if (signalValues.isEmpty())
            return QVariant();
        QJsonObject object;
        for (const SignalValue &signal : signalValues)
            object.insert(signalNames().name(signal.id), signal.value);
        return QString::fromUtf8(QJsonDocument(object).toJson(QJsonDocument::Compact));
    }

    void insert(const SemanticEvent &event, double)
    {
        m_eventInsert.addBindValue(event.t);
        m_eventInsert.addBindValue(m_grippers[size_t(event.gripper)]);
        m_eventInsert.addBindValue(event.node >= 0 && event.node < m_nodes.size()
                                       ? m_nodes.at(event.node)
                                       : QString::number(event.node));
        m_eventInsert.addBindValue(detectorKindName(event.detector));
        m_eventInsert.addBindValue(messageName(event.message));
        m_eventInsert.addBindValue(categoryName(event.category));
        m_eventInsert.addBindValue(eventPhaseName(event.phase));
        m_eventInsert.addBindValue(event.intensity);
        check(m_eventInsert.exec(), m_eventInsert);
    }

    void insert(const DeviceFrame &frame, double)
    {
        m_deviceInsert.addBindValue(frame.t);
        m_deviceInsert.addBindValue(frame.device >= 0 && size_t(frame.device) < m_devices.size()
                                        ? m_devices[size_t(frame.device)].name
                                        : QString::number(frame.device));
        for (int c = 0; c < MaxChannels; ++c)
            m_deviceInsert.addBindValue(c < frame.channelCount ? QVariant(frame.values[size_t(c)])
                                                               : QVariant());
        check(m_deviceInsert.exec(), m_deviceInsert);
    }

    void insert(const HandCommand &input, double)
    {
        m_inputInsert.addBindValue(input.t);
        m_inputInsert.addBindValue(m_grippers[size_t(input.hand)]);
        for (double v : input.target.pos)
            m_inputInsert.addBindValue(v);
        for (double v : input.target.quat)
            m_inputInsert.addBindValue(v);
        m_inputInsert.addBindValue(input.grip);
        check(m_inputInsert.exec(), m_inputInsert);
    }

    void insert(const SceneState &state, double)
    {
        m_sceneInsert.addBindValue(state.t);
        QByteArray pose(qsizetype(state.pose.size() * sizeof(double)), Qt::Uninitialized);
        qToLittleEndian<double>(state.pose.data(), qsizetype(state.pose.size()), pose.data());
        m_sceneInsert.addBindValue(pose);
        for (double value : state.overlay)
            m_sceneInsert.addBindValue(value);
        check(m_sceneInsert.exec(), m_sceneInsert);
    }

    void check(bool ok, const QSqlQuery &query)
    {
        if (!ok && m_error.isEmpty())
            m_error = m_path + QStringLiteral(": cannot write: ") + sqlError(query.lastError());
    }

    SessionWriter &m_owner;
    QString m_path;
    Options m_options;
    QString m_connection;
    std::vector<DeviceRow> m_devices;
    QStringList m_nodes;
    std::thread m_thread;
    pthread_t m_handle{};
    std::atomic<bool> m_done{false};
    std::atomic<double> m_cpuAtEnd{0.0};

    std::mutex m_mutex; ///< guards the front batch and m_stopping; held only to copy
    std::condition_variable m_wake;
    std::condition_variable m_room; ///< a waiting producer's: the batch was taken
    bool m_full = false;            ///< a producer waits for room (Options::waitWhenFull)
    bool m_stopping = false;
    std::vector<Record> m_front;
    QStringList m_frontActors;

    // Writer thread only.
    std::vector<Record> m_back;
    QStringList m_backActors;
    QStringList m_actorNames;
    std::array<QString, 2> m_grippers;
    QSqlQuery m_frameInsert;
    QSqlQuery m_eventInsert;
    QSqlQuery m_deviceInsert;
    QSqlQuery m_inputInsert;
    QSqlQuery m_sceneInsert;
    QString m_error;
};

SessionWriter::SessionWriter(const QString &path, Options options)
    : m_path(path), m_thread(std::make_unique<Thread>(*this, path, options))
{}

SessionWriter::~SessionWriter()
{
    finish();
}

std::unique_ptr<SessionWriter> SessionWriter::create(const QString &path, SessionInfo info,
                                                     const Router &router, QString *error)
{
    return create(path, std::move(info), router, Options(), error);
}

std::unique_ptr<SessionWriter> SessionWriter::create(const QString &path, SessionInfo info,
                                                     const Router &router, Options options,
                                                     QString *error)
{
    if (QFileInfo::exists(path)) {
        *error = path + QStringLiteral(": already exists (a session is never overwritten)");
        return nullptr;
    }
    if (info.router.isEmpty())
        info.router = router.selfContained().toJson();
    // A recording started mid-run (mid-grasp) begins what is active at its first frame.
    EventBuffer open;
    router.appendActive(0.0, open);
    if (!open.isEmpty()) {
        QJsonArray list;
        for (const SemanticEvent &event : open)
            list.append(QJsonObject{{QStringLiteral("node"), router.nodeIds().value(event.node)},
                                    {QStringLiteral("message"), messageName(event.message)}});
        info.extra.insert(QLatin1String(SessionInfo::OpenAtStartKey),
                          QString::fromUtf8(QJsonDocument(list).toJson(QJsonDocument::Compact)));
    }
    if (info.semhapVersion.isEmpty())
        info.semhapVersion = QStringLiteral(SEMHAP_VERSION);
    if (!info.started.isValid())
        info.started = QDateTime::currentDateTimeUtc();
    std::vector<DeviceRow> devices;
    const Player &player = router.player();
    for (int d = 0; d < player.deviceCount(); ++d) {
        const DeviceModel &model = player.deviceModel(d);
        devices.push_back(
            {player.deviceName(d), model.name(), model.rate(), model.channelNames()});
    }
    std::unique_ptr<SessionWriter> writer(new SessionWriter(path, options));
    if (!writer->m_thread->start(info, std::move(devices), router.nodeIds(), error)) {
        writer->m_finished = true;
        return nullptr;
    }
    writer->m_open.assign(open.begin(), open.end());
    return writer;
}

void SessionWriter::pushActors(const ContactFrame &frame)
{
    const int needed = std::max(frame.left.actor, frame.right.actor) + 1;
    if (needed <= m_actorsSent || !m_actors)
        return;
    for (; m_actorsSent < m_actors->size(); ++m_actorsSent)
        m_thread->pushActor(m_actors->name(m_actorsSent));
}

void SessionWriter::recordContactFrame(const ContactFrame &frame, double arrival)
{
    pushActors(frame);
    if (!m_thread->push({frame, arrival}))
        m_dropped.fetch_add(1, std::memory_order_relaxed);
    if (m_open.empty())
        return;
    // Before the first tick's own events, which may already end them.
    for (SemanticEvent &event : m_open) {
        event.t = frame.t;
        onEvent(event);
    }
    m_open.clear();
}

void SessionWriter::recordHandCommand(const HandCommand &input)
{
    if (!m_thread->push({input, 0.0}))
        m_dropped.fetch_add(1, std::memory_order_relaxed);
}

void SessionWriter::recordSceneState(const SceneState &state)
{
    if (!m_thread->push({state, 0.0}))
        m_dropped.fetch_add(1, std::memory_order_relaxed);
}

void SessionWriter::onEvent(const SemanticEvent &event)
{
    if (!m_thread->push({event, 0.0}))
        m_dropped.fetch_add(1, std::memory_order_relaxed);
}

void SessionWriter::onDeviceFrame(const DeviceFrame &frame)
{
    if (!m_thread->push({frame, 0.0}))
        m_dropped.fetch_add(1, std::memory_order_relaxed);
}

bool SessionWriter::finish(QString *error)
{
    if (m_finished)
        return true;
    m_finished = true;
    const QString failure = m_thread->stop();
    if (error)
        *error = failure;
    return failure.isEmpty();
}

double SessionWriter::writerCpuSeconds() const
{
    return m_thread->cpuSeconds();
}

} // namespace semhap
