// SPDX-License-Identifier: MIT
#include "userpatterns.h"

#include "patternlibrary.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>

namespace semhap {

QList<UserPattern> userPatterns(const QString &folder)
{
    QList<UserPattern> patterns;
    for (const QFileInfo &file :
         QDir(folder).entryInfoList({QStringLiteral("*.json")}, QDir::Files, QDir::Name))
        patterns.append({file.completeBaseName(), file.absoluteFilePath()});
    return patterns;
}

QString userPatternPath(const QString &folder, const QString &name)
{
    return QDir::cleanPath(QDir(folder).absoluteFilePath(name + QStringLiteral(".json")));
}

QString userPatternNameProblem(const QString &folder, const QString &name, const QString &path)
{
    if (name.trimmed().isEmpty())
        return QCoreApplication::translate("semhap::UserPatterns", "A pattern needs a name.");
    if (name.contains(QLatin1Char('/')) || name.contains(QLatin1Char('\\')) ||
        name.startsWith(QLatin1Char('.')))
        return QCoreApplication::translate(
                   "semhap::UserPatterns",
                   "'%1' cannot name a file: a pattern's name may not contain '/' or '\\' or "
                   "begin with '.'.")
            .arg(name);
    // Routers find patterns by name: one named like a built-in would be ambiguous.
    if (PatternLibrary::builtin(name))
        return QCoreApplication::translate(
                   "semhap::UserPatterns",
                   "'%1' is the name of a built-in pattern: choose another.")
            .arg(name);
    const QString target = userPatternPath(folder, name);
    if (QFileInfo::exists(target) && target != QDir::cleanPath(QFileInfo(path).absoluteFilePath()))
        return QCoreApplication::translate(
                   "semhap::UserPatterns",
                   "Another of your patterns is named '%1': choose another name.")
            .arg(name);
    return QString();
}

} // namespace semhap
