// SPDX-License-Identifier: MIT
#pragma once

#include <QString>
#include <QStringList>

namespace semhap {

/**
 * Where gripper adapters (`semhap.gripper/1`, docs/grippers.md) are found by name: the
 * user's folder (`~/.local/share/semhap/grippers`), then the installed ones
 * (`share/semhap/grippers` beside the programs), then the source tree's `resources/grippers`
 * (a build that is not installed). An adapter names its model by a path relative to itself,
 * so a model is used where its adapter lies.
 */
class GripperLibrary
{
public:
    /** The folders searched, the user's first; only those that exist. */
    static QStringList folders();
    /** The adapters' names (file names without `.json`) found in folders(), each once, sorted. */
    static QStringList names();
    /**
     * The adapter file `nameOrPath` means: a path ending in `.json` as given, else the first
     * folder's `NAME.json`; empty when no folder has it.
     */
    static QString find(const QString &nameOrPath);
};

} // namespace semhap
