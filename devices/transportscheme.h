// SPDX-License-Identifier: MIT
#pragma once

#include "deviceuri.h"
#include "transport.h"

#include <QString>

#include <memory>
#include <vector>

namespace semhap {

class Link;

/** Something a transport could be made for, as listed to the user. */
struct PortInfo
{
    QString uri;         ///< ready for --device / --bind
    QString kind;        ///< its scheme: "serial", "hid", "audio", "virtual", "udp", …
    QString description; ///< what the system says it is (audio: the host API)
    int vendorId = -1;   ///< USB only
    int productId = -1;
    int outputChannels = -1; ///< sound cards only
    double sampleRate = 0.0; ///< sound cards only: Hz
};

/**
 * A kind of device address (`serial:`, `udp:`, …) as one registered row: how users write it,
 * how it is read and spelled, what it makes and what of it is present. The URI parser, the
 * transport factory, the device listing, `semhap devices` and `play --device`, the Devices
 * panel and the documentation's check all read this table; a new transport is its own files
 * plus one row in transportscheme.cpp.
 */
struct TransportScheme
{
    const char *name = "";   ///< before the colon: "serial"
    const char *syntax = ""; ///< as users write it: "serial:PATH[?baud=N]"
    const char *help = "";   ///< one line for `semhap devices` (what it reaches, its defaults)
    /** Reads what follows `name:` into `uri`; false with a reason that names the wrong part. */
    bool (*parse)(const QString &address, DeviceUri *uri, QString *error) = nullptr;
    /** What follows `name:` in the canonical spelling; parse() reads it back unchanged. */
    QString (*format)(const DeviceUri &uri) = nullptr;
    /** Whether `uri` can drive `model`, false with a reason; null: any model. */
    bool (*fits)(const DeviceUri &uri, const DeviceModel &model, QString *error) = nullptr;
    /** The byte link to a band at `uri`, not opened; null for the schemes that are no link. */
    std::unique_ptr<Link> (*link)(const DeviceUri &uri) = nullptr;
    /** The transport of a scheme that is no link (virtual, audio); null for links. */
    std::unique_ptr<Transport> (*transport)(const DeviceUri &uri, DeviceModelPtr model) = nullptr;
    /** Appends what of this kind is present now; null for the kinds nothing discovers. */
    void (*present)(std::vector<PortInfo> *out) = nullptr;

    /** Every scheme, in the order `semhap devices` lists them. */
    static const std::vector<TransportScheme> &all();
    /** The row named `name`, or null. */
    static const TransportScheme *find(const QString &name);
    /** The names, comma-separated, for messages ("virtual, serial, …"). */
    static QString names();
};

} // namespace semhap
