// SPDX-License-Identifier: MIT
#include "tcplink.h"

#include "deviceuri.h"

#include <cerrno>
#include <cstring>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

namespace semhap {

namespace {

QString errnoText()
{
    return QString::fromLocal8Bit(std::strerror(errno));
}

/** Connects `fd` to `address`, waiting at most `timeoutMs`; false with errno set. */
bool connectWithin(int fd, const sockaddr *address, socklen_t length, int timeoutMs)
{
    if (::connect(fd, address, length) == 0)
        return true;
    if (errno != EINPROGRESS)
        return false;
    pollfd wait{fd, POLLOUT, 0};
    const int ready = ::poll(&wait, 1, timeoutMs);
    if (ready <= 0) {
        errno = ready == 0 ? ETIMEDOUT : errno;
        return false;
    }
    int result = 0;
    socklen_t size = sizeof result;
    if (::getsockopt(fd, SOL_SOCKET, SO_ERROR, &result, &size) < 0)
        return false;
    errno = result;
    return result == 0;
}

} // namespace

TcpLink::TcpLink(const QString &host, int port) : m_host(host), m_port(port) {}

QString TcpLink::uri() const
{
    return DeviceUri::hostPortUri(QStringLiteral("tcp"), m_host, m_port);
}

bool TcpLink::open(QString *error)
{
    if (!openSocket(
            m_host, m_port, SOCK_STREAM,
            [](int fd, const sockaddr *address, socklen_t length) {
                return connectWithin(fd, address, length, ConnectTimeoutMs);
            },
            error))
        return false;
    const int on = 1;
    ::setsockopt(m_fd, IPPROTO_TCP, TCP_NODELAY, &on, sizeof on);
    return true;
}

bool TcpLink::writeFrame(const std::uint8_t *data, int size, QString *error)
{
    // send(), not write(): a server gone away must be an error here, not SIGPIPE.
    const ssize_t n = ::send(m_fd, data, size_t(size), MSG_NOSIGNAL);
    if (n == size || (n < 0 && (errno == EAGAIN || errno == EINTR)))
        return true;
    *error =
        n < 0 ? errnoText()
              : QStringLiteral("the band stopped reading (%1 of %2 bytes sent)").arg(n).arg(size);
    return false;
}

int TcpLink::read(std::uint8_t *buffer, int size, QString *error)
{
    const ssize_t n = ::recv(m_fd, buffer, size_t(size), 0);
    if (n > 0)
        return int(n);
    if (n < 0 && (errno == EAGAIN || errno == EINTR))
        return 0;
    *error = n == 0 ? QStringLiteral("closed by the other end") : errnoText();
    return -1;
}

} // namespace semhap
