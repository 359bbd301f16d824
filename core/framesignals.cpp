// SPDX-License-Identifier: MIT
#include "framesignals.h"

namespace semhap {

bool FrameSignals::set(int id, double value)
{
    for (SignalValue &signal : m_values) {
        if (signal.id == id) {
            signal.value = value;
            return true;
        }
    }
    if (size() >= Capacity)
        return false;
    m_values.push_back({id, value});
    return true;
}

const double *FrameSignals::find(int id) const
{
    // Linear: a frame carries a handful of signals, and this is what the router reads.
    for (const SignalValue &signal : m_values) {
        if (signal.id == id)
            return &signal.value;
    }
    return nullptr;
}

bool FrameSignals::operator==(const FrameSignals &other) const
{
    if (m_values.size() != other.m_values.size())
        return false;
    for (const SignalValue &signal : m_values) {
        const double *value = other.find(signal.id);
        if (!value || *value != signal.value)
            return false;
    }
    return true;
}

} // namespace semhap
