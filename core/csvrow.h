// SPDX-License-Identifier: MIT
#pragma once

#include <QByteArray>
#include <QString>

namespace semhap {

/** Builds CSV rows the way every semhap export writes them (RFC 4180, UTF-8). */
namespace CsvRow {

/** Appends a field: quoted when it holds a separator, a quote or a line break. */
void appendText(QByteArray &row, const QString &text);
/** Appends a number, exact (shortest round trip); nothing for NaN or infinity. */
void appendNumber(QByteArray &row, double value);

} // namespace CsvRow

} // namespace semhap
