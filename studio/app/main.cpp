// SPDX-License-Identifier: MIT
// semhap-studio: the GUI. Everything lives in the semhap_studio library; this only reads
// the command line and starts it.
#include "quitsignal.h"
#include "semhaprevision.h"
#include "studio.h"

#include <QApplication>
#include <QCoreApplication>
#include <QSurfaceFormat>
#include <QTimer>

#include <cstdio>

namespace {

/** The names and version every part of the studio reads (settings, --version, dialogs). */
void nameApplication()
{
    QCoreApplication::setOrganizationName(QStringLiteral("semhap"));
    QCoreApplication::setApplicationName(QStringLiteral("semhap-studio"));
    QCoreApplication::setApplicationVersion(
        QStringLiteral(SEMHAP_VERSION " (" SEMHAP_REVISION ")"));
}

/**
 * Reads the command line into `options`; -1 to go on, else the exit code after printing
 * the help or version text (standard output) or the usage error (standard error).
 */
int readCommandLine(semhap::StudioOptions *options)
{
    QString message;
    bool help = false;
    if (semhap::StudioOptions::parse(QCoreApplication::arguments().mid(1), options, &message,
                                     &help))
        return -1;
    std::fprintf(help ? stdout : stderr, "%s%s",
                 help ? "" : "semhap-studio: ", qPrintable(message));
    if (!help)
        std::fprintf(stderr, "\n");
    return help ? 0 : 2;
}

/** Whether the command line asks only for the help or the version text. */
bool asksForText(int argc, char *argv[])
{
    for (int i = 1; i < argc; ++i) {
        const QByteArray arg(argv[i]);
        if (arg == "--help" || arg == "-h" || arg == "-?" || arg == "--help-all" ||
            arg == "--version" || arg == "-v")
            return true;
    }
    return false;
}

} // namespace

int main(int argc, char *argv[])
{
    // The help and the version need no display: they are answered before the GUI exists.
    if (asksForText(argc, argv)) {
        QCoreApplication core(argc, argv);
        nameApplication();
        semhap::StudioOptions options;
        return readCommandLine(&options);
    }

    // MuJoCo's renderer needs a compatibility profile; set it before any context exists.
    QSurfaceFormat format;
    format.setProfile(QSurfaceFormat::CompatibilityProfile);
    format.setDepthBufferSize(24);
    format.setStencilBufferSize(8);
    QSurfaceFormat::setDefaultFormat(format);

    QApplication app(argc, argv);
    nameApplication();
    // Desktops find the window's icon and name through the installed desktop entry.
    QGuiApplication::setDesktopFileName(QStringLiteral("org.semhap.studio"));

    semhap::StudioOptions options;
    if (const int exitCode = readCommandLine(&options); exitCode >= 0)
        return exitCode;

    // SIGINT and SIGTERM close the studio normally, so every device is stopped first.
    semhap::QuitSignal::install();
    QTimer quitPoll;
    QObject::connect(&quitPoll, &QTimer::timeout, &app, [] {
        if (semhap::QuitSignal::requested())
            QApplication::quit();
    });
    quitPoll.start(100);

    semhap::Studio studio(options);
    studio.start();
    return app.exec();
}
