// SPDX-License-Identifier: MIT
#include "sessionschema.h"

#include "deviceframe.h"

namespace semhap {

static_assert(SessionSchema::DeviceColumns == 2 + MaxChannels);

const char *SessionSchema::streamName(Stream stream)
{
    switch (stream) {
    case Stream::ContactFrames:
        return "contact_frames";
    case Stream::DeviceFrames:
        return "device_frames";
    case Stream::OperatorInput:
        return "operator_input";
    case Stream::SceneStates:
        return "scene_states";
    }
    return "";
}

int SessionSchema::keyColumn(Stream stream)
{
    return stream == Stream::SceneStates ? -1 : 1;
}

QString SessionSchema::valueColumn(int channel)
{
    return QLatin1Char('v') + QString::number(channel);
}

QStringList SessionSchema::tables(int version)
{
    if (version >= 5)
        return {QStringLiteral("metadata"), QStringLiteral("devices"), QStringLiteral("names"),
                QStringLiteral("events"), QStringLiteral("blocks")};
    QStringList names{QStringLiteral("metadata"),       QStringLiteral("devices"),
                      QStringLiteral("contact_frames"), QStringLiteral("events"),
                      QStringLiteral("device_frames"),  QStringLiteral("operator_input")};
    if (version >= 2)
        names.append(QStringLiteral("scene_states"));
    return names;
}

QStringList SessionSchema::createStatements()
{
    return {
        QStringLiteral("CREATE TABLE metadata (key TEXT PRIMARY KEY, value TEXT NOT NULL)"),
        QStringLiteral("CREATE TABLE devices (device INTEGER PRIMARY KEY, name TEXT NOT NULL, "
                       "model TEXT NOT NULL, rate REAL NOT NULL, channels TEXT NOT NULL)"),
        // What a block row's ids name: kind `actor` or `signal`.
        QStringLiteral("CREATE TABLE names (kind TEXT NOT NULL, id INTEGER NOT NULL, "
                       "name TEXT NOT NULL, PRIMARY KEY (kind, id))"),
        QStringLiteral("CREATE TABLE events (t REAL NOT NULL, gripper TEXT NOT NULL, "
                       "node TEXT NOT NULL, detector TEXT NOT NULL, message TEXT NOT NULL, "
                       "category TEXT NOT NULL, phase TEXT NOT NULL, intensity REAL NOT NULL)"),
        // A block: `rows` rows of `width` numbers of one stream, first and last its least and
        // greatest t, packed as SessionBlock says. Recorded order is rowid order.
        QStringLiteral("CREATE TABLE blocks (stream TEXT NOT NULL, first REAL NOT NULL, "
                       "last REAL NOT NULL, rows INTEGER NOT NULL, width INTEGER NOT NULL, "
                       "data BLOB NOT NULL)"),
        QStringLiteral("CREATE INDEX events_t ON events (t)"),
        QStringLiteral("CREATE INDEX blocks_first ON blocks (stream, first)"),
    };
}

} // namespace semhap
