// SPDX-License-Identifier: MIT
#pragma once

#include "fdlink.h"

namespace semhap {

/**
 * A band behind a TCP port: a serial band shared from another machine by ser2net or socat
 * (raw mode), or a Wi-Fi board serving the protocol on a socket. The bytes are a serial
 * stream's; Nagle's delay is off, since a frame held back behind the previous one is late.
 * The server closing the connection is a lost link, reopened as a pulled cable is.
 */
class TcpLink : public FdLink
{
public:
    /** How long open() waits for a connection before the transport tries again. */
    static constexpr int ConnectTimeoutMs = 200;

    TcpLink(const QString &host, int port);

    QString uri() const override;
    bool open(QString *error) override;
    /**
     * A full send buffer drops the frame; one that takes only part of it loses the link
     * (the rest would misframe the stream), so the band stopped reading is reconnected.
     */
    bool writeFrame(const std::uint8_t *data, int size, QString *error) override;
    /** As FdLink's, but the end of the stream is the link lost, not "no data". */
    int read(std::uint8_t *buffer, int size, QString *error) override;

private:
    QString m_host;
    int m_port;
};

} // namespace semhap
