// SPDX-License-Identifier: MIT
#pragma once

#include <QString>

#include <cstdint>

namespace semhap {

/**
 * A byte link to one device (a serial port, a UDP socket, a HID handle), driven by its
 * transport's I/O thread only. Links carry whole protocol frames; the transport does the
 * rest (latest values, heartbeats, reconnects), once for every kind of link.
 */
class Link
{
public:
    virtual ~Link();

    virtual QString uri() const = 0;
    /** Opens the link; false with `error` (the transport retries later). */
    virtual bool open(QString *error) = 0;
    virtual void close() = 0;
    /** A descriptor to poll for input, or -1 for links that are polled by timer. */
    virtual int pollFd() const = 0;
    /**
     * A descriptor that a signal handler may write() whole frames to (async-signal-safe),
     * or -1 when the link has none (HID).
     */
    virtual int emergencyFd() const { return pollFd(); }
    /** Writes one whole frame; false with `error` when the link is lost. */
    virtual bool writeFrame(const std::uint8_t *data, int size, QString *error) = 0;
    /** Reads what is there without waiting: the byte count, 0 for none, -1 when lost. */
    virtual int read(std::uint8_t *buffer, int size, QString *error) = 0;
};

} // namespace semhap
