// SPDX-License-Identifier: MIT
#pragma once

#include <QByteArray>
#include <QFile>
#include <QString>

/** The bytes of a file; empty when it cannot be read (the test's comparison says so). */
inline QByteArray readAll(const QString &path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

/** An example study protocol shipped in resources/studies. */
inline QString example(const char *name)
{
    return QStringLiteral(SEMHAP_RESOURCES "/studies/") + QLatin1String(name);
}
