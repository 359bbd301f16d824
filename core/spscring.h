// SPDX-License-Identifier: MIT
#pragma once

#include <atomic>
#include <cstddef>
#include <vector>

namespace semhap {

/**
 * A bounded single-producer, single-consumer queue without locks: the pipeline thread
 * pushes, the GUI thread pops at display rate (the studio's feed); a sender hands
 * envelopes to an audio callback, which may neither lock nor wait (`devices/`). A full
 * queue refuses the value (the caller counts it) rather than making the producer wait.
 */
template<typename T> class SpscRing
{
public:
    /** Holds up to `capacity` values (rounded up to a power of two). */
    explicit SpscRing(std::size_t capacity)
    {
        std::size_t size = 2;
        while (size < capacity + 1)
            size *= 2;
        m_slots.resize(size);
        m_mask = size - 1;
    }

    /** Producer thread only. False when the queue is full. */
    bool push(const T &value)
    {
        const std::size_t head = m_head.load(std::memory_order_relaxed);
        const std::size_t next = (head + 1) & m_mask;
        if (next == m_tail.load(std::memory_order_acquire))
            return false;
        m_slots[head] = value;
        m_head.store(next, std::memory_order_release);
        return true;
    }

    /** Consumer thread only. False when the queue is empty. */
    bool pop(T *value)
    {
        const std::size_t tail = m_tail.load(std::memory_order_relaxed);
        if (tail == m_head.load(std::memory_order_acquire))
            return false;
        *value = m_slots[tail];
        m_tail.store((tail + 1) & m_mask, std::memory_order_release);
        return true;
    }

    /** Values queued now; exact on the consumer thread, a snapshot on any other. */
    std::size_t size() const
    {
        return (m_head.load(std::memory_order_acquire) - m_tail.load(std::memory_order_acquire)) &
               m_mask;
    }

private:
    std::vector<T> m_slots;
    std::size_t m_mask = 0;
    // On separate cache lines, so producer and consumer do not slow each other down.
    alignas(64) std::atomic<std::size_t> m_head{0};
    alignas(64) std::atomic<std::size_t> m_tail{0};
};

} // namespace semhap
