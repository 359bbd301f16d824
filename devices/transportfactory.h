// SPDX-License-Identifier: MIT
#pragma once

#include "deviceuri.h"
#include "link.h"
#include "transport.h"

#include <memory>

namespace semhap {

/** Makes the transport a URI names, so callers never name a link class. */
class TransportFactory
{
public:
    /** A transport for `uri` driving `model` (not opened yet); null with `error`. */
    static std::unique_ptr<Transport> create(const QString &uri, DeviceModelPtr model,
                                             QString *error);
    /** The same for a parsed URI the caller knows fits `model` (the form above checks). */
    static std::unique_ptr<Transport> create(const DeviceUri &uri, DeviceModelPtr model);
    /**
     * The byte link to a band at `uri`, not opened; null for `virtual:` and `audio:`, which
     * have none (nothing there answers).
     */
    static std::unique_ptr<Link> createLink(const DeviceUri &uri);
};

} // namespace semhap
