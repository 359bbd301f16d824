// SPDX-License-Identifier: MIT
#pragma once

#include "deviceframe.h"

#include <cstdint>
#include <mutex>
#include <vector>

namespace semhap {

/**
 * The frames a transport sent, as its device got them — after clamp, gain, inflation limit
 * and arming, a stop-all's rest values included — for readouts: meters and plots show these,
 * never what a caller asked for. The latest `Capacity` frames are kept in a ring and read by
 * running count, so each reader takes only what is new. Any thread; a tiny mutex held only
 * to copy.
 */
class SentLog
{
public:
    /** Frames kept: a studio reads them every display frame, at 100 times real time too. */
    static constexpr int Capacity = 4096;

    SentLog();

    /** Keeps `frame` as sent. */
    void append(const DeviceFrame &frame);
    /** Frames appended since construction. */
    std::uint64_t count() const;
    /** The latest frame sent; a default frame before the first. */
    DeviceFrame last() const;
    /**
     * Appends to `out` the frames sent from running count `*next` on (those still kept,
     * oldest first) and moves `*next` past them; returns how many were overwritten before
     * they could be read.
     */
    std::uint64_t readSince(std::uint64_t *next, std::vector<DeviceFrame> *out) const;

private:
    mutable std::mutex m_mutex;
    std::vector<DeviceFrame> m_ring;
    std::uint64_t m_count = 0;
};

} // namespace semhap
