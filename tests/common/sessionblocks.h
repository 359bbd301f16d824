// SPDX-License-Identifier: MIT
#pragma once

#include "sessionblock.h"
#include "sessionschema.h"

#include <QString>

#include <limits>
#include <vector>

/**
 * The SQL that adds a block of `rows` (row by row, `width` numbers each) to a session's
 * `blocks` table as stream `stream`: how a test writes rows the writer never would.
 */
inline QString insertBlock(semhap::SessionSchema::Stream stream, const std::vector<double> &rows,
                           int width)
{
    const auto [first, last] = semhap::SessionBlock::span(rows, width);
    const QByteArray data =
        semhap::SessionBlock::pack(rows, width, semhap::SessionSchema::keyColumn(stream), 3);
    return QStringLiteral("INSERT INTO blocks VALUES ('%1', %2, %3, %4, %5, x'%6')")
        .arg(QLatin1String(semhap::SessionSchema::streamName(stream)))
        .arg(first, 0, 'g', 17)
        .arg(last, 0, 'g', 17)
        .arg(rows.size() / size_t(width))
        .arg(width)
        .arg(QString::fromLatin1(data.toHex()));
}

/** A contact frame row with no contact: gripper `gripper` (0 left, 1 right) at `t`. */
inline std::vector<double> emptyContactRow(double t, double gripper)
{
    const double unknown = std::numeric_limits<double>::quiet_NaN();
    return {t,   gripper, unknown,                                  // t, gripper, arrival
            0.0, 0.0,     -1.0,    unknown, unknown, unknown, 0.0,  // left: f, n, actor, fxyz, mu
            0.0, 0.0,     -1.0,    unknown, unknown, unknown, 0.0}; // right
}
