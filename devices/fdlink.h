// SPDX-License-Identifier: MIT
#pragma once

#include "link.h"

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
    /** Called by close() before the descriptor is closed (releases a library's handle). */
    virtual void release() {}

    int m_fd = -1;
};

} // namespace semhap
