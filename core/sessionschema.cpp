// SPDX-License-Identifier: MIT
#include "sessionschema.h"

#include "deviceframe.h"

namespace semhap {

QString SessionSchema::valueColumn(int channel)
{
    return QLatin1Char('v') + QString::number(channel);
}

QStringList SessionSchema::tables(int version)
{
    QStringList names{QStringLiteral("metadata"),       QStringLiteral("devices"),
                      QStringLiteral("contact_frames"), QStringLiteral("events"),
                      QStringLiteral("device_frames"),  QStringLiteral("operator_input")};
    if (version >= 2)
        names.append(QStringLiteral("scene_states"));
    return names;
}

QStringList SessionSchema::createStatements()
{
    QString values;
    for (int c = 0; c < MaxChannels; ++c)
        values += QStringLiteral(", %1 REAL").arg(valueColumn(c));
    const QString fingertip =
        QStringLiteral("%1_f REAL NOT NULL, %1_n INTEGER NOT NULL, %1_actor TEXT, "
                       "%1_fx REAL, %1_fy REAL, %1_fz REAL");
    return {
        QStringLiteral("CREATE TABLE metadata (key TEXT PRIMARY KEY, value TEXT NOT NULL)"),
        QStringLiteral("CREATE TABLE devices (device INTEGER PRIMARY KEY, name TEXT NOT NULL, "
                       "model TEXT NOT NULL, rate REAL NOT NULL, channels TEXT NOT NULL)"),
        QStringLiteral("CREATE TABLE contact_frames (t REAL NOT NULL, gripper TEXT NOT NULL, ") +
            fingertip.arg(QLatin1String("left")) + QStringLiteral(", ") +
            fingertip.arg(QLatin1String("right")) +
            QStringLiteral(", arrival REAL, left_mu REAL, right_mu REAL, signals TEXT)"),
        QStringLiteral("CREATE TABLE events (t REAL NOT NULL, gripper TEXT NOT NULL, "
                       "node TEXT NOT NULL, detector TEXT NOT NULL, message TEXT NOT NULL, "
                       "category TEXT NOT NULL, phase TEXT NOT NULL, intensity REAL NOT NULL)"),
        QStringLiteral("CREATE TABLE device_frames (t REAL NOT NULL, device TEXT NOT NULL") +
            values + QLatin1Char(')'),
        QStringLiteral("CREATE TABLE operator_input (t REAL NOT NULL, hand TEXT NOT NULL, "
                       "x REAL NOT NULL, y REAL NOT NULL, z REAL NOT NULL, qw REAL NOT NULL, "
                       "qx REAL NOT NULL, qy REAL NOT NULL, qz REAL NOT NULL, "
                       "grip REAL NOT NULL)"),
        // The pose is float64 little-endian: World::sceneState()'s numbers (docs/sessions.md).
        QStringLiteral("CREATE TABLE scene_states (t REAL NOT NULL, pose BLOB NOT NULL, "
                       "left_confirm REAL NOT NULL, left_warn REAL NOT NULL, "
                       "right_confirm REAL NOT NULL, right_warn REAL NOT NULL)"),
        QStringLiteral("CREATE INDEX contact_frames_t ON contact_frames (t)"),
        QStringLiteral("CREATE INDEX events_t ON events (t)"),
        QStringLiteral("CREATE INDEX device_frames_t ON device_frames (t)"),
        QStringLiteral("CREATE INDEX operator_input_t ON operator_input (t)"),
        QStringLiteral("CREATE INDEX scene_states_t ON scene_states (t)"),
    };
}

} // namespace semhap
