// SPDX-License-Identifier: MIT
#pragma once

#include "link.h"

#include <functional>

#include <sys/socket.h>

namespace semhap {

/** A link over a POSIX descriptor (serial ports, sockets): non-blocking reads and writes. */
class FdLink : public Link
{
public:
    ~FdLink() override;
    void close() override;
    int pollFd() const override { return m_fd; }
    bool writeFrame(const std::uint8_t *data, int size, QString *error) override;
    int read(std::uint8_t *buffer, int size, QString *error) override;

protected:
    /** Connects a socket to an address, false with errno set (a network link's own way). */
    using Connect = std::function<bool(int fd, const sockaddr *address, socklen_t length)>;

    /** Called by close() before the descriptor is closed (releases a library's handle). */
    virtual void release() {}
    /**
     * Resolves `host`:`port` and opens a non-blocking socket of `type` (SOCK_DGRAM,
     * SOCK_STREAM) on the first address `connect` takes, as the link's descriptor; false with
     * `error` naming the host or the address and why.
     */
    bool openSocket(const QString &host, int port, int type, const Connect &connect,
                    QString *error);

    int m_fd = -1;
};

} // namespace semhap
