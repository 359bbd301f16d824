// SPDX-License-Identifier: MIT
#pragma once

#include "bandlog.h"

#include <QProcess>
#include <QString>
#include <QStringList>

/** The band's watchdog (devices/PROTOCOL.md): the silence after which it zeroes its outputs. */
constexpr qint64 BandWatchdogMs = 250;

/**
 * A band in software in a child process — `semhap emulate …` or `semhap bandsim …` (the
 * real binary, SEMHAP_CLI_BINARY) — whose first line, the pty or HOST:PORT it serves, has
 * been read. Stopped with SIGTERM (a clean exit) when destroyed.
 */
class BandProcess
{
public:
    explicit BandProcess(const QStringList &arguments)
    {
        m_process.start(QStringLiteral(SEMHAP_CLI_BINARY), arguments);
        if (m_process.waitForReadyRead(5000))
            m_address = QString::fromUtf8(m_process.readLine()).trimmed();
    }
    ~BandProcess()
    {
        m_process.terminate();
        if (!m_process.waitForFinished(3000))
            m_process.kill();
    }
    BandProcess(const BandProcess &) = delete;
    BandProcess &operator=(const BandProcess &) = delete;

    bool started() const { return !m_address.isEmpty(); }
    /** The first line it printed: the pty's path, or HOST:PORT. */
    const QString &address() const { return m_address; }
    /** Stops it with SIGTERM; its exit code, or -1 when it did not exit normally. */
    int stop()
    {
        m_process.terminate();
        m_process.waitForFinished(3000);
        return m_process.exitStatus() == QProcess::NormalExit ? m_process.exitCode() : -1;
    }
    /** What it wrote on standard error. */
    QByteArray errors() { return m_process.readAllStandardError(); }

private:
    QProcess m_process;
    QString m_address;
};

/** Starts a long `air.squeeze` on `uri` in `play`; whether the band's log shows it full. */
inline bool squeezeUntilFull(QProcess &play, const QString &uri, const QString &log)
{
    play.start(QStringLiteral(SEMHAP_CLI_BINARY),
               {"play", "air.squeeze", "--device", uri, "--duration", "20"});
    return waitForBandLog(
               log, [](const BandLogLine &l) { return allAt(l, 1.0); }, 5000) >= 0;
}
