// SPDX-License-Identifier: MIT
#pragma once

#include "sessioninfo.h"

#include <QString>
#include <QStringList>

namespace semhap {

/**
 * The tables of a session database (schema SessionInfo::SchemaVersion), in one place so
 * the writer creates exactly what the reader checks. docs/sessions.md documents them.
 */
namespace SessionSchema {

/**
 * The per-tick streams, which schema 5 keeps in the `blocks` table (docs/sessions.md) and
 * older schemas in a table each, named as the stream.
 */
enum class Stream
{
    ContactFrames,
    DeviceFrames,
    OperatorInput,
    SceneStates
};
constexpr int StreamCount = 4;
/** The stream's name in the `blocks` table: its table's name in schemas 1 to 4. */
const char *streamName(Stream stream);
/** The column of a stream's rows that keys them (gripper, device, hand); -1 for none. */
int keyColumn(Stream stream);

/**
 * The columns of a contact frame row in a block: t, gripper (0 left, 1 right), arrival
 * (NaN when simulated), then per fingertip, left then right: f, n, actor (`names` id, -1
 * for none), fx, fy, fz (NaN when unknown), mu (0 when unknown). Pairs of signal (`names`
 * id) and value follow; a NaN id pads a row with fewer signals than its block has room for.
 */
constexpr int ContactColumns = 17;
/** A device frame row: t, device (`devices` id), then MaxChannels values, NaN past its count. */
constexpr int DeviceColumns = 18;
/** An operator input row: t, hand (0 left, 1 right), x, y, z, qw, qx, qy, qz, grip. */
constexpr int InputColumns = 10;
/** A scene state row: t, the four overlay levels, then the pose's numbers. */
constexpr int SceneColumns = 5;

/** Device frame value columns `v0` … `v15` (schemas 1 to 4): NULL past the model's count. */
QString valueColumn(int channel);
/**
 * The tables a session of schema `version` has: the stream tables in the order the writer
 * fills them, after `metadata` and `devices`.
 */
QStringList tables(int version = SessionInfo::SchemaVersion);
/** The statements that create an empty session. */
QStringList createStatements();

} // namespace SessionSchema

} // namespace semhap
