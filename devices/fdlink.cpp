// SPDX-License-Identifier: MIT
#include "fdlink.h"

#include <cerrno>
#include <cstring>
#include <memory>
#include <netdb.h>
#include <unistd.h>

namespace semhap {

FdLink::~FdLink()
{
    // Not close(): a virtual call from a destructor would skip the subclass's release().
    if (m_fd >= 0)
        ::close(m_fd);
}

void FdLink::close()
{
    release();
    if (m_fd >= 0)
        ::close(m_fd);
    m_fd = -1;
}

bool FdLink::writeFrame(const std::uint8_t *data, int size, QString *error)
{
    const ssize_t n = ::write(m_fd, data, size_t(size));
    if (n >= 0 || errno == EAGAIN || errno == EINTR || errno == ECONNREFUSED || errno == ENOBUFS)
        return true; // a full or unreachable link drops this frame; the next one is newer
    *error = QString::fromLocal8Bit(std::strerror(errno));
    return false;
}

int FdLink::read(std::uint8_t *buffer, int size, QString *error)
{
    // 0 is no data, not an end: a raw tty with VMIN 0 says so, and so does an empty
    // datagram. A pty whose other side went away fails with EIO instead.
    const ssize_t n = ::read(m_fd, buffer, size_t(size));
    if (n >= 0)
        return int(n);
    if (errno == EAGAIN || errno == EINTR || errno == ECONNREFUSED)
        return 0; // nobody listening on a UDP port yet is not a lost link
    *error = QString::fromLocal8Bit(std::strerror(errno));
    return -1;
}

bool FdLink::openSocket(const QString &host, int port, int type, const Connect &connect,
                        QString *error)
{
    close();
    addrinfo hints{};
    hints.ai_family = AF_UNSPEC;
    hints.ai_socktype = type;
    addrinfo *found = nullptr;
    const int rc = ::getaddrinfo(host.toLocal8Bit().constData(),
                                 QByteArray::number(port).constData(), &hints, &found);
    if (rc != 0) {
        *error = QStringLiteral("%1: %2").arg(host, QString::fromLocal8Bit(gai_strerror(rc)));
        return false;
    }
    std::unique_ptr<addrinfo, void (*)(addrinfo *)> list(found, ::freeaddrinfo);
    for (addrinfo *a = found; a; a = a->ai_next) {
        const int fd =
            ::socket(a->ai_family, a->ai_socktype | SOCK_NONBLOCK | SOCK_CLOEXEC, a->ai_protocol);
        if (fd < 0)
            continue;
        if (connect(fd, a->ai_addr, a->ai_addrlen)) {
            m_fd = fd;
            return true;
        }
        const int failure = errno;
        ::close(fd);
        errno = failure;
    }
    *error = QStringLiteral("%1:%2: %3")
                 .arg(host)
                 .arg(port)
                 .arg(QString::fromLocal8Bit(std::strerror(errno)));
    return false;
}

} // namespace semhap
