// SPDX-License-Identifier: MIT
#pragma once

#include <QByteArray>
#include <QFile>
#include <QString>

#include <vector>

namespace semhap {

/**
 * A band's state as JSON Lines, `{"t": 0.513, "setpoint": [...], "values": [...]}`, a line
 * at every change (numbers to 1e-4, so that a settling lag stops producing lines): what
 * `semhap emulate --log` and `semhap bandsim --log` write, line by line for whoever follows
 * the band live.
 */
class BandStateLog
{
public:
    /** Empties and opens `path`; false with `FILE: cannot write: reason`. */
    bool open(const QString &path, QString *error);
    bool isOpen() const { return m_file.isOpen(); }
    /**
     * Writes a line at `t` when the setpoints or values differ from the last line's; false
     * once a write failed (the log is closed then, the reason in error()).
     */
    bool write(double t, const std::vector<double> &setpoints, const std::vector<double> &values);
    /** `FILE: cannot write: reason` after a failed write; empty while the log is fine. */
    const QString &error() const { return m_error; }

private:
    QFile m_file;
    QString m_error;
    QByteArray m_state; ///< this line's arrays, reused
    QByteArray m_lastState;
    QByteArray m_line;
};

} // namespace semhap
