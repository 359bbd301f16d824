// SPDX-License-Identifier: MIT
#include "conditionorder.h"

#include "random.h"

#include <algorithm>
#include <numeric>

namespace semhap {

namespace {

/**
 * Williams' square for n conditions: the first row 0, 1, n-1, 2, n-2, …, each next row the
 * previous one plus 1 (mod n). For an even n every condition follows every other exactly once.
 */
std::vector<std::vector<int>> williams(int n)
{
    std::vector<int> first;
    for (int k = 0, low = 1, high = n - 1; k < n; ++k) {
        if (k == 0)
            first.push_back(0);
        else if (k % 2 == 1)
            first.push_back(low++);
        else
            first.push_back(high--);
    }
    std::vector<std::vector<int>> rows;
    for (int r = 0; r < n; ++r) {
        std::vector<int> row;
        for (int c : first)
            row.push_back((c + r) % n);
        rows.push_back(row);
    }
    return rows;
}

} // namespace

ConditionOrder::ConditionOrder(Scheme scheme, int conditions, std::uint64_t seed)
    : m_scheme(scheme), m_conditions(conditions), m_seed(seed)
{
    if (scheme == Scheme::Random || conditions < 1)
        return;
    m_rows = williams(conditions);
    if (conditions % 2 == 1) {
        // An odd square is balanced for carry-over only with its mirror image beside it.
        const std::vector<std::vector<int>> square = m_rows;
        for (std::vector<int> row : square) {
            std::reverse(row.begin(), row.end());
            m_rows.push_back(row);
        }
    }
}

bool ConditionOrder::accepts(Scheme scheme, int conditions)
{
    return conditions >= 1 && (scheme != Scheme::Williams || conditions % 2 == 0);
}

std::vector<int> ConditionOrder::order(int participant) const
{
    if (m_scheme != Scheme::Random)
        return m_rows.empty() ? std::vector<int>() : m_rows[size_t(participant) % m_rows.size()];
    // A Fisher-Yates shuffle from the study's seed and the participant's place: the same
    // participant gets the same order on any machine.
    std::vector<int> order(size_t(std::max(0, m_conditions)));
    std::iota(order.begin(), order.end(), 0);
    Random random(m_seed * 1000003u + std::uint64_t(participant));
    for (size_t i = order.size(); i > 1; --i)
        std::swap(order[i - 1], order[size_t(random.next() % i)]);
    return order;
}

} // namespace semhap
