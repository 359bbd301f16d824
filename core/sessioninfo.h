// SPDX-License-Identifier: MIT
#pragma once

#include "routercontext.h"

#include <QDateTime>
#include <QJsonObject>
#include <QMap>
#include <QString>
#include <QStringList>

namespace semhap {

/**
 * What a session is, beside its streams: where the frames came from, the router that ran
 * them (self-contained, so the session replays on another machine), the devices it drove,
 * who operated and with which seed. Stored as the session's `metadata` table, one text
 * value per key (docs/sessions.md lists the keys).
 */
struct SessionInfo
{
    static constexpr const char *Format = "semhap.session/1";
    /**
     * The schema this semhap writes: 2 added the scene states, 3 friction, 4 signals, and 5
     * keeps the per-tick streams in compressed blocks.
     */
    static constexpr int SchemaVersion = 5;
    /** The oldest schema this semhap reads; a session outside the two is refused. */
    static constexpr int OldestSchemaVersion = 1;

    QString source;              ///< what produced the frames: `run`, `listen`, `studio`
    QString scene;               ///< scene name or file, when simulated
    QJsonObject router;          ///< RouterGraph JSON with its patterns and models embedded
    QString routerSource;        ///< the preset name or file the router was loaded from
    QStringList overrides;       ///< `NODE.PARAM=VALUE` applied to it
    RouterContext routerContext; ///< what the router was compiled for (`reaction_time`, …)
    QJsonObject bindings;        ///< device name → transport URI
    QString operatorName;
    QString seed;
    QString semhapVersion;
    QDateTime started; ///< UTC
    QDateTime ended;   ///< UTC; invalid when the recording did not close (a crash)
    QString notes;
    QMap<QString, QString> extra; ///< any other key, kept as is (run options, …)

    /** Adds `NAME=URI` bindings as given on a command line (`--bind`). */
    void addBindings(const QStringList &bindings);

    /** The metadata table's rows. */
    QMap<QString, QString> toMetadata() const;
    /**
     * The metadata as one JSON object (`semhap export`'s metadata.json): the keys whose
     * value is JSON (isJsonKey) nested, every other value a string as stored.
     */
    QJsonObject toJson() const;
    /**
     * Whether metadata `key` holds JSON: `router`, `overrides`, `bindings`, `open_at_start`,
     * `steady_clock`.
     */
    static bool isJsonKey(const QString &key);
    /**
     * Reads the rows back; unknown keys go to `extra`. False with `error` (`KEY: reason`)
     * when a value this semhap needs to replay the session is malformed.
     */
    static bool fromMetadata(const QMap<QString, QString> &rows, SessionInfo *info,
                             QString *error);

    /** The metadata key listing the messages a recording begins with (a JSON array). */
    static constexpr const char *OpenAtStartKey = "open_at_start";

    /** The longest reaction time a session or an option may state (s). */
    static constexpr double MaxReactionTime = 10.0;
};

} // namespace semhap
