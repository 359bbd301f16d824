// SPDX-License-Identifier: MIT
#include "csvrow.h"

#include "jsonlineswriter.h"

#include <cmath>

namespace semhap {

void CsvRow::appendText(QByteArray &row, const QString &text)
{
    const QByteArray utf8 = text.toUtf8();
    if (utf8.contains(',') || utf8.contains('"') || utf8.contains('\n') || utf8.contains('\r')) {
        row += '"';
        row += QByteArray(utf8).replace('"', "\"\"");
        row += '"';
    } else {
        row += utf8;
    }
}

void CsvRow::appendNumber(QByteArray &row, double value)
{
    if (std::isfinite(value))
        JsonLinesWriter::appendNumber(row, value);
}

} // namespace semhap
