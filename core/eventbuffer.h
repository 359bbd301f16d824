// SPDX-License-Identifier: MIT
#pragma once

#include "semanticevent.h"

#include <array>

namespace semhap {

/**
 * A fixed-capacity list of the events of one tick. A detector produces at most four per
 * tick (two ends of a reset, two begins), so this never fills in practice; overflow drops
 * the event and counts it rather than allocating.
 */
class EventBuffer
{
public:
    static constexpr int Capacity = 32;

    void clear() { m_size = 0; }
    void push(const SemanticEvent &event)
    {
        if (m_size < Capacity)
            m_events[size_t(m_size++)] = event;
        else
            ++m_dropped;
    }
    int size() const { return m_size; }
    bool isEmpty() const { return m_size == 0; }
    const SemanticEvent &operator[](int i) const { return m_events[size_t(i)]; }
    const SemanticEvent *begin() const { return m_events.data(); }
    const SemanticEvent *end() const { return m_events.data() + m_size; }
    int dropped() const { return m_dropped; }

private:
    std::array<SemanticEvent, Capacity> m_events{};
    int m_size = 0;
    int m_dropped = 0;
};

} // namespace semhap
