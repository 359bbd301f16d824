// SPDX-License-Identifier: MIT
#pragma once

#include <QByteArray>
#include <QString>

#include <utility>
#include <vector>

namespace semhap {

/**
 * A block of one session stream's rows as schema 5 stores them (docs/sessions.md): `count`
 * rows of `width` float64 values, row by row. Packed, each value is XORed with the same
 * column of the previous row of its key (the value of column `keyColumn`, stored as is; -1
 * for a stream with one key), the columns are laid out one after another in eight byte
 * planes, and the whole is compressed with zstd. A value that did not change packs to
 * zero bytes, and unpacking gives back every bit, NaN and -0 included.
 */
class SessionBlock
{
public:
    /** The most values (count × width) a block may hold: 32 MB unpacked. */
    static constexpr int MaxValues = 1 << 22;
    /** The widest row a block may hold (a scene state's pose is most of it). */
    static constexpr int MaxWidth = 1 << 16;

    /** The least and greatest of the rows' first numbers (their `t`): a block's `first`, `last`.
     */
    static std::pair<double, double> span(const std::vector<double> &rows, int width);
    /** Packs `rows` (count × width values) at zstd `level`; empty when zstd fails. */
    static QByteArray pack(const std::vector<double> &rows, int width, int keyColumn, int level);
    /**
     * Unpacks `data` into `rows`, which must come to `count` × `width` values; false with a
     * one-sentence `reason` for a block that does not (a damaged file).
     */
    static bool unpack(const QByteArray &data, int count, int width, int keyColumn,
                       std::vector<double> *rows, QString *reason);
};

} // namespace semhap
