// SPDX-License-Identifier: MIT
#pragma once

#include "deviceframe.h"
#include "devicemodel.h"

#include <array>

namespace semhap {

/** The comfort limit on continuous full inflation (pneumatic bands on a wrist for an hour). */
struct InflationLimit
{
    double seconds = 60.0;  ///< how long a channel may stay above `threshold`; 0 disables
    double threshold = 0.9; ///< fraction of the channel's range that counts as "full"
    double comfort = 0.6;   ///< fraction of the range the value is capped to afterwards
};

/**
 * The last word before values leave the host: clamp to the model's limits (never trust the
 * caller), scale by the master gain, cap continuous full inflation, and send zeros unless
 * armed. Plain value; the transport's I/O thread owns one.
 */
class SafetyFilter
{
public:
    /** Pneumatic models (channels in units of pressure) get the inflation limit by default. */
    explicit SafetyFilter(DeviceModelPtr model);

    void setInflationLimit(const InflationLimit &limit) { m_limit = limit; }
    const InflationLimit &inflationLimit() const { return m_limit; }

    /**
     * Safe values for `commanded` (`count` channels, model units) at time `now` (s, any
     * monotonic clock), into `out` (the model's channel count).
     */
    void apply(const double *commanded, int count, double now, double gain, bool armed,
               double *out);
    /** True while a channel is held at the comfort level. */
    bool isCapped(int channel) const { return m_channels[size_t(channel)].capped; }
    /** Forgets inflation history (after a stop-all or a reconnect). */
    void reset();

private:
    struct ChannelState
    {
        double fullSince = -1.0; ///< when the value went above the threshold; < 0: it is not
        bool capped = false;
    };

    DeviceModelPtr m_model;
    InflationLimit m_limit;
    std::array<ChannelState, MaxChannels> m_channels{};
};

} // namespace semhap
