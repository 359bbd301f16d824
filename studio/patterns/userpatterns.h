// SPDX-License-Identifier: MIT
#pragma once

#include <QStringList>

namespace semhap {

/** Where the designer saves the user's patterns: `<app data>/patterns`. */
QString userPatternFolder();

/** The user's saved pattern files, by path, so a router node can name one. */
QStringList userPatternFiles();

} // namespace semhap
