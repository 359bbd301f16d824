// SPDX-License-Identifier: MIT
#pragma once

#include <QString>

#include <vector>

namespace semhap {

/**
 * Where a device is, as users write it: `SCHEME:ADDRESS`, the schemes being the rows of
 * TransportScheme (`virtual:NAME`, `serial:PATH[?baud=N]`, `udp:HOST:PORT`, …). One string
 * names a band in options, bindings and settings; the fields are the parts the schemes'
 * addresses are made of.
 */
struct DeviceUri
{
    /** The reference bands' rate (firmware/README.md): 250000 is exact on a 16 MHz AVR. */
    static constexpr int DefaultBaud = 250000;
    /** Hz: the resonance of the LRAs vibrotactile bands use. */
    static constexpr double DefaultCarrier = 170.0;

    QString scheme = QStringLiteral("virtual"); ///< a TransportScheme's name
    QString name; ///< virtual: the name; serial: the path; udp, tcp: the host; audio: the output
    int baud = DefaultBaud;
    int vendorId = 0;
    int productId = 0;
    int port = 0;
    /** audio: the card's output channel (from 1) of each model channel; empty: 1, 2, … */
    std::vector<int> outputChannels;
    /** audio: the carrier (Hz), one for all channels or one per channel; empty: 170 Hz */
    std::vector<double> carriers;

    /** Parses `text`; false with a reason that names the part that is wrong. */
    static bool parse(const QString &text, DeviceUri *uri, QString *error);
    /** The canonical spelling (hex IDs with four digits, baud only when not the default). */
    QString toString() const;
    /** `HOST:PORT` (an IPv6 host in brackets) into name and port: the network schemes' address. */
    static bool parseHostPort(const QString &address, DeviceUri *uri, QString *error);
    /** The same, spelled: brackets around an IPv6 host. */
    static QString formatHostPort(const DeviceUri &uri);
    /** `SCHEME:HOST:PORT` as a network link names itself (udp, tcp). */
    static QString hostPortUri(const QString &scheme, const QString &host, int port);
    /**
     * `virtual:NAME`: where a router device `name` plays when no band is bound to it (its
     * frames show in the studio, nothing leaves the machine).
     */
    static QString virtualFor(const QString &name);
};

} // namespace semhap
