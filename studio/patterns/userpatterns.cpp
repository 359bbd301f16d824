// SPDX-License-Identifier: MIT
#include "userpatterns.h"

#include <QDir>
#include <QStandardPaths>

namespace semhap {

QString userPatternFolder()
{
    return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) +
           QStringLiteral("/patterns");
}

QStringList userPatternFiles()
{
    const QDir folder(userPatternFolder());
    QStringList files;
    for (const QString &name :
         folder.entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name))
        files.append(folder.filePath(name));
    return files;
}

} // namespace semhap
