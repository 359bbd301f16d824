// SPDX-License-Identifier: MIT
#pragma once

#include <QString>
#include <QStringList>

class QIODevice;

namespace semhap {

class SessionReader;

/**
 * A session as an XDF file (docs/science.md), for labs that line their recordings up with
 * the Lab Streaming Layer. Its streams, each left out when it has no samples:
 *
 * - per gripper, the fingertip forces: `f`, `n`, `fx`, `fy`, `fz` of each tip as float32
 *   channels named as `semhap export --csv` names them;
 * - per gripper, its semantic events as string markers, `MESSAGE/PHASE/INTENSITY`;
 * - per device, its output channels as the player sent them;
 * - per hand, the operator's input (wrist target and grip).
 *
 * Samples go in chunks of a second of session time, interleaved, with a Boundary chunk
 * every ten seconds and a ClockOffset chunk per stream for each sample of the steady clock
 * the session kept (SessionClock), then a footer per stream.
 */
class XdfExport
{
public:
    /** The clock the time stamps are on. */
    enum class TimeBase
    {
        /**
         * The session's seconds. The ClockOffset chunks map them onto the steady clock (LSL's
         * `local_clock()`), as LabRecorder's map another machine's streams, so a reader that
         * synchronises clocks (pyxdf's default) puts them on it.
         */
        Session,
        /** LSL's clock (the steady clock of the machine that recorded): offsets are 0. */
        Lsl
    };

    /**
     * Writes `session` to `out` with its time stamps on `time`. What the export could not do
     * (no steady clock to offset by) goes to `notes`, a line each. False with `error` when
     * the session cannot be read, a write fails, or `time` is Lsl and the session's time
     * cannot be put on the clock (recorded before sessions kept it, or faster than real time).
     */
    static bool write(SessionReader &session, QIODevice *out, TimeBase time, QStringList *notes,
                      QString *error);

    /** The marker of an event: `grasp/begin/0.80`. */
    static QByteArray marker(const QString &message, const QString &phase, double intensity);
};

} // namespace semhap
