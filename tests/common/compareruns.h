// SPDX-License-Identifier: MIT
#pragma once

#include <QByteArray>
#include <QStringList>

/**
 * A `semhap compare` CSV's rows without its wall-clock columns (`wall_seconds` and
 * `realtime_factor`, the last two), sorted: what a merged compare must share with the
 * one-machine compare, whatever slice ran each run (docs/cluster.md).
 */
inline QStringList compareRuns(const QByteArray &csv)
{
    QStringList lines;
    for (const QByteArray &line : csv.trimmed().split('\n'))
        lines.append(QString::fromUtf8(line).section(QLatin1Char(','), 0, -3));
    lines.sort();
    return lines;
}
