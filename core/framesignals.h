// SPDX-License-Identifier: MIT
#pragma once

#include <vector>

namespace semhap {

/** One named scalar of a contact frame: its signalNames() id and value. */
struct SignalValue
{
    int id = -1;
    double value = 0.0;
};

/**
 * The named scalar signals a contact frame carries for its gripper (docs/streams.md,
 * "Signals"): at most Capacity, each name once, finite values. Names are ids in
 * signalNames(), so a frame holds no strings; a frame without signals holds no memory, and
 * setting the same signals again (a simulation step) reuses what it holds.
 */
class FrameSignals
{
public:
    /** The most signals one frame may carry. */
    static constexpr int Capacity = 64;

    /** Sets signal `id` to `value`, adding it when new; false when the frame is full. */
    bool set(int id, double value);
    /** The value of signal `id`, or null when the frame does not carry it. */
    const double *find(int id) const;
    void clear() { m_values.clear(); }
    int size() const { return int(m_values.size()); }
    bool isEmpty() const { return m_values.empty(); }
    std::vector<SignalValue>::const_iterator begin() const { return m_values.begin(); }
    std::vector<SignalValue>::const_iterator end() const { return m_values.end(); }

    bool operator==(const FrameSignals &other) const;
    bool operator!=(const FrameSignals &other) const { return !(*this == other); }

private:
    std::vector<SignalValue> m_values; ///< in the order they were first set
};

} // namespace semhap
