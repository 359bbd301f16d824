// SPDX-License-Identifier: MIT
#include "udplink.h"

#include "deviceuri.h"

#include <sys/socket.h>

namespace semhap {

UdpLink::UdpLink(const QString &host, int port) : m_host(host), m_port(port) {}

QString UdpLink::uri() const
{
    return DeviceUri::hostPortUri(QStringLiteral("udp"), m_host, m_port);
}

bool UdpLink::open(QString *error)
{
    return openSocket(
        m_host, m_port, SOCK_DGRAM,
        [](int fd, const sockaddr *address, socklen_t length) {
            return ::connect(fd, address, length) == 0;
        },
        error);
}

} // namespace semhap
