// SPDX-License-Identifier: MIT
#pragma once

#include <chrono>
#include <cstdint>

namespace semhap {

/** Seconds on the steady clock: what timeouts, rates and the inflation limit measure. */
inline double monotonicSeconds()
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

/** Microseconds on the steady clock: heartbeat timestamps. */
inline std::uint64_t monotonicMicros()
{
    return std::uint64_t(std::chrono::duration_cast<std::chrono::microseconds>(
                             std::chrono::steady_clock::now().time_since_epoch())
                             .count());
}

} // namespace semhap
