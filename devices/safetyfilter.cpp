// SPDX-License-Identifier: MIT
#include "safetyfilter.h"

#include <algorithm>
#include <cmath>

namespace semhap {

SafetyFilter::SafetyFilter(DeviceModelPtr model) : m_model(std::move(model))
{
    const bool pneumatic = std::any_of(
        m_model->channels().begin(), m_model->channels().end(),
        [](const ChannelSpec &c) { return c.unit.contains(QLatin1String("pressure")); });
    if (!pneumatic)
        m_limit.seconds = 0.0;
}

void SafetyFilter::apply(const double *commanded, int count, double now, double gain, bool armed,
                         double *out)
{
    const int channels = std::min(m_model->channelCount(), MaxChannels);
    gain = std::isfinite(gain) ? std::clamp(gain, 0.0, 1.0) : 0.0;
    for (int c = 0; c < channels; ++c) {
        const ChannelSpec &spec = m_model->channels()[size_t(c)];
        const double range = spec.max - spec.min;
        const double v = m_model->clamp(c, c < count ? commanded[c] : spec.min);
        double safe = spec.min + (v - spec.min) * gain;
        ChannelState &state = m_channels[size_t(c)];
        if (m_limit.seconds > 0.0) {
            const double fraction = range > 0.0 ? (safe - spec.min) / range : 0.0;
            if (fraction > m_limit.threshold) {
                if (state.fullSince < 0.0)
                    state.fullSince = now;
                if (now - state.fullSince >= m_limit.seconds)
                    state.capped = true;
            } else {
                state.fullSince = -1.0;
                if (fraction <= m_limit.comfort)
                    state.capped = false;
            }
            if (state.capped)
                safe = std::min(safe, spec.min + range * m_limit.comfort);
        }
        out[c] = armed ? safe : spec.min;
    }
}

void SafetyFilter::reset()
{
    m_channels.fill({});
}

} // namespace semhap
