// SPDX-License-Identifier: MIT
#pragma once

#include "pattern.h"

#include <QStringList>

namespace semhap {

/**
 * The built-in patterns (resource files under `:/semhap/patterns/`) and the loader that
 * resolves a name or a path to a pattern.
 */
class PatternLibrary
{
public:
    /** Names of the built-in patterns, sorted. */
    static QStringList builtinNames();
    /** A built-in pattern by name, or null. Parsed once, then shared. */
    static PatternPtr builtin(const QString &name);
    /**
     * A built-in name or a file path (anything with a `/` or ending in `.json` is a path).
     * On failure returns null with `error` filled.
     */
    static PatternPtr load(const QString &nameOrPath, LoadError *error);
};

} // namespace semhap
