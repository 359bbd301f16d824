// SPDX-License-Identifier: MIT
#include "framerate.h"

#include <cstddef>

namespace semhap {

void FrameRate::record(std::uint64_t total, double now)
{
    if (m_count > 0 && now - m_samples[std::size_t(m_newest)].t < Spacing)
        return;
    m_newest = (m_newest + 1) % int(m_samples.size());
    m_samples[std::size_t(m_newest)] = {now, total};
    if (m_count < int(m_samples.size()))
        ++m_count;
}

double FrameRate::perSecond(std::uint64_t total, double now) const
{
    if (m_count == 0)
        return 0.0;
    // The newest sample a whole second old, or the oldest there is.
    int base = (m_newest - m_count + 1 + int(m_samples.size())) % int(m_samples.size());
    for (int i = 0; i < m_count; ++i) {
        const int k = (m_newest - i + int(m_samples.size())) % int(m_samples.size());
        if (now - m_samples[std::size_t(k)].t >= Window) {
            base = k;
            break;
        }
    }
    const Sample &from = m_samples[std::size_t(base)];
    const double span = now - from.t;
    if (span < Spacing)
        return 0.0; // too soon to tell
    return double(total - from.total) / span;
}

} // namespace semhap
