// SPDX-License-Identifier: MIT
#include "studiofolders.h"

#include <QSettings>
#include <QStandardPaths>

namespace semhap {

namespace {

const QString SessionsKey = QStringLiteral("sessions/folder");

QString dataFolder()
{
    return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation);
}

} // namespace

QString StudioFolders::sessions()
{
    const QString saved = QSettings().value(SessionsKey).toString();
    return saved.isEmpty() ? defaultSessions() : saved;
}

QString StudioFolders::defaultSessions()
{
    return dataFolder() + QStringLiteral("/sessions");
}

void StudioFolders::setSessions(const QString &folder)
{
    // Left empty or at the default, it follows the default (a moved data folder too).
    QSettings settings;
    if (folder.isEmpty() || folder == defaultSessions())
        settings.remove(SessionsKey);
    else
        settings.setValue(SessionsKey, folder);
}

QString StudioFolders::patterns()
{
    return dataFolder() + QStringLiteral("/patterns");
}

} // namespace semhap
