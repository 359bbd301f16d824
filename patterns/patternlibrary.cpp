// SPDX-License-Identifier: MIT
#include "patternlibrary.h"

#include "inputfile.h"

#include <QDir>

#include <map>
#include <mutex>

namespace semhap {

namespace {

const QString &resourceDir()
{
    static const QString dir = QStringLiteral(":/semhap/patterns/");
    return dir;
}

} // namespace

QStringList PatternLibrary::builtinNames()
{
    QStringList names =
        QDir(resourceDir()).entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name);
    for (QString &name : names)
        name.chop(int(qstrlen(".json")));
    return names;
}

PatternPtr PatternLibrary::builtin(const QString &name)
{
    // Parsed on first use and shared: voices only read patterns, so sharing is safe.
    static std::mutex mutex;
    static std::map<QString, PatternPtr> cache;
    const std::lock_guard<std::mutex> lock(mutex);
    const auto found = cache.find(name);
    if (found != cache.end())
        return found->second;
    if (!builtinNames().contains(name))
        return nullptr;
    PatternPtr pattern =
        Pattern::fromFile(resourceDir() + name + QStringLiteral(".json"), nullptr);
    cache.emplace(name, pattern);
    return pattern;
}

PatternPtr PatternLibrary::load(const QString &nameOrPath, LoadError *error)
{
    if (InputFile::namesFile(nameOrPath)) {
        return Pattern::fromFile(nameOrPath, error);
    }
    PatternPtr pattern = builtin(nameOrPath);
    if (!pattern && error) {
        *error = LoadError();
        error->file = nameOrPath;
        error->reason = QStringLiteral("no built-in pattern of that name (there are ") +
                        builtinNames().join(QStringLiteral(", ")) + QLatin1Char(')');
    }
    return pattern;
}

} // namespace semhap
