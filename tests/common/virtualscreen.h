// SPDX-License-Identifier: MIT
#pragma once

#include <QDir>
#include <QFile>
#include <QProcess>
#include <QRect>
#include <QRegularExpression>
#include <QSize>
#include <QString>
#include <QTest>

/**
 * An X screen of its own for programs a test starts: an Xvfb of a chosen size and,
 * optionally, a real window manager (openbox) that frames windows with a title bar and
 * keeps `panel` pixels at the bottom free, as a desktop's panel does. Windows on it are
 * read with xwininfo and xprop (x11-utils), as the window manager sees them.
 */
class VirtualScreen
{
public:
    ~VirtualScreen()
    {
        for (QProcess *process : {&m_windowManager, &m_server}) {
            process->terminate();
            process->waitForFinished(5000);
        }
    }

    /** Starts the screen; false with the reason. `folder` takes the manager's settings. */
    bool start(const QSize &size, bool windowManager, int panel, const QString &folder,
               QString *error)
    {
        // The server picks a free display and says which on its standard output.
        // -noreset: the server would reset, refusing clients a moment, whenever its last
        // client leaves (each xwininfo).
        m_server.start("Xvfb", {"-displayfd", "1", "-noreset", "-nolisten", "tcp", "-screen", "0",
                                QString("%1x%2x24").arg(size.width()).arg(size.height())});
        if (!m_server.waitForStarted(10000)) {
            *error = "Xvfb does not start: " + m_server.errorString();
            return false;
        }
        if (!QTest::qWaitFor([this] { return m_server.canReadLine(); }, 10000)) {
            *error = "Xvfb gave no display";
            return false;
        }
        m_display = ':' + QString::fromLatin1(m_server.readLine()).trimmed();
        if (!windowManager)
            return true;
        // openbox's own settings with a margin where a panel would be.
        QFile defaults("/etc/xdg/openbox/rc.xml");
        QFile settings(QDir(folder).filePath("openbox-rc.xml"));
        if (!defaults.open(QIODevice::ReadOnly) || !settings.open(QIODevice::WriteOnly)) {
            *error = "no openbox settings (scripts/deps.sh installs openbox)";
            return false;
        }
        settings.write(
            QString::fromUtf8(defaults.readAll())
                .replace("<bottom>0</bottom>", QString("<bottom>%1</bottom>").arg(panel))
                .toUtf8());
        settings.close();
        m_windowManager.setProcessEnvironment(environment());
        m_windowManager.start("openbox", {"--config-file", settings.fileName()});
        if (!m_windowManager.waitForStarted(10000)) {
            *error = "openbox does not start: " + m_windowManager.errorString();
            return false;
        }
        // Ready once it announces the area it leaves to windows (the whole screen first).
        if (!QTest::qWaitFor([&] { return workArea().height() == size.height() - panel; },
                             10000)) {
            *error = QString("openbox did not keep the panel's margin: work area %1x%2; %3")
                         .arg(workArea().width())
                         .arg(workArea().height())
                         .arg(QString::fromLocal8Bit(m_windowManager.readAll()));
            return false;
        }
        return true;
    }

    /** An environment whose programs open their windows on this screen. */
    QProcessEnvironment environment() const
    {
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert("DISPLAY", m_display);
        env.insert("QT_QPA_PLATFORM", "xcb");
        env.remove("WAYLAND_DISPLAY");
        return env;
    }

    /** The screen without what the window manager keeps free (`_NET_WORKAREA`). */
    QRect workArea() const
    {
        const QList<int> area = numbers(run("xprop", {"-root", "_NET_WORKAREA"}));
        if (area.size() >= 4)
            return QRect(area[0], area[1], area[2], area[3]);
        const QString root = run("xwininfo", {"-root"});
        const QRegularExpressionMatch size =
            QRegularExpression(R"(-geometry (\d+)x(\d+))").match(root);
        return QRect(0, 0, size.captured(1).toInt(), size.captured(2).toInt());
    }

    /** A top-level window of WM_CLASS `windowClass`: where its inside is, on the screen. */
    struct Window
    {
        QString id;
        QRect inside; ///< without the window manager's frame
        QRect frame;  ///< with it
    };

    /**
     * The largest window of `windowClass` on screen (and framed, with a window manager);
     * empty id when there is none.
     */
    Window window(const QString &windowClass) const
    {
        Window found;
        const QRegularExpression line(QString(R"(^\s*(0x[0-9a-f]+) .*\("%1" "[^"]*"\)\s+)"
                                              R"((\d+)x(\d+)[+-]\d+[+-]\d+\s+\+(-?\d+)\+(-?\d+))")
                                          .arg(windowClass),
                                      QRegularExpression::MultilineOption);
        auto it = line.globalMatch(run("xwininfo", {"-root", "-tree"}));
        while (it.hasNext()) {
            const QRegularExpressionMatch m = it.next();
            const QRect inside(m.captured(4).toInt(), m.captured(5).toInt(), m.captured(2).toInt(),
                               m.captured(3).toInt());
            if (inside.width() * inside.height() > found.inside.width() * found.inside.height())
                found = Window{m.captured(1), inside, inside};
        }
        // Only a window on screen, framed when there is a window manager, counts.
        if (found.id.isEmpty() ||
            !run("xwininfo", {"-id", found.id}).contains("Map State: IsViewable"))
            return Window();
        // left, right, top, bottom; none without a window manager
        const QList<int> extents = numbers(run("xprop", {"-id", found.id, "_NET_FRAME_EXTENTS"}));
        if (extents.size() == 4)
            found.frame = found.inside.adjusted(-extents[0], -extents[2], extents[1], extents[3]);
        else if (m_windowManager.state() == QProcess::Running)
            return Window();
        return found;
    }

private:
    /**
     * What `program` prints; it is run again when it fails (xwininfo -tree fails when a
     * window goes while it walks the tree).
     */
    QString run(const QString &program, const QStringList &arguments) const
    {
        for (int attempt = 0; attempt < 10; ++attempt) {
            QProcess process;
            process.setProcessEnvironment(environment());
            process.start(program, arguments);
            if (process.waitForFinished(10000) && process.exitStatus() == QProcess::NormalExit &&
                process.exitCode() == 0)
                return QString::fromLocal8Bit(process.readAllStandardOutput());
        }
        return QString();
    }

    /** The numbers after '=' in xprop's answer. */
    static QList<int> numbers(const QString &answer)
    {
        QList<int> values;
        const qsizetype equals = answer.indexOf('=');
        if (equals < 0)
            return values;
        for (const QString &part : answer.mid(equals + 1).split(QLatin1Char(','))) {
            bool ok = false;
            const int value = part.trimmed().toInt(&ok);
            if (ok)
                values.append(value);
        }
        return values;
    }

    QProcess m_server;
    QProcess m_windowManager;
    QString m_display;
};
