// SPDX-License-Identifier: MIT
// semhap-studio: the GUI. Everything lives in the semhap_studio library; this only reads
// the command line and starts it.
#include "quitsignal.h"
#include "semhaprevision.h"
#include "studio.h"

#include <QApplication>
#include <QSurfaceFormat>
#include <QTimer>

#include <cstdio>

int main(int argc, char *argv[])
{
    // MuJoCo's renderer needs a compatibility profile; set it before any context exists.
    QSurfaceFormat format;
    format.setProfile(QSurfaceFormat::CompatibilityProfile);
    format.setDepthBufferSize(24);
    format.setStencilBufferSize(8);
    QSurfaceFormat::setDefaultFormat(format);

    QApplication app(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("semhap"));
    QApplication::setApplicationName(QStringLiteral("semhap-studio"));
    QApplication::setApplicationVersion(QStringLiteral(SEMHAP_VERSION " (" SEMHAP_REVISION ")"));
    // Desktops find the window's icon and name through the installed desktop entry.
    QGuiApplication::setDesktopFileName(QStringLiteral("org.semhap.studio"));

    semhap::StudioOptions options;
    QString message;
    bool help = false;
    if (!semhap::StudioOptions::parse(QApplication::arguments().mid(1), &options, &message,
                                      &help)) {
        std::fprintf(help ? stdout : stderr, "%s%s",
                     help ? "" : "semhap-studio: ", qPrintable(message));
        if (!help)
            std::fprintf(stderr, "\n");
        return help ? 0 : 2;
    }

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
