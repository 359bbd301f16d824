// SPDX-License-Identifier: MIT
#pragma once

#include <QString>

namespace semhap {

/**
 * Where a device is, as users write it: `virtual:NAME`, `serial:PATH[?baud=N]`,
 * `hid:VID:PID` (hex), `udp:HOST:PORT`. One string names a band in options, bindings and
 * settings.
 */
struct DeviceUri
{
    enum class Scheme
    {
        Virtual,
        Serial,
        Hid,
        Udp
    };

    /** The reference bands' rate (firmware/README.md): 250000 is exact on a 16 MHz AVR. */
    static constexpr int DefaultBaud = 250000;

    Scheme scheme = Scheme::Virtual;
    QString name; ///< virtual: the name; serial: the path; udp: the host
    int baud = DefaultBaud;
    int vendorId = 0;
    int productId = 0;
    int port = 0;

    /** Parses `text`; false with a reason that names the part that is wrong. */
    static bool parse(const QString &text, DeviceUri *uri, QString *error);
    /** The canonical spelling (hex IDs with four digits, baud only when not the default). */
    QString toString() const;
    /**
     * `virtual:NAME`: where a router device `name` plays when no band is bound to it (its
     * frames show in the studio, nothing leaves the machine).
     */
    static QString virtualFor(const QString &name);
};

} // namespace semhap
