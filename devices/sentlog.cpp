// SPDX-License-Identifier: MIT
#include "sentlog.h"

#include <algorithm>

namespace semhap {

SentLog::SentLog() : m_ring(size_t(Capacity)) {}

void SentLog::append(const DeviceFrame &frame)
{
    std::lock_guard<std::mutex> lock(m_mutex);
    m_ring[size_t(m_count % Capacity)] = frame;
    ++m_count;
}

std::uint64_t SentLog::count() const
{
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_count;
}

DeviceFrame SentLog::last() const
{
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_count > 0 ? m_ring[size_t((m_count - 1) % Capacity)] : DeviceFrame{};
}

std::uint64_t SentLog::readSince(std::uint64_t *next, std::vector<DeviceFrame> *out) const
{
    std::lock_guard<std::mutex> lock(m_mutex);
    const std::uint64_t oldest = m_count > std::uint64_t(Capacity) ? m_count - Capacity : 0;
    const std::uint64_t first = std::clamp(*next, oldest, m_count);
    for (std::uint64_t i = first; i < m_count; ++i)
        out->push_back(m_ring[size_t(i % Capacity)]);
    const std::uint64_t lost = first > *next ? first - *next : 0;
    *next = m_count;
    return lost;
}

} // namespace semhap
