// SPDX-License-Identifier: MIT
#include "sessionreader.h"

#include "routergraph.h"
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
    ++m_rejectedRows;
    if (m_onRowError)
        m_onRowError(QStringLiteral("%1: %2 row %3: %4")
                         .arg(m_path, QLatin1String(table), rowid.toString(), reason));
}

bool SessionReader::readContactFrames(const FrameVisitor &visit, QString *error, double from,
                                      double to)
{
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
    m_frames.restartClock();
    m_frames.setMaxGap(std::numeric_limits<double>::infinity());
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

} // namespace semhap
