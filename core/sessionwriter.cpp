// SPDX-License-Identifier: MIT
#include "sessionwriter.h"

#include "actortable.h"
#include "nametable.h"
#include "router.h"
#include "sessionblock.h"
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
#include <set>
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
    std::variant<ContactFrame, SemanticEvent, DeviceFrame, HandCommand, SceneState,
                 SessionClock::Sample>
        value;
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

using Stream = SessionSchema::Stream;

/**
 * How long a stream's open block grows before it is sealed: a second of rows packs several
 * times smaller than each commit's few (docs/sessions.md).
 */
constexpr double SealSeconds = 1.0;
/** Values a block holds at most before it is sealed early (a very wide scene). */
constexpr size_t SealValues = SessionBlock::MaxValues / 4;
/** zstd levels: fast for the tail blocks written at each commit, tighter for a sealed one. */
constexpr int TailLevel = 1;
constexpr int SealLevel = 3;

/**
 * One stream's rows on their way into blocks. Each commit writes the rows it brought as a
 * tail block, so a crash loses no more than a commit's worth; once the open block spans
 * SealSeconds, its tail blocks are replaced by one sealed block of all its rows.
 */
struct BlockStream
{
    int width = 0;            ///< of the open block's rows
    std::vector<double> rows; ///< the open block's rows
    size_t written = 0;       ///< values of `rows` already in tail blocks
    std::vector<qint64> tail; ///< the rowids of those tail blocks
};

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
            for (QSqlQuery *query : {&m_eventInsert, &m_blockInsert, &m_blockDelete, &m_nameInsert,
                                     &m_metadataReplace})
                query->clear();
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
        const std::array<std::pair<QSqlQuery *, const char *>, 5> statements{{
            {&m_eventInsert, "INSERT INTO events VALUES (?, ?, ?, ?, ?, ?, ?, ?)"},
            {&m_blockInsert, "INSERT INTO blocks VALUES (?, ?, ?, ?, ?, ?)"},
            {&m_blockDelete, "DELETE FROM blocks WHERE rowid = ?"},
            {&m_nameInsert, "INSERT INTO names VALUES (?, ?, ?)"},
            {&m_metadataReplace, "INSERT OR REPLACE INTO metadata VALUES (?, ?)"},
        }};
        for (const auto &[query, statement] : statements) {
            *query = QSqlQuery(db);
            if (!query->prepare(QLatin1String(statement))) {
                *error = QStringLiteral("cannot prepare: ") + sqlError(query->lastError());
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
            write(db, stopping);
            lock.lock();
            if (stopping)
                return;
        }
    }

    /** Writes the batch taken; `last`: seals every open block, the session ends. */
    void write(QSqlDatabase &db, bool last)
    {
        if (m_back.empty() && m_backActors.isEmpty() && !last)
            return;
        db.transaction();
        for (const QString &name : std::as_const(m_backActors)) {
            insertName("actor", m_actorsNamed++, name);
        }
        m_backActors.clear();
        for (const Record &record : m_back)
            std::visit([this, &record](const auto &value) { insert(value, record.arrival); },
                       record.value);
        for (int s = 0; s < SessionSchema::StreamCount; ++s) {
            BlockStream &stream = m_streams[size_t(s)];
            if (last || spansSeal(stream))
                seal(Stream(s));
            else if (stream.written < stream.rows.size())
                writeTail(Stream(s));
        }
        if (!db.commit() && m_error.isEmpty())
            m_error = m_path + QStringLiteral(": cannot write: ") + sqlError(db.lastError());
        else
            m_owner.m_committed.fetch_add(m_back.size() - m_batchClockSamples,
                                          std::memory_order_relaxed);
        m_batchClockSamples = 0;
        m_back.clear();
    }

    static bool spansSeal(const BlockStream &stream)
    {
        return !stream.rows.empty() &&
               (stream.rows.size() >= SealValues ||
                stream.rows[stream.rows.size() - size_t(stream.width)] - stream.rows[0] >=
                    SealSeconds);
    }

    /**
     * Adds a row to its stream's open block. A contact frame with fewer signals than the
     * block's rows have room for is padded with NaN pairs; any other row of another width,
     * or any row once the block spans SealSeconds, seals the block first.
     */
    void append(Stream s, std::vector<double> &row)
    {
        BlockStream &stream = m_streams[size_t(s)];
        if (s == Stream::ContactFrames && int(row.size()) < stream.width)
            row.resize(size_t(stream.width), qQNaN());
        if (spansSeal(stream) || (!stream.rows.empty() && int(row.size()) != stream.width))
            seal(s);
        stream.width = int(row.size());
        stream.rows.insert(stream.rows.end(), row.begin(), row.end());
    }

    void writeTail(Stream s)
    {
        BlockStream &stream = m_streams[size_t(s)];
        const std::vector<double> rows(stream.rows.begin() + qsizetype(stream.written),
                                       stream.rows.end());
        const qint64 id = insertBlock(s, rows, stream.width, TailLevel);
        if (id >= 0)
            stream.tail.push_back(id);
        stream.written = stream.rows.size();
    }

    /** Replaces the open block's tail blocks by one block of all its rows. */
    void seal(Stream s)
    {
        BlockStream &stream = m_streams[size_t(s)];
        if (stream.rows.empty())
            return;
        for (const qint64 id : stream.tail) {
            m_blockDelete.addBindValue(id);
            check(m_blockDelete.exec(), m_blockDelete);
        }
        insertBlock(s, stream.rows, stream.width, SealLevel);
        stream.rows.clear();
        stream.tail.clear();
        stream.written = 0;
    }

    /** Inserts a block of `rows`; its rowid, or -1 when it could not be written. */
    qint64 insertBlock(Stream s, const std::vector<double> &rows, int width, int level)
    {
        const auto [first, last] = SessionBlock::span(rows, width);
        const QByteArray data =
            SessionBlock::pack(rows, width, SessionSchema::keyColumn(s), level);
        if (data.isEmpty()) {
            if (m_error.isEmpty())
                m_error = m_path + QStringLiteral(": cannot write: zstd cannot pack a block");
            return -1;
        }
        m_blockInsert.addBindValue(QLatin1String(SessionSchema::streamName(s)));
        m_blockInsert.addBindValue(first);
        m_blockInsert.addBindValue(last);
        m_blockInsert.addBindValue(qint64(rows.size() / size_t(width)));
        m_blockInsert.addBindValue(width);
        m_blockInsert.addBindValue(data);
        if (!m_blockInsert.exec()) {
            check(false, m_blockInsert);
            return -1;
        }
        return m_blockInsert.lastInsertId().toLongLong();
    }

    void insertName(const char *kind, int id, const QString &name)
    {
        m_nameInsert.addBindValue(QLatin1String(kind));
        m_nameInsert.addBindValue(id);
        m_nameInsert.addBindValue(name);
        check(m_nameInsert.exec(), m_nameInsert);
    }

    static void appendFingertip(std::vector<double> &row, const Fingertip &tip)
    {
        const double unknown = qQNaN();
        row.insert(row.end(),
                   {tip.f, double(tip.n), double(tip.actor), tip.hasFxyz ? tip.fxyz[0] : unknown,
                    tip.hasFxyz ? tip.fxyz[1] : unknown, tip.hasFxyz ? tip.fxyz[2] : unknown,
                    std::max(0.0, tip.mu)});
    }

    void insert(const ContactFrame &frame, double arrival)
    {
        m_row.assign({frame.t, double(frame.gripper), arrival});
        appendFingertip(m_row, frame.left);
        appendFingertip(m_row, frame.right);
        for (const SignalValue &signal : frame.signalValues) {
            if (m_signalsNamed.insert(signal.id).second)
                insertName("signal", signal.id, signalNames().name(signal.id));
            m_row.insert(m_row.end(), {double(signal.id), signal.value});
        }
        append(Stream::ContactFrames, m_row);
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
        m_row.assign({frame.t, double(frame.device)});
        for (int c = 0; c < MaxChannels; ++c)
            m_row.push_back(c < frame.channelCount ? frame.values[size_t(c)] : qQNaN());
        append(Stream::DeviceFrames, m_row);
    }

    void insert(const HandCommand &input, double)
    {
        m_row.assign({input.t, double(input.hand)});
        m_row.insert(m_row.end(), input.target.pos.begin(), input.target.pos.end());
        m_row.insert(m_row.end(), input.target.quat.begin(), input.target.quat.end());
        m_row.push_back(input.grip);
        append(Stream::OperatorInput, m_row);
    }

    /** The steady clock's samples so far, in the metadata (a few a minute: rewritten whole). */
    void insert(const SessionClock::Sample &sample, double)
    {
        m_clockSamples.push_back(sample);
        ++m_batchClockSamples; // not a stream's value: committed() leaves it out
        m_metadataReplace.addBindValue(QLatin1String(SessionClock::MetadataKey));
        m_metadataReplace.addBindValue(QString::fromUtf8(SessionClock::toJson(m_clockSamples)));
        check(m_metadataReplace.exec(), m_metadataReplace);
    }

    void insert(const SceneState &state, double)
    {
        // A block holds rows of at most SessionBlock::MaxWidth numbers: a wider scene state
        // could be written but never read back, so it is refused here, said once.
        if (state.pose.size() + SessionSchema::SceneColumns > size_t(SessionBlock::MaxWidth)) {
            if (m_error.isEmpty())
                m_error = m_path + QStringLiteral(": cannot write: a scene state of %1 numbers "
                                                  "is more than a block's row holds (%2)")
                                       .arg(state.pose.size())
                                       .arg(SessionBlock::MaxWidth - SessionSchema::SceneColumns);
            return;
        }
        m_row.assign({state.t});
        m_row.insert(m_row.end(), state.overlay.begin(), state.overlay.end());
        m_row.insert(m_row.end(), state.pose.begin(), state.pose.end());
        append(Stream::SceneStates, m_row);
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
    int m_actorsNamed = 0;        ///< actor ids the names table has
    std::set<int> m_signalsNamed; ///< signal ids the names table has
    std::array<QString, 2> m_grippers;
    std::array<BlockStream, SessionSchema::StreamCount> m_streams;
    std::vector<double> m_row; ///< the row being made, kept to spare its allocation
    QSqlQuery m_eventInsert;
    QSqlQuery m_blockInsert;
    QSqlQuery m_blockDelete;
    QSqlQuery m_nameInsert;
    QSqlQuery m_metadataReplace;
    std::vector<SessionClock::Sample> m_clockSamples;
    size_t m_batchClockSamples = 0; ///< of the batch being written
    QString m_error;
};

SessionWriter::SessionWriter(const QString &path, Options options)
    : m_path(path), m_thread(std::make_unique<Thread>(*this, path, options)),
      m_steadyClock(options.steadyClock)
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
    // Pairs in the order of t: a gripper's frame behind the other's (each gripper's t only
    // rises on its own) is not one.
    if (!m_steadyClock || (m_clockSampled && frame.t < m_lastClock.t))
        return;
    m_lastClock = {frame.t, SessionClock::now()};
    if (m_lastClock.steady >= m_nextClockSample) {
        if (m_thread->push({m_lastClock, 0.0}))
            m_nextClockSample = m_lastClock.steady + SessionClock::Interval;
        m_clockSampled = true;
    }
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
    // The last frame's pair, so the samples span the whole recording.
    if (m_clockSampled && m_lastClock.steady > m_nextClockSample - SessionClock::Interval)
        m_thread->push({m_lastClock, 0.0});
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
