// SPDX-License-Identifier: MIT
#pragma once

#include "studiofolders.h"

#include <QList>
#include <QString>

namespace semhap {

/** A pattern the user saved: its name and its file, `<folder>/<name>.json`. */
struct UserPattern
{
    QString name;
    QString path;
};

/**
 * The user's saved patterns in `folder`, by name, so a router node can offer them by name
 * and store their file as the core reads it (RouterGraph::pattern).
 */
QList<UserPattern> userPatterns(const QString &folder = StudioFolders::patterns());

/** The file a pattern named `name` is saved as in `folder`: the name is the file's. */
QString userPatternPath(const QString &folder, const QString &name);

/**
 * Why the user pattern saved as `path` (empty: not saved yet) cannot be named `name` in
 * `folder`: the name does not make a file name, or a built-in or another of the user's
 * patterns has it. Empty when it can; translated, one sentence.
 */
QString userPatternNameProblem(const QString &folder, const QString &name, const QString &path);

} // namespace semhap
