// SPDX-License-Identifier: MIT
#include "hidreport.h"

#include <algorithm>
#include <cstring>

namespace semhap {
namespace hidreport {

int pack(const std::uint8_t *data, int size, std::uint8_t *report)
{
    const int n = std::clamp(size, 0, DataPerReport);
    std::memset(report, 0, ReportSize);
    report[0] = ReportId;
    report[1] = std::uint8_t(n);
    if (n > 0)
        std::memcpy(report + 2, data, size_t(n));
    return n;
}

int unpack(const std::uint8_t *report, int size, const std::uint8_t **data)
{
    if (size < 2 || report[0] != ReportId || report[1] > DataPerReport || report[1] > size - 2)
        return -1;
    *data = report + 2;
    return report[1];
}

} // namespace hidreport
} // namespace semhap
