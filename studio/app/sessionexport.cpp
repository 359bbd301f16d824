// SPDX-License-Identifier: MIT
#include "sessionexport.h"

#include "filedialogs.h"
#include "mcapexport.h"
#include "sessionreader.h"
#include "xdfexport.h"

#include <QFileInfo>
#include <QSaveFile>
#include <QThread>
#include <QWidget>

namespace semhap {

namespace {

enum class Format
{
    XdfSession,
    XdfLsl,
    Mcap
};

/** Writes `session` to `target` as `format`; the reason when it could not, else empty. */
QString exportSession(const QString &session, const QString &target, Format format,
                      QStringList *notes)
{
    if (QFileInfo(target).canonicalFilePath() == QFileInfo(session).canonicalFilePath())
        return target + QStringLiteral(": is the session itself");
    QString error;
    // Opened on this thread: a reader's database connection is its thread's.
    std::unique_ptr<SessionReader> reader = SessionReader::open(session, &error);
    if (!reader)
        return error;
    QSaveFile out(target);
    if (!out.open(QIODevice::WriteOnly))
        return target + QStringLiteral(": cannot write: ") + out.errorString();
    const bool written =
        format == Format::Mcap
            ? McapExport::write(*reader, &out, &error)
            : XdfExport::write(*reader, &out,
                               format == Format::XdfLsl ? XdfExport::TimeBase::Lsl
                                                        : XdfExport::TimeBase::Session,
                               notes, &error);
    if (!written) {
        out.cancelWriting();
        return error.startsWith(QLatin1String("cannot write"))
                   ? target + QStringLiteral(": ") + error
                   : error;
    }
    if (!out.commit())
        return target + QStringLiteral(": cannot write: ") + out.errorString();
    return QString();
}

} // namespace

SessionExport::SessionExport(QWidget *window) : QObject(window), m_window(window) {}

SessionExport::~SessionExport()
{
    if (!m_thread)
        return;
    m_thread->wait();
    delete m_thread; // its report, queued to this object, is dropped with it
}

bool SessionExport::start(const QString &session)
{
    if (m_thread)
        return false;
    const QString xdfSession = tr("XDF for LSL labs, session time with clock offsets (*.xdf)");
    const QString xdfLsl = tr("XDF for LSL labs, on LSL's clock (*.xdf)");
    const QString mcap = tr("MCAP for Foxglove, PlotJuggler and Rerun (*.mcap)");
    QString picked;
    QString target = FileDialogs::saveFile(
        m_window, FileKind::SessionExport, tr("Export session"),
        QFileInfo(session).completeBaseName() + QStringLiteral(".xdf"),
        xdfSession + QStringLiteral(";;") + xdfLsl + QStringLiteral(";;") + mcap, &picked);
    if (target.isEmpty())
        return false;
    // The file type picked decides; a name typed without its suffix gets it. With no type
    // picked (some native dialogs), the name's suffix does.
    const bool mcapName = target.endsWith(QLatin1String(".mcap"), Qt::CaseInsensitive);
    const Format format = picked == mcap || (picked.isEmpty() && mcapName) ? Format::Mcap
                          : picked == xdfLsl                               ? Format::XdfLsl
                                                                           : Format::XdfSession;
    const QString suffix =
        format == Format::Mcap ? QStringLiteral(".mcap") : QStringLiteral(".xdf");
    if (!target.endsWith(suffix, Qt::CaseInsensitive))
        target += suffix;
    m_thread = QThread::create([this, session, target, format] {
        QStringList notes;
        const QString error = exportSession(session, target, format, &notes);
        QMetaObject::invokeMethod(this, [this, target, error, notes] {
            m_thread->wait();
            delete m_thread;
            m_thread = nullptr;
            emit finished(target, error, notes.join(QLatin1Char('\n')));
        });
    });
    m_thread->start();
    return true;
}

} // namespace semhap
