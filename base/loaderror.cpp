// SPDX-License-Identifier: MIT
#include "loaderror.h"

namespace semhap {

QString LoadError::toString() const
{
    QString where = file.isEmpty() ? QStringLiteral("<input>") : file;
    if (line > 0) {
        where += QLatin1Char(':') + QString::number(line);
        if (column > 0)
            where += QLatin1Char(':') + QString::number(column);
    } else if (!pointer.isEmpty()) {
        where += QStringLiteral(": ") + pointer;
    }
    return where + QStringLiteral(": ") + reason;
}

LoadError LoadError::at(const QString &file, const QString &pointer, const QString &reason)
{
    LoadError e;
    e.file = file;
    e.pointer = pointer;
    e.reason = reason;
    return e;
}

LoadError LoadError::atLine(const QString &file, int line, int column, const QString &reason)
{
    LoadError e;
    e.file = file;
    e.line = line;
    e.column = column;
    e.reason = reason;
    return e;
}

QString jsonPointerChild(const QString &pointer, const QString &token)
{
    QString escaped = token;
    escaped.replace(QLatin1Char('~'), QStringLiteral("~0"));
    escaped.replace(QLatin1Char('/'), QStringLiteral("~1"));
    return pointer + QLatin1Char('/') + escaped;
}

QString jsonPointerChild(const QString &pointer, int index)
{
    return pointer + QLatin1Char('/') + QString::number(index);
}

} // namespace semhap
