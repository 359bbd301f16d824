// SPDX-License-Identifier: MIT
#include "bandprobe.h"

#include "framedecoder.h"
#include "monotonic.h"
#include "transportfactory.h"

#include <array>
#include <cmath>
#include <poll.h>

namespace semhap {

namespace {

/** How often the requests go again while the band has not answered (s). */
constexpr double AskPeriod = 0.2;

} // namespace

bool BandProbe::probe(const QString &uri, double timeout, BandReport *report, QString *error)
{
    DeviceUri parsed;
    if (!DeviceUri::parse(uri, &parsed, error))
        return false;
    const std::unique_ptr<Link> link = TransportFactory::createLink(parsed);
    if (!link) {
        *error = QStringLiteral("%1: no band on a link there to answer (a virtual band or a "
                                "sound output)")
                     .arg(uri);
        return false;
    }
    QString reason;
    if (!link->open(&reason)) {
        *error = QStringLiteral("%1: cannot open: %2").arg(uri, reason);
        return false;
    }
    // Two delimiters first, as every host starts: the band drops whatever half-frame it
    // holds and starts counting our numbers afresh. Then the two requests, a frame per
    // write (a HID report never carries two).
    std::array<QByteArray, 3> frames{QByteArray(2, '\0'), QByteArray(), QByteArray()};
    protocol::Message request;
    request.type = protocol::MessageType::IdentifyRequest;
    protocol::encode(request, &frames[1]);
    request.type = protocol::MessageType::StatusRequest;
    request.sequence = 1;
    protocol::encode(request, &frames[2]);
    const auto ask = [&]() {
        for (const QByteArray &frame : frames) {
            if (!link->writeFrame(reinterpret_cast<const std::uint8_t *>(frame.constData()),
                                  int(frame.size()), &reason)) {
                *error = QStringLiteral("%1: cannot write: %2").arg(uri, reason);
                return false;
            }
        }
        return true;
    };
    bool identified = false;
    bool counted = false;
    FrameDecoder decoder;
    std::array<std::uint8_t, 1024> buffer{};
    const double deadline = monotonicSeconds() + timeout;
    double askAt = monotonicSeconds();
    while (!(identified && counted) && monotonicSeconds() < deadline) {
        // Asked again until answered: opening an Arduino's port resets it, and its boot
        // loader takes what comes first. Each time after the two delimiters: no gap counted.
        if (monotonicSeconds() >= askAt) {
            if (!ask())
                return false;
            askAt = monotonicSeconds() + AskPeriod;
        }
        // Links without a descriptor (HID) are read every 2 ms.
        pollfd fd{link->pollFd(), POLLIN, 0};
        const double left = std::max(0.0, std::min(deadline, askAt) - monotonicSeconds());
        ::poll(&fd, 1, fd.fd >= 0 ? int(std::ceil(left * 1000.0)) : 2);
        const int n = link->read(buffer.data(), int(buffer.size()), &reason);
        if (n < 0) {
            *error = QStringLiteral("%1: lost: %2").arg(uri, reason);
            return false;
        }
        decoder.feed(buffer.data(), size_t(n), [&](const protocol::Message &m) {
            if (m.type == protocol::MessageType::IdentifyReply) {
                report->identity = m.identity;
                identified = true;
            } else if (m.type == protocol::MessageType::Status && m.status.acknowledged == 1) {
                report->status = m.status;
                counted = true;
            }
        });
    }
    if (!identified || !counted) {
        *error =
            QStringLiteral("%1: no %2 within %3 s")
                .arg(uri, identified ? QStringLiteral("status reply") : QStringLiteral("answer"))
                .arg(timeout);
        return false;
    }
    return true;
}

} // namespace semhap
