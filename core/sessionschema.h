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

/** Device frame value columns `v0` … `v15`: one per channel, NULL past the model's count. */
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
