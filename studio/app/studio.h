// SPDX-License-Identifier: MIT
#pragma once

#include "studiooptions.h"

#include <QObject>
#include <QPointer>
#include <QTranslator>

#include <memory>

namespace semhap {

class MainWindow;

/**
 * The studio as an application: installs the interface language (the command line's, the
 * saved setting's or the system's), shows the main window — building it again when the
 * user switches language — and runs the testing hooks (`--screenshot`, `--quit-after`).
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
    /** The language in use ("en", "de"). */
    QString language() const { return m_language; }

    /** Installs `language` ("en", "de"; empty: the system's) and rebuilds the window. */
    void setLanguage(const QString &language);

    /** Grabs the whole window, docks and viewport included, to a PNG. */
    static bool screenshot(QWidget *window, const QString &path, QString *error);

signals:
    /** The window was rebuilt (after a language switch). */
    void windowRebuilt();

private:
    void install(const QString &language);
    void buildWindow();

    StudioOptions m_options;
    std::unique_ptr<MainWindow> m_window;
    QTranslator m_translator;
    QTranslator m_qtTranslator;
    QString m_language;
};

} // namespace semhap
