// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <cstdint>

namespace semhap {

/**
 * Frames per second over the last second, from a running count sampled every 100 ms or
 * more: what every transport's status reads. From the first 100 ms on it tells how fast
 * frames come, and it falls to 0 within a second once they stop — a count over fixed
 * one-second windows read 0 for a whole second after a connect and went stale between.
 */
class FrameRate
{
public:
    /** Notes the running count `total` at `now` (s); call as often as convenient. */
    void record(std::uint64_t total, double now);
    /** Frames per second over the last second up to `now`, `total` frames counted by then. */
    double perSecond(std::uint64_t total, double now) const;

private:
    struct Sample
    {
        double t = 0.0;
        std::uint64_t total = 0;
    };
    static constexpr double Spacing = 0.1; ///< s between kept samples
    static constexpr double Window = 1.0;  ///< s the rate is averaged over
    /** A second's worth of samples and one more, to reach back a whole second. */
    std::array<Sample, 12> m_samples{};
    int m_count = 0;
    int m_newest = -1;
};

} // namespace semhap
