// SPDX-License-Identifier: MIT
#pragma once

#include <QObject>
#include <QString>

class QThread;
class QWidget;

namespace semhap {

/**
 * File → Export session…: a recorded session as XDF, for labs synchronised by the Lab
 * Streaming Layer (on the session's time with clock offsets, or on LSL's clock), or as MCAP,
 * for Foxglove, PlotJuggler and Rerun — what `semhap export --xdf` and `--mcap` write. The
 * export runs on a thread of its own into a temporary file renamed into place, so the window
 * goes on and a failed export leaves nothing behind.
 */
class SessionExport : public QObject
{
    Q_OBJECT

public:
    explicit SessionExport(QWidget *window);
    ~SessionExport() override;

    /**
     * Asks where to export `session` (its format by the file type picked) and starts; false
     * when the user cancelled or an export is still running.
     */
    bool start(const QString &session);
    bool isRunning() const { return m_thread != nullptr; }

signals:
    /** The export ended: `error` empty, else why not (`FILE: reason`); `notes` a line each. */
    void finished(const QString &target, const QString &error, const QString &notes);

private:
    QWidget *m_window;
    QThread *m_thread = nullptr;
};

} // namespace semhap
