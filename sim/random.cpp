// SPDX-License-Identifier: MIT
#include "random.h"

#include <cmath>

namespace semhap {

std::uint64_t Random::next()
{
    std::uint64_t z = (m_state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

double Random::uniform()
{
    return double(next() >> 11) * 0x1.0p-53;
}

double Random::normal(double mean, double sd)
{
    constexpr double Pi = 3.14159265358979323846;
    const double u = 1.0 - uniform(); // (0, 1]: log(u) is finite
    const double v = uniform();
    return mean + sd * std::sqrt(-2.0 * std::log(u)) * std::cos(2.0 * Pi * v);
}

} // namespace semhap
