// SPDX-License-Identifier: MIT
#pragma once

#include <QString>

namespace semhap {

/**
 * Where the studio keeps its own files, in the user's data folder unless the preferences
 * say otherwise: recordings and the patterns the designer saves. One home for these, read
 * by the file dialogs, the preferences, the designer and the window.
 */
class StudioFolders
{
public:
    /** Where recordings go: the saved folder, else defaultSessions(). */
    static QString sessions();
    /** `<app data>/sessions`: where recordings go when the user has not chosen a folder. */
    static QString defaultSessions();
    /** Saves where recordings go; empty or the default follows the default from now on. */
    static void setSessions(const QString &folder);
    /** Where the designer saves the user's patterns: `<app data>/patterns`. */
    static QString patterns();
};

} // namespace semhap
