// SPDX-License-Identifier: MIT
#include "studio.h"

#include "mainwindow.h"
#include "preferencesdialog.h"
#include "studydocument.h"
#include "studypanel.h"

#include <QApplication>
#include <QDir>
#include <QFileInfo>
#include <QLibraryInfo>
#include <QTimer>

#include <cstdio>

namespace semhap {

Studio::Studio(const StudioOptions &options, QObject *parent) : QObject(parent), m_options(options)
{
    QString language = options.language;
    if (language.isEmpty())
        language = PreferencesDialog::savedLanguage();
    install(language);
}

Studio::~Studio()
{
    // The window goes before the workspace writes itself a last time (and may say it
    // could not).
    m_window.reset();
}

void Studio::install(const QString &language)
{
    QCoreApplication::removeTranslator(&m_translator);
    QCoreApplication::removeTranslator(&m_qtTranslator);
    const QLocale locale = language.isEmpty() ? QLocale::system() : QLocale(language);
    // English is the source language: it needs no file, and other locales fall back to it.
    m_language = QStringLiteral("en");
    if (m_translator.load(locale, QStringLiteral("semhap"), QStringLiteral("_"),
                          QStringLiteral(":/i18n"))) {
        QCoreApplication::installTranslator(&m_translator);
        m_language = locale.name().section(QLatin1Char('_'), 0, 0);
    }
    // Qt's own strings (standard buttons, dialogs), where the system has them.
    if (m_qtTranslator.load(locale, QStringLiteral("qtbase"), QStringLiteral("_"),
                            QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        QCoreApplication::installTranslator(&m_qtTranslator);
    QLocale::setDefault(QLocale(m_language));
}

void Studio::buildWindow()
{
    m_window = std::make_unique<MainWindow>(m_workspace, m_options);
    connect(m_window.get(), &MainWindow::languageChangeRequested, this, &Studio::setLanguage,
            Qt::QueuedConnection);
    m_window->show();
}

void Studio::start()
{
    // What was open when the studio last went — quit or crashed — opens again.
    QStringList problems;
    Engine &engine = m_workspace.engine();
    engine.setSpeed(m_options.speed);
    const bool restored = m_workspace.restore(Workspace::defaultFile(), m_options, &problems);
    m_workspace.autosaveTo(Workspace::defaultFile());
    openStudy(&problems);
    buildWindow();
    m_workspace.restoreBindings(&problems); // to the run restored or the window opened
    if (restored && m_options.autoRun)
        engine.run();
    if (!problems.isEmpty())
        m_window->showError(tr("Some of what you left open could not be opened again"),
                            problems.join(QLatin1Char('\n')));
    if (m_options.startStep && m_workspace.study().participant() == m_options.participant)
        m_window->studyPanel()->start();
    connect(&m_workspace, &Workspace::autosaveFailed, this, [this](const QString &error) {
        if (m_window)
            m_window->showError(tr("Your work is not being saved"), error);
    });
    if (m_options.quitAfter < 0)
        return;
    QTimer::singleShot(int(m_options.quitAfter * 1000), this, [this] {
        int code = 0;
        if (!m_options.screenshot.isEmpty()) {
            QString error;
            if (screenshot(m_window.get(), m_options.screenshot, &error)) {
                std::printf("%s\n", qPrintable(m_options.screenshot));
            } else {
                std::fprintf(stderr, "semhap-studio: %s\n", qPrintable(error));
                code = 1;
            }
        }
        m_window->close();
        QCoreApplication::exit(code);
    });
}

void Studio::openStudy(QStringList *problems)
{
    if (m_options.study.isEmpty())
        return;
    StudyDocument &study = m_workspace.study();
    QString error;
    if (!study.open(m_options.study, &error)) {
        problems->append(error);
        return;
    }
    if (m_options.participant.isEmpty())
        return;
    study.setParticipant(m_options.participant);
    if (study.participant() != m_options.participant)
        problems->append(
            tr("%1: no participant '%2'").arg(m_options.study, m_options.participant));
}

void Studio::setLanguage(const QString &language)
{
    // The new window opens where the old one was, with its layout. The old one is not
    // closed (closing stops every device): it only goes, and the run goes on.
    m_options.size = QSize();
    m_options.restoreLayout = true;
    if (m_window)
        m_window->saveLayout();
    m_window.reset();
    install(language);
    buildWindow();
    emit windowRebuilt();
}

QUrl Studio::manualUrl()
{
    // Installed: beside the programs, so an extracted package and any --prefix find it too.
    const QStringList places{QDir(QCoreApplication::applicationDirPath())
                                 .filePath(QStringLiteral(SEMHAP_DOCS_FROM_BINARY "/studio.md")),
                             QStringLiteral(SEMHAP_SOURCE_DOCS "/studio.md")};
    for (const QString &place : places) {
        if (QFileInfo(place).isFile())
            return QUrl::fromLocalFile(QFileInfo(place).canonicalFilePath());
    }
    return QUrl();
}

bool Studio::screenshot(QWidget *window, const QString &path, QString *error)
{
    const QPixmap image = window->grab();
    if (image.isNull() || !image.save(path, "PNG")) {
        *error = tr("%1: could not write the screenshot").arg(path);
        return false;
    }
    return true;
}

} // namespace semhap
