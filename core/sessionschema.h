// SPDX-License-Identifier: MIT
#pragma once

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
/** The tables every session has. */
QStringList tables();
/** The statements that create an empty session. */
QStringList createStatements();

} // namespace SessionSchema

} // namespace semhap
