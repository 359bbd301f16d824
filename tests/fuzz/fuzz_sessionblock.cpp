// SPDX-License-Identifier: MIT
// A session's blocks (schema 5) are read from files anyone may have written: any bytes, with
// any row count, width and key column, unpack to exactly that many numbers or are refused
// with a reason, in bounded memory, never a crash; what unpacks packs and unpacks again to
// the same bits.
#include "sessionblock.h"

#include <cstdlib>
#include <cstring>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 5)
        return 0;
    // The block's row in the table: rows and width as a session may claim them.
    const int count = data[0] | data[1] << 8;
    const int width = (data[2] | data[3] << 8) % 64;
    const int keyColumn = int(data[4] % 4) - 1;
    const QByteArray bytes(reinterpret_cast<const char *>(data + 5), qsizetype(size - 5));
    std::vector<double> rows;
    QString reason;
    if (!semhap::SessionBlock::unpack(bytes, count, width, keyColumn, &rows, &reason)) {
        if (reason.isEmpty())
            std::abort();
        return 0;
    }
    if (rows.size() != size_t(count) * size_t(width))
        std::abort();
    std::vector<double> again;
    if (!semhap::SessionBlock::unpack(semhap::SessionBlock::pack(rows, width, keyColumn, 1), count,
                                      width, keyColumn, &again, &reason) ||
        std::memcmp(again.data(), rows.data(), rows.size() * sizeof(double)) != 0)
        std::abort();
    return 0;
}
