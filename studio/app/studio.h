// SPDX-License-Identifier: MIT
#pragma once

#include "studiooptions.h"
#include "workspace.h"

#include <QObject>
#include <QPointer>
#include <QTranslator>
#include <QUrl>

#include <memory>

namespace semhap {

class MainWindow;

/**
 * The studio as an application: installs the interface language (the command line's, the
 * saved setting's or the system's), holds the Workspace and shows the main window over it —
 * building the window again when the user switches language, over the same workspace, so
 * the run, the devices, the recording, the edits and a study's trial go on — and runs the
 * testing hooks (`--screenshot`, `--quit-after`, `--start-step`).
 */
class Studio : public QObject
{
    Q_OBJECT

public:
    explicit Studio(const StudioOptions &options, QObject *parent = nullptr);
    ~Studio() override;

    /** Shows the window and arms the testing hooks. */
    void start();
    MainWindow *window() const { return m_window.get(); }
    Workspace &workspace() { return m_workspace; }
    /** The language in use ("en", "de"). */
    QString language() const { return m_language; }

    /**
     * Installs `language` ("en", "de"; empty: the system's) and builds the window again, where
     * it was and with its layout, over the same workspace.
     */
    void setLanguage(const QString &language);

    /**
     * The manual (docs/studio.md): installed with the programs (`share/doc/semhap/docs`),
     * else in the sources the build came from; empty when neither is there.
     */
    static QUrl manualUrl();

    /** Grabs the whole window, docks and viewport included, to a PNG. */
    static bool screenshot(QWidget *window, const QString &path, QString *error);

signals:
    /** The window was rebuilt (after a language switch). */
    void windowRebuilt();

private:
    void install(const QString &language);
    void buildWindow();
    /** Opens the study the command line names (`--study`, `--participant`), or says why not. */
    void openStudy(QStringList *problems);

    StudioOptions m_options;
    Workspace m_workspace;
    std::unique_ptr<MainWindow> m_window; ///< after the workspace: it goes first
    QTranslator m_translator;
    QTranslator m_qtTranslator;
    QString m_language;
};

} // namespace semhap
