// SPDX-License-Identifier: MIT
#include "gripperlibrary.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QStandardPaths>

namespace semhap {

QStringList GripperLibrary::folders()
{
    const QStringList places{
        QStandardPaths::writableLocation(QStandardPaths::GenericDataLocation) +
            QStringLiteral("/semhap/grippers"),
        QDir(QCoreApplication::applicationDirPath())
            .filePath(QStringLiteral(SEMHAP_GRIPPERS_FROM_BINARY)),
        QStringLiteral(SEMHAP_SOURCE_GRIPPERS)};
    QStringList found;
    for (const QString &place : places) {
        const QFileInfo info(place);
        if (info.isDir() && !found.contains(info.canonicalFilePath()))
            found.append(info.canonicalFilePath());
    }
    return found;
}

QStringList GripperLibrary::names()
{
    QStringList names;
    for (const QString &folder : folders()) {
        const QStringList files =
            QDir(folder).entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name);
        for (const QString &file : files) {
            if (!names.contains(file.chopped(5)))
                names.append(file.chopped(5));
        }
    }
    names.sort();
    return names;
}

QString GripperLibrary::find(const QString &nameOrPath)
{
    if (nameOrPath.endsWith(QLatin1String(".json"), Qt::CaseInsensitive))
        return nameOrPath;
    for (const QString &folder : folders()) {
        const QString path = QDir(folder).filePath(nameOrPath + QStringLiteral(".json"));
        if (QFileInfo(path).isFile())
            return path;
    }
    return QString();
}

} // namespace semhap
