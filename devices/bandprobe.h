// SPDX-License-Identifier: MIT
#pragma once

#include "protocol.h"

#include <QString>

namespace semhap {

/** What a band says about itself when asked. */
struct BandReport
{
    protocol::Identity identity;   ///< model, firmware version and channels
    protocol::DeviceStatus status; ///< its counters, the probe's own frames included
};

/**
 * Asks a band on a link who it is and how its link has been (an identify request and a
 * status request), as `semhap devices --probe` does: a look at a band without driving it.
 */
class BandProbe
{
public:
    /**
     * Opens `uri`, asks, and waits up to `timeout` seconds for both replies; false with
     * `URI: reason` (a malformed URI, a link that does not open, no answer).
     */
    static bool probe(const QString &uri, double timeout, BandReport *report, QString *error);
};

} // namespace semhap
