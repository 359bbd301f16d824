// SPDX-License-Identifier: MIT
#pragma once

#include "actortable.h"
#include "contactframe.h"
#include "contactframeparser.h"
#include "deviceframe.h"
#include "handcommand.h"
#include "scenestate.h"
#include "semanticevent.h"
#include "sessioninfo.h"
#include "sessionschema.h"

#include <QString>
#include <QStringList>

#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <vector>

namespace semhap {

class RouterGraph;
struct LoadError;

/**
 * Opens a recorded session (docs/sessions.md) and reads its streams back, whole or within
 * a time window — what replay, export and the studio's scrubber need. Values come back bit
 * for bit as they were recorded (except that -0 reads as 0: SQLite stores integral reals
 * as integers). Opened read-only; a session whose recording was killed opens too. Nothing
 * read back is trusted: a row that breaks its stream's rules (a contact frame is checked
 * exactly as a stream line is) is skipped, counted and reported as
 * `SESSION: TABLE row N: reason`.
 *
 * Not thread-safe: use one reader from one thread (Qt SQL connections are per thread).
 */
class SessionReader
{
public:
    /** Reads a contact frame and its arrival time (NaN when simulated); false stops. */
    using FrameVisitor = std::function<bool(const ContactFrame &frame, double arrival)>;
    using EventVisitor = std::function<bool(const SemanticEvent &event)>;
    using DeviceFrameVisitor = std::function<bool(const DeviceFrame &frame)>;
    using HandCommandVisitor = std::function<bool(const HandCommand &input)>;
    /** Gets each skipped row as `SESSION: TABLE row N: reason`. */
    using RowErrorHandler = std::function<void(const QString &line)>;

    static constexpr double Forever = std::numeric_limits<double>::infinity();

    /**
     * Opens `path` and checks it is a session this semhap reads: an SQLite database with
     * the schema version and every table. Null with `error` as `FILE: reason`.
     */
    static std::unique_ptr<SessionReader> open(const QString &path, QString *error);
    ~SessionReader();

    const QString &path() const { return m_path; }
    const SessionInfo &info() const { return m_info; }
    /** The recorded router, ready to compile (its patterns and models embedded). */
    bool routerGraph(RouterGraph *graph, LoadError *error) const;

    /** Router node ids: SemanticEvent::node indexes this (the recorded router's order). */
    const QStringList &nodeNames() const { return m_nodes; }
    /** Device names: DeviceFrame::device indexes this (the recorded player's order). */
    const QStringList &deviceNames() const { return m_devices; }
    /** The channel names of device `device`, in its model's order. */
    const QStringList &channelNames(int device) const { return m_channels[size_t(device)]; }
    /** The actors the contact frames name; frames refer to them by id. */
    const ActorTable &actors() const { return m_frames.actors(); }

    void setRowErrorHandler(RowErrorHandler handler) { m_onRowError = std::move(handler); }
    /** Rows skipped so far, in every read. */
    qint64 rejectedRows() const { return m_rejectedRows; }

    qint64 contactFrameCount() const { return m_frameCount; }
    qint64 eventCount() const { return m_eventCount; }
    qint64 deviceFrameCount() const { return m_deviceFrameCount; }
    qint64 operatorInputCount() const { return m_inputCount; }
    /** Scene states recorded (0 for a live rig's session and for schema 1). */
    qint64 sceneStateCount() const { return m_sceneStateCount; }
    /** The schema version the session was written with. */
    int schemaVersion() const { return m_schemaVersion; }
    /** The first and last contact frame times (0 when there are none). */
    double startTime() const { return m_start; }
    double endTime() const { return m_end; }

    /**
     * Visits the values with `from <= t < to`, in recorded order. False with `error` when
     * the database cannot be read (a damaged file); a visitor returning false just stops.
     */
    bool readContactFrames(const FrameVisitor &visit, QString *error, double from = -Forever,
                           double to = Forever);
    bool readEvents(const EventVisitor &visit, QString *error, double from = -Forever,
                    double to = Forever);
    bool readDeviceFrames(const DeviceFrameVisitor &visit, QString *error, double from = -Forever,
                          double to = Forever);
    bool readHandCommands(const HandCommandVisitor &visit, QString *error, double from = -Forever,
                          double to = Forever);
    /**
     * Reads the scene state shown at `t`: the latest recorded at or before it (the first
     * one before the first). False when there are none, or with `error` when the database
     * cannot be read.
     */
    bool readSceneState(double t, SceneState *state, QString *error);

private:
    class Database;
    /** A row of a block (schema 5): its numbers, where it is for a reason. */
    struct Row
    {
        const double *values;
        int width;
        qint64 block;
        int row; ///< 1-based, in its block
        QString where() const { return QStringLiteral("block %1 row %2").arg(block).arg(row); }
    };
    using RowVisitor = std::function<bool(const Row &row)>;

    SessionReader() = default;
    bool load(QString *error);
    bool loadBlocks(QString *error);
    /** Visits the rows of `stream` with `from <= t < to`, in recorded order (schema 5). */
    bool readBlocks(SessionSchema::Stream stream, double from, double to, const RowVisitor &visit,
                    QString *error);
    bool contactFrameOf(const Row &row, ContactFrame *frame, QString *reason);
    bool readSceneStateBlock(double t, SceneState *state, QString *error);
    int nodeIndex(const QString &name);
    int deviceIndex(const QString &name);
    /** Skips a row: counts and reports it. */
    void rejectRow(const char *table, const QVariant &rowid, const QString &reason);
    /** Skips `rows` rows at `where` (`row 3`, `block 2 row 7`): counts and reports them. */
    void reject(const char *table, const QString &where, const QString &reason, qint64 rows = 1);

    QString m_path;
    std::unique_ptr<Database> m_db;
    SessionInfo m_info;
    QStringList m_nodes;
    QStringList m_devices;
    std::vector<QStringList> m_channels;
    ContactFrameParser m_frames; ///< the stream rules for contact frame rows; names actors
    RowErrorHandler m_onRowError;
    qint64 m_rejectedRows = 0;
    qint64 m_frameCount = 0;
    qint64 m_eventCount = 0;
    qint64 m_deviceFrameCount = 0;
    qint64 m_inputCount = 0;
    qint64 m_sceneStateCount = 0;
    int m_schemaVersion = 0;
    double m_start = 0.0;
    double m_end = 0.0;
    // Schema 5: what the `names` table names, and the scene state block last unpacked.
    std::map<double, QString> m_actorNames; ///< the session's actor ids to their names
    std::map<double, int> m_signalIds;      ///< the session's signal ids to signalNames()'
    qint64 m_sceneBlock = -1;
    int m_sceneWidth = 0;
    std::vector<double> m_sceneRows;
};

} // namespace semhap
