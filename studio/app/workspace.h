// SPDX-License-Identifier: MIT
#pragma once

#include "engine.h"

#include <QJsonObject>
#include <QObject>
#include <QString>
#include <QTimer>

#include <memory>

namespace semhap {

class PatternDocument;
class RouterDocument;
class StudyDocument;
struct StudioOptions;

/**
 * What the user works on, apart from any window: the engine (the run with its scene and
 * running router, the devices with their addresses, bindings and armed state, the
 * recording), the router editor's document and the pattern designer's, the study open
 * (with its running trial), and the next recording's name and notes. The studio rebuilds its
 * window around the same workspace (another interface language), so none of it is lost.
 *
 * It also outlives the studio: autosaveTo() keeps it in a `semhap.workspace/1` file, and
 * restore() opens it again at the next start — after a quit or a crash alike. The device
 * addresses the user added are kept in the settings.
 */
class Workspace : public QObject
{
    Q_OBJECT

public:
    /** The file format's name and version. */
    static constexpr const char *Format = "semhap.workspace/1";
    /** How often (ms) autosaveTo() writes the workspace when something changed. */
    static constexpr int AutosaveInterval = 2000;

    /**
     * Adds the device addresses saved by earlier sessions to the device listing (those that
     * no longer parse are left out, with a warning naming the settings file).
     */
    explicit Workspace(QObject *parent = nullptr);
    /** Writes the workspace a last time when it autosaves. */
    ~Workspace() override;

    Engine &engine() { return m_engine; }
    RouterDocument &routerDocument() { return *m_routerDocument; }
    PatternDocument &patternDocument() { return *m_patternDocument; }
    StudyDocument &study() { return *m_study; }

    /** Keeps the device addresses the user added (DeviceManager::configured) for next time. */
    void saveDeviceAddresses();

    /** The next recording's name and notes, as typed in the toolbar. */
    QString sessionName() const { return m_sessionName; }
    void setSessionName(const QString &name) { m_sessionName = name; }
    QString sessionNotes() const { return m_sessionNotes; }
    void setSessionNotes(const QString &notes) { m_sessionNotes = notes; }

    /**
     * Where the studio keeps its workspace: beside its settings file and named after it
     * (`semhap-studio.workspace.json`).
     */
    static QString defaultFile();

    /**
     * The workspace as its file holds it: the run (a simulation's scene, cubes, gripper,
     * router, operator, seed and reaction time, or a live rig's address, port and router), the
     * running router's graph when it is an edit, the bindings to real devices (with their
     * models), the two documents (content, file, read-only, modified), the study open and its
     * participant chosen, and the next recording's name and notes. A replay is not kept: the
     * run it replaced is.
     */
    QJsonObject toJson() const;

    /**
     * Opens the workspace saved in `path` (none there: false, nothing to say). The saved
     * run is loaded (paused), with an edited router applied again, unless `options` names a
     * run of its own; the documents come back with their unsaved edits shown as not saved
     * (their undo history does not survive). Whatever cannot come back is left out and said
     * in `problems`, each as `FILE: /pointer: reason` (or `FILE:LINE:COL:` for broken JSON),
     * and the file as it was is kept as `PATH.bak`, since the next autosave writes only
     * what came back. True when a run was loaded. Call restoreBindings() once a run is.
     */
    bool restore(const QString &path, const StudioOptions &options, QStringList *problems);
    /**
     * Binds the bands restore() read to the running router's devices of the same name and
     * model, disarmed as every real band starts; a band with no such device stays unbound
     * and is said in `problems`. Once after restore().
     */
    void restoreBindings(QStringList *problems);

    /**
     * From now on writes the workspace to `path` (through a temporary and a rename) every
     * AutosaveInterval when it changed, and when the workspace goes; a write that fails is
     * reported once by autosaveFailed().
     */
    void autosaveTo(const QString &path);
    /** Writes the workspace to the autosave file now if it changed; false with `error`. */
    bool autosave(QString *error = nullptr);

signals:
    /** The autosave file could not be written (`FILE: cannot write: reason`). */
    void autosaveFailed(const QString &error);

private:
    void restoreRun(const QJsonObject &run, const QString &path, const StudioOptions &options,
                    QStringList *problems);
    void restoreDocuments(const QJsonObject &json, const QString &path, QStringList *problems);
    void restoreStudy(const QJsonObject &json, const QString &path, QStringList *problems);
    /** Copies `path` to `PATH.bak` and says so (or why not) in `problems`. */
    void keepCopy(const QString &path, QStringList *problems);

    Engine m_engine;
    std::unique_ptr<StudyDocument> m_study; ///< after the engine it drives: it goes first
    RouterDocument *m_routerDocument;
    PatternDocument *m_patternDocument;
    QString m_sessionName;
    QString m_sessionNotes;
    QJsonObject m_restored; ///< what restore() read, until restoreBindings()
    QString m_restoredPath;
    bool m_copyKept = false; ///< the file restore() read is copied to PATH.bak
    QString m_autosavePath;
    QByteArray m_saved; ///< what the autosave file holds
    QTimer m_autosaveTimer;
    bool m_autosaveFailing = false; ///< reported once until a write works again
};

} // namespace semhap
