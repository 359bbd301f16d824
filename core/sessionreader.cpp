// SPDX-License-Identifier: MIT
#include "sessionreader.h"

#include "nametable.h"
#include "routergraph.h"
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
#include <QtEndian>
#include <QUrl>

#include <climits>
#include <cmath>
#include <limits>

namespace semhap {

namespace {

QString sqlError(const QSqlError &error)
{
    return error.databaseText().isEmpty() ? error.text() : error.databaseText();
}

/** The WHERE clause of a time window; infinite bounds are left out. */
QString window(double from, double to)
{
    QStringList terms;
    if (std::isfinite(from))
        terms.append(QStringLiteral("t >= :from"));
    if (std::isfinite(to))
        terms.append(QStringLiteral("t < :to"));
    return terms.isEmpty() ? QString()
                           : QStringLiteral(" WHERE ") + terms.join(QLatin1String(" AND "));
}

double optional(const QVariant &value)
{
    return value.isNull() ? qQNaN() : value.toDouble();
}

/** True when `value` is a whole number from 0 to below `size`: an index a block row holds. */
bool isIndex(double value, qint64 size)
{
    return value >= 0.0 && value < double(size) && value == std::floor(value);
}

} // namespace

/** The read-only connection, named per reader (Qt SQL keeps connections by name). */
class SessionReader::Database
{
public:
    /**
     * `immutable`: for a session nobody can write (a read-only folder): SQLite then reads
     * the file alone, without the shared-memory index a write-ahead log needs beside it.
     */
    Database(const QString &path, bool immutable)
        : m_name(QStringLiteral("semhap.session.reader.%1").arg(quintptr(this)))
    {
        m_db = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), m_name);
        if (immutable) {
            QUrl uri = QUrl::fromLocalFile(QFileInfo(path).absoluteFilePath());
            uri.setScheme(QStringLiteral("file"));
            uri.setQuery(QStringLiteral("immutable=1"));
            m_db.setDatabaseName(uri.toString(QUrl::FullyEncoded));
            m_db.setConnectOptions(QStringLiteral("QSQLITE_OPEN_READONLY;QSQLITE_OPEN_URI"));
        } else {
            m_db.setDatabaseName(path);
            m_db.setConnectOptions(QStringLiteral("QSQLITE_OPEN_READONLY"));
        }
    }
    ~Database()
    {
        m_db.close();
        m_db = QSqlDatabase();
        QSqlDatabase::removeDatabase(m_name);
    }
    QSqlDatabase &db() { return m_db; }

private:
    QString m_name;
    QSqlDatabase m_db;
};

SessionReader::~SessionReader() = default;

std::unique_ptr<SessionReader> SessionReader::open(const QString &path, QString *error)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        *error = path + QStringLiteral(": cannot read: ") + file.errorString();
        return nullptr;
    }
    // SQLite would take an empty or foreign file for a new database: look first.
    if (file.read(16) != QByteArray("SQLite format 3", 16)) {
        *error = path + QStringLiteral(": not a semhap session (not an SQLite database)");
        return nullptr;
    }
    file.close();
    // A write-ahead log needs its index beside the file, which a folder one may not write
    // cannot hold: such a session is read as it stands.
    const bool immutable = !QFileInfo(QFileInfo(path).absolutePath()).isWritable();
    std::unique_ptr<SessionReader> reader(new SessionReader);
    reader->m_path = path;
    reader->m_db = std::make_unique<Database>(path, immutable);
    QString reason;
    if (!reader->load(&reason)) {
        *error = path + QStringLiteral(": ") + reason;
        return nullptr;
    }
    return reader;
}

bool SessionReader::load(QString *error)
{
    QSqlDatabase &db = m_db->db();
    if (!db.isValid()) {
        *error = QStringLiteral("the Qt SQLite driver (QSQLITE) is not available");
        return false;
    }
    if (!db.open()) {
        *error = QStringLiteral("cannot open: ") + sqlError(db.lastError());
        return false;
    }
    const auto damaged = [error](const QSqlQuery &query) {
        *error = QStringLiteral("damaged session: ") + sqlError(query.lastError());
        return false;
    };
    QSqlQuery query(db);
    query.setForwardOnly(true);
    if (!query.exec(QStringLiteral("SELECT name FROM sqlite_master WHERE type = 'table'")))
        return damaged(query);
    QStringList tables;
    while (query.next())
        tables.append(query.value(0).toString());
    if (query.lastError().isValid())
        return damaged(query);
    if (!tables.contains(QLatin1String("metadata"))) {
        *error = QStringLiteral("not a semhap session (no metadata table)");
        return false;
    }
    QMap<QString, QString> rows;
    if (!query.exec(QStringLiteral("SELECT key, value FROM metadata")))
        return damaged(query);
    while (query.next())
        rows.insert(query.value(0).toString(), query.value(1).toString());
    if (query.lastError().isValid())
        return damaged(query);
    const QString version = rows.value(QStringLiteral("schema_version"));
    if (version.isEmpty()) {
        *error = QStringLiteral("not a semhap session (no schema_version in its metadata)");
        return false;
    }
    bool numeric = false;
    m_schemaVersion = version.toInt(&numeric);
    if (!numeric || m_schemaVersion < SessionInfo::OldestSchemaVersion ||
        m_schemaVersion > SessionInfo::SchemaVersion) {
        *error = QStringLiteral("session schema version %1 is not supported (this semhap "
                                "reads %2 to %3)")
                     .arg(version)
                     .arg(SessionInfo::OldestSchemaVersion)
                     .arg(SessionInfo::SchemaVersion);
        return false;
    }
    for (const QString &table : SessionSchema::tables(m_schemaVersion)) {
        if (!tables.contains(table)) {
            *error = QStringLiteral("damaged session: table '%1' is missing").arg(table);
            return false;
        }
    }
    QString malformed;
    if (!SessionInfo::fromMetadata(rows, &m_info, &malformed)) {
        *error = QStringLiteral("damaged session: metadata ") + malformed;
        return false;
    }
    for (const QJsonValue &node : m_info.router.value(QLatin1String("nodes")).toArray())
        m_nodes.append(node.toObject().value(QLatin1String("id")).toString());

    if (!query.exec(QStringLiteral("SELECT name, channels FROM devices ORDER BY device")))
        return damaged(query);
    while (query.next()) {
        m_devices.append(query.value(0).toString());
        QStringList channels;
        const QJsonArray list =
            QJsonDocument::fromJson(query.value(1).toString().toUtf8()).array();
        for (const QJsonValue &channel : list)
            channels.append(channel.toString());
        m_channels.push_back(channels.mid(0, MaxChannels));
    }
    if (query.lastError().isValid())
        return damaged(query);

    if (m_schemaVersion >= 5)
        return loadBlocks(error);
    // Counting walks every table's pages: a truncated file shows here, not halfway through.
    const std::array<std::pair<const char *, qint64 *>, 4> counts{{
        {"contact_frames", &m_frameCount},
        {"events", &m_eventCount},
        {"device_frames", &m_deviceFrameCount},
        {"operator_input", &m_inputCount},
    }};
    for (const auto &[table, count] : counts) {
        if (!query.exec(QStringLiteral("SELECT count(*) FROM ") + QLatin1String(table)) ||
            !query.next())
            return damaged(query);
        *count = query.value(0).toLongLong();
    }
    if (m_schemaVersion >= 2) {
        if (!query.exec(QStringLiteral("SELECT count(*) FROM scene_states")) || !query.next())
            return damaged(query);
        m_sceneStateCount = query.value(0).toLongLong();
    }
    if (!query.exec(QStringLiteral("SELECT min(t), max(t) FROM contact_frames")) || !query.next())
        return damaged(query);
    m_start = query.value(0).toDouble();
    m_end = query.value(1).toDouble();
    return true;
}

bool SessionReader::loadBlocks(QString *error)
{
    QSqlQuery query(m_db->db());
    query.setForwardOnly(true);
    const auto damaged = [&] {
        *error = QStringLiteral("damaged session: ") + sqlError(query.lastError());
        return false;
    };
    // A name that could not have been written is left out: rows naming it are rejected.
    if (!query.exec(QStringLiteral("SELECT kind, id, name FROM names")))
        return damaged();
    QString reason;
    while (query.next()) {
        const QString kind = query.value(0).toString();
        const qint64 id = query.value(1).toLongLong();
        const QString name = query.value(2).toString();
        if (kind == QLatin1String("actor") && !name.isEmpty()) {
            m_actorNames[double(id)] = name;
        } else if (kind == QLatin1String("signal") &&
                   ContactFrameParser::checkSignalName(name, &reason)) {
            const int signal = signalNames().intern(name);
            if (signal >= 0)
                m_signalIds[double(id)] = signal;
        }
    }
    if (query.lastError().isValid())
        return damaged();
    // Summing walks the block table's pages: a truncated file shows here.
    if (!query.exec(QStringLiteral("SELECT stream, sum(rows), min(first), max(last) FROM "
                                   "blocks GROUP BY stream")))
        return damaged();
    using S = SessionSchema::Stream;
    while (query.next()) {
        const QString stream = query.value(0).toString();
        const qint64 rows = query.value(1).toLongLong();
        if (stream == QLatin1String(SessionSchema::streamName(S::ContactFrames))) {
            m_frameCount = rows;
            m_start = query.value(2).toDouble();
            m_end = query.value(3).toDouble();
        } else if (stream == QLatin1String(SessionSchema::streamName(S::DeviceFrames))) {
            m_deviceFrameCount = rows;
        } else if (stream == QLatin1String(SessionSchema::streamName(S::OperatorInput))) {
            m_inputCount = rows;
        } else if (stream == QLatin1String(SessionSchema::streamName(S::SceneStates))) {
            m_sceneStateCount = rows;
        }
    }
    if (query.lastError().isValid())
        return damaged();
    if (!query.exec(QStringLiteral("SELECT count(*) FROM events")) || !query.next())
        return damaged();
    m_eventCount = query.value(0).toLongLong();
    return true;
}

bool SessionReader::routerGraph(RouterGraph *graph, LoadError *error) const
{
    if (!RouterGraph::fromJson(m_info.router, m_path, graph, error))
        return false;
    // A session's router is self-contained as recorded: it may name no file to read.
    graph->filesAllowed = false;
    return true;
}

int SessionReader::nodeIndex(const QString &name)
{
    int index = int(m_nodes.indexOf(name));
    if (index < 0) {
        m_nodes.append(name);
        index = int(m_nodes.size()) - 1;
    }
    return index;
}

int SessionReader::deviceIndex(const QString &name)
{
    int index = int(m_devices.indexOf(name));
    if (index < 0) {
        m_devices.append(name);
        m_channels.emplace_back();
        index = int(m_devices.size()) - 1;
    }
    return index;
}

namespace {

/** Runs a windowed SELECT; false with the damage as `error`. */
bool select(QSqlDatabase &db, QSqlQuery *query, const QString &columns, const char *table,
            double from, double to, QString *error)
{
    *query = QSqlQuery(db);
    query->setForwardOnly(true);
    query->prepare(QStringLiteral("SELECT ") + columns + QStringLiteral(" FROM ") +
                   QLatin1String(table) + window(from, to) + QStringLiteral(" ORDER BY rowid"));
    if (std::isfinite(from))
        query->bindValue(QStringLiteral(":from"), from);
    if (std::isfinite(to))
        query->bindValue(QStringLiteral(":to"), to);
    if (query->exec())
        return true;
    *error = QStringLiteral("damaged session: ") + sqlError(query->lastError());
    return false;
}

/** After the rows: false with the damage as `error` when reading stopped on one. */
bool finished(const QSqlQuery &query, const QString &path, QString *error)
{
    if (!query.lastError().isValid())
        return true;
    *error = path + QStringLiteral(": damaged session: ") + sqlError(query.lastError());
    return false;
}

} // namespace

namespace {

/** A value as a stream line would carry it: SQLite's integers, reals, text and NULL. */
QJsonValue jsonOf(const QVariant &value)
{
    return value.isNull() ? QJsonValue(QJsonValue::Null) : QJsonValue::fromVariant(value);
}

/** A REAL column's value: false when it holds text, a blob or NULL, or is not finite. */
bool finiteReal(const QVariant &value, double *out)
{
    const int type = value.typeId();
    if (type != QMetaType::Double && type != QMetaType::LongLong && type != QMetaType::Int)
        return false;
    *out = value.toDouble();
    return std::isfinite(*out);
}

/** How a column's value reads in a reason: text quoted, NULL as null. */
QString describe(const QVariant &value)
{
    if (value.isNull())
        return QStringLiteral("null");
    if (value.typeId() == QMetaType::QString)
        return QLatin1Char('"') + value.toString().left(40) + QLatin1Char('"');
    if (value.typeId() == QMetaType::QByteArray)
        return QStringLiteral("a blob");
    return value.toString();
}

} // namespace

void SessionReader::rejectRow(const char *table, const QVariant &rowid, const QString &reason)
{
    reject(table, QStringLiteral("row ") + rowid.toString(), reason);
}

void SessionReader::reject(const char *table, const QString &where, const QString &reason,
                           qint64 rows)
{
    m_rejectedRows += rows;
    if (m_onRowError)
        m_onRowError(
            QStringLiteral("%1: %2 %3: %4").arg(m_path, QLatin1String(table), where, reason));
}

bool SessionReader::readBlocks(SessionSchema::Stream stream, double from, double to,
                               const RowVisitor &visit, QString *error)
{
    const char *name = SessionSchema::streamName(stream);
    QSqlQuery query(m_db->db());
    query.setForwardOnly(true);
    // A block may hold rows of the window when it ends at or after its start and begins
    // before its end; the rows themselves are sifted below.
    QString sql = QStringLiteral("SELECT rowid, rows, width, data FROM blocks WHERE stream = "
                                 ":stream");
    if (std::isfinite(from))
        sql += QStringLiteral(" AND last >= :from");
    if (std::isfinite(to))
        sql += QStringLiteral(" AND first < :to");
    query.prepare(sql + QStringLiteral(" ORDER BY rowid"));
    query.bindValue(QStringLiteral(":stream"), QLatin1String(name));
    if (std::isfinite(from))
        query.bindValue(QStringLiteral(":from"), from);
    if (std::isfinite(to))
        query.bindValue(QStringLiteral(":to"), to);
    if (!query.exec()) {
        *error = m_path + QStringLiteral(": damaged session: ") + sqlError(query.lastError());
        return false;
    }
    std::vector<double> rows;
    QString reason;
    while (query.next()) {
        const qint64 block = query.value(0).toLongLong();
        const int count = query.value(1).toInt();
        const int width = query.value(2).toInt();
        if (!SessionBlock::unpack(query.value(3).toByteArray(), count, width,
                                  SessionSchema::keyColumn(stream), &rows, &reason)) {
            reject(name, QStringLiteral("block %1").arg(block), reason, std::max(count, 1));
            continue;
        }
        for (int r = 0; r < count; ++r) {
            const double *row = rows.data() + size_t(r) * size_t(width);
            if (!(row[0] >= from && row[0] < to))
                continue;
            const Row at{row, width, block, r + 1};
            if (!visit(at))
                return true;
        }
    }
    return finished(query, m_path, error);
}

bool SessionReader::readContactFrames(const FrameVisitor &visit, QString *error, double from,
                                      double to)
{
    m_frames.restartClock();
    m_frames.setMaxGap(std::numeric_limits<double>::infinity());
    if (m_schemaVersion >= 5) {
        ContactFrame frame;
        QString reason;
        return readBlocks(
            SessionSchema::Stream::ContactFrames, from, to,
            [&](const Row &row) {
                if (contactFrameOf(row, &frame, &reason))
                    return visit(frame, row.values[2]);
                reject("contact_frames", row.where(), reason);
                return true;
            },
            error);
    }
    QSqlQuery query;
    QString reason;
    if (!select(m_db->db(), &query, QStringLiteral("rowid, *"), "contact_frames", from, to,
                &reason)) {
        *error = m_path + QStringLiteral(": ") + reason;
        return false;
    }
    // Each row is checked as the stream line it was: one set of rules for frames, wherever
    // they come from. A recorded pause is real, so no gap is too long; time must still move
    // on per gripper.
    const bool hasMu = m_schemaVersion >= 3;      // friction coefficients came with schema 3
    const bool hasSignals = m_schemaVersion >= 4; // and signals with 4
    const auto fingertip = [&query, hasMu](int column, int muColumn) {
        QJsonObject tip{{QStringLiteral("f"), jsonOf(query.value(column))},
                        {QStringLiteral("n"), jsonOf(query.value(column + 1))},
                        {QStringLiteral("actor"), jsonOf(query.value(column + 2))}};
        if (!query.value(column + 3).isNull() || !query.value(column + 4).isNull() ||
            !query.value(column + 5).isNull())
            tip.insert(QStringLiteral("fxyz"),
                       QJsonArray{jsonOf(query.value(column + 3)), jsonOf(query.value(column + 4)),
                                  jsonOf(query.value(column + 5))});
        if (hasMu)
            tip.insert(QStringLiteral("mu"), jsonOf(query.value(muColumn)));
        return tip;
    };
    ContactFrame frame;
    while (query.next()) {
        QJsonObject line{{QStringLiteral("t"), jsonOf(query.value(1))},
                         {QStringLiteral("gripper"), jsonOf(query.value(2))},
                         {QStringLiteral("left"), fingertip(3, 16)},
                         {QStringLiteral("right"), fingertip(9, 17)}};
        if (hasSignals && !query.value(18).isNull()) {
            // Stored as the stream's JSON object; anything else is rejected by the parser.
            const QJsonDocument document =
                QJsonDocument::fromJson(query.value(18).toString().toUtf8());
            line.insert(QStringLiteral("signals"), document.isObject()
                                                       ? QJsonValue(document.object())
                                                       : jsonOf(query.value(18)));
        }
        if (!m_frames.parse(line, &frame, &reason)) {
            rejectRow("contact_frames", query.value(0), reason);
            continue;
        }
        if (!visit(frame, optional(query.value(15))))
            return true;
    }
    return finished(query, m_path, error);
}

bool SessionReader::readEvents(const EventVisitor &visit, QString *error, double from, double to)
{
    QSqlQuery query;
    QString reason;
    if (!select(m_db->db(), &query, QStringLiteral("rowid, *"), "events", from, to, &reason)) {
        *error = m_path + QStringLiteral(": ") + reason;
        return false;
    }
    SemanticEvent event;
    while (query.next()) {
        const auto bad = [&](const char *column, int index) {
            rejectRow("events", query.value(0),
                      QStringLiteral("\"%1\" is not valid, got %2")
                          .arg(QLatin1String(column), describe(query.value(index))));
        };
        const QString node = query.value(3).toString();
        if (!finiteReal(query.value(1), &event.t)) {
            bad("t", 1);
        } else if (!gripperFromName(query.value(2).toString(), &event.gripper)) {
            bad("gripper", 2);
        } else if (node.isEmpty()) {
            bad("node", 3);
        } else if (!detectorKindFromName(query.value(4).toString(), &event.detector)) {
            bad("detector", 4);
        } else if (!messageFromName(query.value(5).toString(), &event.message)) {
            bad("message", 5);
        } else if (!categoryFromName(query.value(6).toString(), &event.category)) {
            bad("category", 6);
        } else if (!eventPhaseFromName(query.value(7).toString(), &event.phase)) {
            bad("phase", 7);
        } else if (!finiteReal(query.value(8), &event.intensity) || event.intensity < 0.0 ||
                   event.intensity > 1.0) {
            bad("intensity", 8);
        } else {
            event.node = nodeIndex(node);
            if (!visit(event))
                return true;
        }
    }
    return finished(query, m_path, error);
}

bool SessionReader::readDeviceFrames(const DeviceFrameVisitor &visit, QString *error, double from,
                                     double to)
{
    if (m_schemaVersion >= 5) {
        DeviceFrame frame;
        return readBlocks(
            SessionSchema::Stream::DeviceFrames, from, to,
            [&](const Row &row) {
                // A device's values run up to the first NaN: its model's channel count.
                frame.t = row.values[0];
                frame.values.fill(0.0);
                frame.channelCount = 0;
                bool valid = row.width == SessionSchema::DeviceColumns &&
                             isIndex(row.values[1], m_devices.size());
                for (int c = 0; valid && c < MaxChannels && !std::isnan(row.values[2 + c]); ++c) {
                    frame.values[size_t(c)] = row.values[2 + c];
                    frame.channelCount = c + 1;
                    valid = std::isfinite(frame.values[size_t(c)]);
                }
                if (!valid) {
                    reject("device_frames", row.where(),
                           QStringLiteral("\"t\", \"device\" and the values must be finite "
                                          "numbers and a device of the session"));
                    return true;
                }
                frame.device = int(row.values[1]);
                return visit(frame);
            },
            error);
    }
    QSqlQuery query;
    QString reason;
    if (!select(m_db->db(), &query, QStringLiteral("rowid, *"), "device_frames", from, to,
                &reason)) {
        *error = m_path + QStringLiteral(": ") + reason;
        return false;
    }
    DeviceFrame frame;
    while (query.next()) {
        const QString device = query.value(2).toString();
        bool valid = finiteReal(query.value(1), &frame.t) && !device.isEmpty();
        frame.values.fill(0.0);
        frame.channelCount = 0;
        for (int c = 0; valid && c < MaxChannels && !query.value(3 + c).isNull(); ++c) {
            valid = finiteReal(query.value(3 + c), &frame.values[size_t(c)]);
            frame.channelCount = c + 1;
        }
        if (!valid) {
            rejectRow("device_frames", query.value(0),
                      QStringLiteral("\"t\", \"device\" and the values must be finite numbers "
                                     "and a name"));
            continue;
        }
        frame.device = deviceIndex(device);
        if (!visit(frame))
            return true;
    }
    return finished(query, m_path, error);
}

bool SessionReader::readHandCommands(const HandCommandVisitor &visit, QString *error, double from,
                                     double to)
{
    if (m_schemaVersion >= 5) {
        HandCommand input;
        return readBlocks(
            SessionSchema::Stream::OperatorInput, from, to,
            [&](const Row &row) {
                bool valid = row.width == SessionSchema::InputColumns && isIndex(row.values[1], 2);
                for (int c = 2; valid && c < SessionSchema::InputColumns; ++c)
                    valid = std::isfinite(row.values[c]);
                if (!valid) {
                    reject("operator_input", row.where(),
                           QStringLiteral("\"t\", the pose and the grip must be finite numbers "
                                          "and \"hand\" left or right"));
                    return true;
                }
                input.t = row.values[0];
                input.hand = Gripper(int(row.values[1]));
                std::copy(row.values + 2, row.values + 5, input.target.pos.begin());
                std::copy(row.values + 5, row.values + 9, input.target.quat.begin());
                input.grip = row.values[9];
                return visit(input);
            },
            error);
    }
    QSqlQuery query;
    QString reason;
    if (!select(m_db->db(), &query, QStringLiteral("rowid, *"), "operator_input", from, to,
                &reason)) {
        *error = m_path + QStringLiteral(": ") + reason;
        return false;
    }
    HandCommand input;
    while (query.next()) {
        bool valid = finiteReal(query.value(1), &input.t) &&
                     gripperFromName(query.value(2).toString(), &input.hand);
        for (int i = 0; valid && i < 3; ++i)
            valid = finiteReal(query.value(3 + i), &input.target.pos[size_t(i)]);
        for (int i = 0; valid && i < 4; ++i)
            valid = finiteReal(query.value(6 + i), &input.target.quat[size_t(i)]);
        valid = valid && finiteReal(query.value(10), &input.grip);
        if (!valid) {
            rejectRow("operator_input", query.value(0),
                      QStringLiteral("\"t\", the pose and the grip must be finite numbers and "
                                     "\"hand\" left or right"));
            continue;
        }
        if (!visit(input))
            return true;
    }
    return finished(query, m_path, error);
}

bool SessionReader::readSceneState(double t, SceneState *state, QString *error)
{
    if (m_sceneStateCount == 0)
        return false;
    if (m_schemaVersion >= 5)
        return readSceneStateBlock(t, state, error);
    // The latest state at or before t; before the first one, the first.
    QSqlQuery query(m_db->db());
    query.setForwardOnly(true);
    query.prepare(QStringLiteral(
        "SELECT * FROM (SELECT * FROM scene_states WHERE t <= :t ORDER BY t DESC LIMIT 1) "
        "UNION ALL SELECT * FROM (SELECT * FROM scene_states ORDER BY t LIMIT 1)"));
    query.bindValue(QStringLiteral(":t"), t);
    if (!query.exec() || !query.next()) {
        if (query.lastError().isValid())
            *error = m_path + QStringLiteral(": damaged session: ") + sqlError(query.lastError());
        return false;
    }
    state->t = query.value(0).toDouble();
    const QByteArray pose = query.value(1).toByteArray();
    state->pose.resize(size_t(pose.size()) / sizeof(double));
    qFromLittleEndian<double>(pose.constData(), qsizetype(state->pose.size()), state->pose.data());
    for (int i = 0; i < 4; ++i)
        state->overlay[size_t(i)] = query.value(2 + i).toDouble();
    return true;
}

bool SessionReader::readSceneStateBlock(double t, SceneState *state, QString *error)
{
    // The block that holds the latest state at or before t (or the first block), by the
    // index on (stream, first); the last one read is kept, so scrubbing within a second
    // unpacks nothing.
    QSqlQuery query(m_db->db());
    query.setForwardOnly(true);
    query.prepare(QStringLiteral(
        "SELECT * FROM (SELECT rowid FROM blocks WHERE stream = 'scene_states' AND first <= :t "
        "ORDER BY first DESC LIMIT 1) UNION ALL SELECT * FROM (SELECT rowid FROM blocks WHERE "
        "stream = 'scene_states' ORDER BY first LIMIT 1)"));
    query.bindValue(QStringLiteral(":t"), t);
    const auto damaged = [&] {
        if (query.lastError().isValid())
            *error = m_path + QStringLiteral(": damaged session: ") + sqlError(query.lastError());
        return false;
    };
    if (!query.exec() || !query.next())
        return damaged();
    const qint64 block = query.value(0).toLongLong();
    if (block != m_sceneBlock) {
        query.prepare(QStringLiteral("SELECT rows, width, data FROM blocks WHERE rowid = :block"));
        query.bindValue(QStringLiteral(":block"), block);
        if (!query.exec() || !query.next())
            return damaged();
        QString reason;
        m_sceneBlock = -1;
        m_sceneWidth = query.value(1).toInt();
        if (!SessionBlock::unpack(query.value(2).toByteArray(), query.value(0).toInt(),
                                  m_sceneWidth, -1, &m_sceneRows, &reason) ||
            m_sceneWidth < SessionSchema::SceneColumns) {
            *error =
                QStringLiteral("%1: damaged session: scene_states block %2: %3")
                    .arg(m_path)
                    .arg(block)
                    .arg(reason.isEmpty() ? QStringLiteral("its rows are too short") : reason);
            return false;
        }
        m_sceneBlock = block;
    }
    const size_t width = size_t(m_sceneWidth);
    size_t at = 0;
    for (size_t r = 0; r * width < m_sceneRows.size(); ++r) {
        if (m_sceneRows[r * width] <= t)
            at = r;
    }
    const double *row = m_sceneRows.data() + at * width;
    state->t = row[0];
    std::copy(row + 1, row + SessionSchema::SceneColumns, state->overlay.begin());
    state->pose.assign(row + SessionSchema::SceneColumns, row + width);
    return true;
}

bool SessionReader::contactFrameOf(const Row &row, ContactFrame *frame, QString *reason)
{
    const int signalCount = (row.width - SessionSchema::ContactColumns) / 2;
    if (row.width < SessionSchema::ContactColumns ||
        (row.width - SessionSchema::ContactColumns) % 2 != 0 ||
        signalCount > FrameSignals::Capacity) {
        *reason = QStringLiteral("a contact frame row of %1 numbers is not one").arg(row.width);
        return false;
    }
    const double *v = row.values;
    if (!isIndex(v[1], 2)) {
        *reason = QStringLiteral("\"gripper\" must be 0 (left) or 1 (right), got %1")
                      .arg(formatNumber(v[1]));
        return false;
    }
    *frame = ContactFrame();
    frame->t = v[0];
    frame->gripper = Gripper(int(v[1]));
    std::array<QString, 2> actors;
    for (int side = 0; side < 2; ++side) {
        Fingertip &tip = side == 0 ? frame->left : frame->right;
        const double *at = v + 3 + 7 * side;
        const QLatin1String name = side == 0 ? QLatin1String("left") : QLatin1String("right");
        if (!isIndex(at[1], INT_MAX)) {
            *reason = QStringLiteral("\"%1.n\" must be a non-negative integer, got %2")
                          .arg(name, formatNumber(at[1]));
            return false;
        }
        const auto actor = m_actorNames.find(at[2]);
        if (at[2] != -1.0 && actor == m_actorNames.end()) {
            *reason = QStringLiteral("\"%1.actor\" names no actor of the session").arg(name);
            return false;
        }
        tip.f = at[0];
        tip.n = int(at[1]);
        tip.actor = at[2] == -1.0 ? -1 : 0; // the parser gives it its id by name
        if (tip.actor >= 0)
            actors[size_t(side)] = actor->second;
        tip.hasFxyz = !(std::isnan(at[3]) && std::isnan(at[4]) && std::isnan(at[5]));
        std::copy(at + 3, at + 6, tip.fxyz.begin());
        tip.mu = at[6];
    }
    for (int i = 0; i < signalCount; ++i) {
        const double id = v[SessionSchema::ContactColumns + 2 * i];
        if (std::isnan(id)) // room for a signal this frame did not have
            continue;
        const auto named = m_signalIds.find(id);
        if (named == m_signalIds.end()) {
            *reason =
                QStringLiteral("signal %1 is not named by the session").arg(formatNumber(id));
            return false;
        }
        frame->signalValues.set(named->second, v[SessionSchema::ContactColumns + 2 * i + 1]);
    }
    return m_frames.accept(frame, actors[0], actors[1], reason);
}

} // namespace semhap
