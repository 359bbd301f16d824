// SPDX-License-Identifier: MIT
#include "sessionblock.h"

#include <zstd.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <utility>

namespace semhap {

namespace {

std::uint64_t bitsOf(double value)
{
    std::uint64_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    return bits;
}

double valueOf(std::uint64_t bits)
{
    double value;
    std::memcpy(&value, &bits, sizeof value);
    return value;
}

/**
 * Where each row's previous row of the same key is (-1 for the first of its key). Keys are
 * few (two grippers, a handful of devices): a short list beats a map.
 */
std::vector<int> previousOfKey(const std::vector<std::uint64_t> &keys)
{
    std::vector<std::pair<std::uint64_t, int>> latest;
    std::vector<int> previous(keys.size(), -1);
    for (size_t r = 0; r < keys.size(); ++r) {
        auto it = latest.begin();
        while (it != latest.end() && it->first != keys[r])
            ++it;
        if (it == latest.end()) {
            latest.emplace_back(keys[r], int(r));
        } else {
            previous[r] = it->second;
            it->second = int(r);
        }
    }
    return previous;
}

} // namespace

std::pair<double, double> SessionBlock::span(const std::vector<double> &rows, int width)
{
    std::pair<double, double> span{rows.at(0), rows.at(0)};
    for (size_t r = 0; r < rows.size(); r += size_t(width)) {
        span.first = std::min(span.first, rows[r]);
        span.second = std::max(span.second, rows[r]);
    }
    return span;
}

QByteArray SessionBlock::pack(const std::vector<double> &rows, int width, int keyColumn, int level)
{
    const size_t count = width > 0 ? rows.size() / size_t(width) : 0;
    std::vector<std::uint64_t> keys(count, 0);
    if (keyColumn >= 0) {
        for (size_t r = 0; r < count; ++r)
            keys[r] = bitsOf(rows[r * size_t(width) + size_t(keyColumn)]);
    }
    const std::vector<int> previous = previousOfKey(keys);
    QByteArray planes(qsizetype(rows.size() * 8), Qt::Uninitialized);
    auto *out = reinterpret_cast<unsigned char *>(planes.data());
    for (int c = 0; c < width; ++c) {
        unsigned char *column = out + size_t(c) * count * 8;
        for (size_t r = 0; r < count; ++r) {
            std::uint64_t bits = bitsOf(rows[r * size_t(width) + size_t(c)]);
            if (c != keyColumn && previous[r] >= 0)
                bits ^= bitsOf(rows[size_t(previous[r]) * size_t(width) + size_t(c)]);
            for (size_t b = 0; b < 8; ++b)
                column[b * count + r] = static_cast<unsigned char>(bits >> (8 * b));
        }
    }
    QByteArray packed(qsizetype(ZSTD_compressBound(size_t(planes.size()))), Qt::Uninitialized);
    const size_t size = ZSTD_compress(packed.data(), size_t(packed.size()), planes.constData(),
                                      size_t(planes.size()), level);
    if (ZSTD_isError(size))
        return QByteArray();
    packed.truncate(qsizetype(size));
    return packed;
}

bool SessionBlock::unpack(const QByteArray &data, int count, int width, int keyColumn,
                          std::vector<double> *rows, QString *reason)
{
    if (count < 1 || width < 1 || width > MaxWidth || qint64(count) * width > MaxValues) {
        *reason = QStringLiteral("a block of %1 rows of %2 values is outside the limits (%3 "
                                 "values, rows of at most %4)")
                      .arg(count)
                      .arg(width)
                      .arg(MaxValues)
                      .arg(MaxWidth);
        return false;
    }
    const size_t n = size_t(count) * size_t(width);
    if (keyColumn >= width) {
        *reason = QStringLiteral("a block of rows of %1 values has no key column %2")
                      .arg(width)
                      .arg(keyColumn);
        return false;
    }
    const unsigned long long size =
        ZSTD_getFrameContentSize(data.constData(), size_t(data.size()));
    if (size != n * 8) {
        *reason = size == ZSTD_CONTENTSIZE_ERROR || size == ZSTD_CONTENTSIZE_UNKNOWN
                      ? QStringLiteral("a block is not zstd data")
                      : QStringLiteral("a block unpacks to %1 bytes, not the %2 its rows need")
                            .arg(size)
                            .arg(n * 8);
        return false;
    }
    std::vector<unsigned char> planes(n * 8);
    const size_t got =
        ZSTD_decompress(planes.data(), planes.size(), data.constData(), size_t(data.size()));
    if (ZSTD_isError(got) || got != planes.size()) {
        *reason = QStringLiteral("a block does not unpack: ") +
                  QString::fromLatin1(ZSTD_isError(got) ? ZSTD_getErrorName(got) : "short");
        return false;
    }
    const auto bitsAt = [&](size_t r, int c) {
        const unsigned char *column = planes.data() + size_t(c) * size_t(count) * 8;
        std::uint64_t bits = 0;
        for (size_t b = 0; b < 8; ++b)
            bits |= std::uint64_t(column[b * size_t(count) + r]) << (8 * b);
        return bits;
    };
    std::vector<std::uint64_t> keys(size_t(count), 0);
    if (keyColumn >= 0) {
        for (size_t r = 0; r < size_t(count); ++r)
            keys[r] = bitsAt(r, keyColumn);
    }
    const std::vector<int> previous = previousOfKey(keys);
    rows->resize(n);
    for (size_t r = 0; r < size_t(count); ++r) {
        for (int c = 0; c < width; ++c) {
            std::uint64_t bits = bitsAt(r, c);
            if (c != keyColumn && previous[r] >= 0)
                bits ^= bitsOf((*rows)[size_t(previous[r]) * size_t(width) + size_t(c)]);
            (*rows)[r * size_t(width) + size_t(c)] = valueOf(bits);
        }
    }
    return true;
}

} // namespace semhap
