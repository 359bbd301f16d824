// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>

namespace semhap {

/**
 * A small seeded generator (SplitMix64) with the few distributions operators need. Our own,
 * not <random>'s distributions, so a seed gives the same run with any standard library.
 */
class Random
{
public:
    explicit Random(std::uint64_t seed) : m_state(seed) {}

    std::uint64_t next();
    /** Uniform in [0, 1). */
    double uniform();
    double uniform(double low, double high) { return low + (high - low) * uniform(); }
    /** Normal (Box-Muller). */
    double normal(double mean, double sd);

private:
    std::uint64_t m_state;
};

} // namespace semhap
