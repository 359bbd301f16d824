// SPDX-License-Identifier: MIT
#include "udplink.h"

#include <cerrno>
#include <cstring>
#include <memory>
#include <netdb.h>
#include <sys/socket.h>
#include <unistd.h>

namespace semhap {

UdpLink::UdpLink(const QString &host, int port) : m_host(host), m_port(port) {}

QString UdpLink::uri() const
{
    return QStringLiteral("udp:%1:%2").arg(m_host).arg(m_port);
}

bool UdpLink::open(QString *error)
{
    close();
    addrinfo hints{};
    hints.ai_family = AF_UNSPEC;
    hints.ai_socktype = SOCK_DGRAM;
    addrinfo *found = nullptr;
    const int rc = ::getaddrinfo(m_host.toLocal8Bit().constData(),
                                 QByteArray::number(m_port).constData(), &hints, &found);
    if (rc != 0) {
        *error = QStringLiteral("%1: %2").arg(m_host, QString::fromLocal8Bit(gai_strerror(rc)));
        return false;
    }
    std::unique_ptr<addrinfo, void (*)(addrinfo *)> list(found, ::freeaddrinfo);
    for (addrinfo *a = found; a; a = a->ai_next) {
        const int fd =
            ::socket(a->ai_family, a->ai_socktype | SOCK_NONBLOCK | SOCK_CLOEXEC, a->ai_protocol);
        if (fd < 0)
            continue;
        if (::connect(fd, a->ai_addr, a->ai_addrlen) == 0) {
            m_fd = fd;
            return true;
        }
        ::close(fd);
    }
    *error = QStringLiteral("%1:%2: %3")
                 .arg(m_host)
                 .arg(m_port)
                 .arg(QString::fromLocal8Bit(std::strerror(errno)));
    return false;
}

} // namespace semhap
