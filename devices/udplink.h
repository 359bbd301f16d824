// SPDX-License-Identifier: MIT
#pragma once

#include "fdlink.h"

namespace semhap {

/**
 * A band on Wi-Fi: a connected UDP socket, one datagram per frame. Connectionless, so it
 * is "open" as soon as the address resolves; whether a band listens shows in the
 * transport's `responding`.
 */
class UdpLink : public FdLink
{
public:
    UdpLink(const QString &host, int port);

    QString uri() const override;
    bool open(QString *error) override;

private:
    QString m_host;
    int m_port;
};

} // namespace semhap
