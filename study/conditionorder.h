// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <vector>

namespace semhap {

/**
 * The order in which each participant meets a study's conditions (docs/studies.md, "Orders"):
 * a balanced Latin square, Williams' design (each condition follows each other once as often
 * as any), or a seeded shuffle per participant. Conditions are indices 0..n-1.
 */
class ConditionOrder
{
public:
    enum class Scheme
    {
        Williams,
        Latin,
        Random
    };

    ConditionOrder(Scheme scheme, int conditions, std::uint64_t seed = 1);

    /**
     * The sequences the design cycles through (Williams: n rows for an even n; Latin: the
     * Williams rows for an even n, the square and its mirror, 2n rows, for an odd n);
     * empty for Random.
     */
    const std::vector<std::vector<int>> &rows() const { return m_rows; }
    /** The order for the participant added `participant`-th (0-based). */
    std::vector<int> order(int participant) const;
    /** Whether the scheme can order `conditions` conditions (Williams needs an even count). */
    static bool accepts(Scheme scheme, int conditions);

private:
    Scheme m_scheme;
    int m_conditions;
    std::uint64_t m_seed;
    std::vector<std::vector<int>> m_rows;
};

} // namespace semhap
