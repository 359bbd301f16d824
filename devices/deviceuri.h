// SPDX-License-Identifier: MIT
#pragma once

#include <QString>

#include <vector>

namespace semhap {

/**
 * Where a device is, as users write it: `virtual:NAME`, `serial:PATH[?baud=N]`,
 * `hid:VID:PID` (hex), `udp:HOST:PORT`, `audio:DEVICE[?channels=1,2&carrier=170]`. One
 * string names a band in options, bindings and settings.
 */
struct DeviceUri
{
    enum class Scheme
    {
        Virtual,
        Serial,
        Hid,
        Udp,
        Audio
    };

    /** The reference bands' rate (firmware/README.md): 250000 is exact on a 16 MHz AVR. */
    static constexpr int DefaultBaud = 250000;
    /** Hz: the resonance of the LRAs vibrotactile bands use. */
    static constexpr double DefaultCarrier = 170.0;

    Scheme scheme = Scheme::Virtual;
    QString name; ///< virtual: the name; serial: the path; udp: the host; audio: the output
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
    /**
     * `virtual:NAME`: where a router device `name` plays when no band is bound to it (its
     * frames show in the studio, nothing leaves the machine).
     */
    static QString virtualFor(const QString &name);
};

} // namespace semhap
