// SPDX-License-Identifier: MIT
#include "pseudoterminal.h"

#include <QFile>
#include <QFileInfo>

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <termios.h>
#include <unistd.h>

namespace semhap {

namespace {

QString errnoText()
{
    return QString::fromLocal8Bit(std::strerror(errno));
}

} // namespace

PseudoTerminal::~PseudoTerminal()
{
    if (!m_link.isEmpty() && !m_path.isEmpty() && QFileInfo(m_link).symLinkTarget() == m_path)
        QFile::remove(m_link);
    if (m_slaveFd >= 0)
        ::close(m_slaveFd);
    if (m_fd >= 0)
        ::close(m_fd);
}

bool PseudoTerminal::open(const QString &link, QString *error)
{
    m_fd = ::posix_openpt(O_RDWR | O_NOCTTY | O_CLOEXEC);
    if (m_fd < 0 || ::grantpt(m_fd) != 0 || ::unlockpt(m_fd) != 0) {
        *error = QStringLiteral("cannot create a pseudo-terminal: %1").arg(errnoText());
        return false;
    }
    m_path = QString::fromLocal8Bit(::ptsname(m_fd));
    m_slaveFd = ::open(m_path.toLocal8Bit().constData(), O_RDWR | O_NOCTTY | O_CLOEXEC);
    if (m_slaveFd < 0) {
        *error = QStringLiteral("%1: %2").arg(m_path, errnoText());
        return false;
    }
    // Raw from the start: an echoing line discipline would send the host's bytes back.
    termios tio{};
    ::tcgetattr(m_slaveFd, &tio);
    ::cfmakeraw(&tio);
    ::tcsetattr(m_slaveFd, TCSANOW, &tio);
    ::fcntl(m_fd, F_SETFL, ::fcntl(m_fd, F_GETFL) | O_NONBLOCK);
    if (link.isEmpty())
        return true;
    m_link = link;
    return makeLink(error);
}

bool PseudoTerminal::makeLink(QString *error)
{
    const QFileInfo existing(m_link);
    if (existing.exists() && !existing.isSymLink()) {
        *error = QStringLiteral("%1: exists and is not a symlink; not replacing it").arg(m_link);
        return false;
    }
    // A new link renamed over the old one, so a host never sees the path missing.
    const QByteArray temporary = (m_link + QStringLiteral(".new")).toLocal8Bit();
    ::unlink(temporary.constData());
    if (::symlink(m_path.toLocal8Bit().constData(), temporary.constData()) != 0 ||
        ::rename(temporary.constData(), m_link.toLocal8Bit().constData()) != 0) {
        *error = QStringLiteral("%1: cannot link: %2").arg(m_link, errnoText());
        return false;
    }
    return true;
}

} // namespace semhap
