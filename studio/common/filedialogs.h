// SPDX-License-Identifier: MIT
#pragma once

#include <QString>

class QWidget;

namespace semhap {

/** The kinds of file the studio opens and saves; each has its own place to start from. */
enum class FileKind
{
    Session,       ///< recordings: the sessions folder (File → Preferences)
    Pattern,       ///< the designer's patterns: the user pattern folder
    Router,        ///< router files
    Scene,         ///< MuJoCo scenes
    Gripper,       ///< gripper adapters (`semhap.gripper/1`) outside the gripper folders
    HapticFile,    ///< AHAP and `.haptic` files, imported and exported
    PlotExport,    ///< the plots as CSV or PNG
    SessionExport, ///< sessions exported as XDF or MCAP
    Protocol,      ///< study protocols (`semhap.study/1`): first the example studies
    Study,         ///< study databases (STUDY.db)
    TopicMap,      ///< a robot recording's topic maps (`semhap.topics/1`)
};

/**
 * The studio's file dialogs, so each kind of file starts where that kind lives: sessions in
 * the sessions folder, patterns in the user pattern folder, every other kind in the folder
 * last used for it (kept in QSettings), else the example study protocols' folder for a
 * protocol and the user's documents folder for the rest.
 */
class FileDialogs
{
public:
    /** The folder a dialog for `kind` starts in now. */
    static QString startFolder(FileKind kind);
    /**
     * The example study protocols (resources/studies): installed with the programs
     * (`share/semhap/studies`), else in the sources the build came from; empty when neither.
     */
    static QString exampleStudies();
    /** Whether a folder was remembered for `kind`. */
    static bool hasRemembered(FileKind kind);
    /** Remembers the folder of `path` for the next dialog of `kind` (empty: nothing). */
    static void remember(FileKind kind, const QString &path);

    /** Asks for a file of `kind` to open; empty when cancelled. */
    static QString openFile(QWidget *parent, FileKind kind, const QString &caption,
                            const QString &filter);
    /**
     * Asks where to save a file of `kind`, offering `name` (a bare name goes in the start
     * folder; a path is offered as it is); empty when cancelled. `picked`, when given, gets
     * the file type the user chose among `filter`'s.
     */
    static QString saveFile(QWidget *parent, FileKind kind, const QString &caption,
                            const QString &name, const QString &filter, QString *picked = nullptr);
    /** Asks for a folder to write files of `kind` into; empty when cancelled. */
    static QString folder(QWidget *parent, FileKind kind, const QString &caption);
};

} // namespace semhap
