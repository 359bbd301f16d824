// SPDX-License-Identifier: MIT
#include "filedialogs.h"

#include "studiofolders.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QSettings>
#include <QStandardPaths>

namespace semhap {

namespace {

/** Where the folder last used for `kind` is kept; empty for a kind with a fixed home. */
QString settingsKey(FileKind kind)
{
    switch (kind) {
    case FileKind::Session:
    case FileKind::Pattern:
        break;
    case FileKind::Router:
        return QStringLiteral("fileDialogs/routers");
    case FileKind::Scene:
        return QStringLiteral("fileDialogs/scenes");
    case FileKind::Gripper:
        return QStringLiteral("fileDialogs/grippers");
    case FileKind::HapticFile:
        return QStringLiteral("fileDialogs/hapticFiles");
    case FileKind::PlotExport:
        return QStringLiteral("fileDialogs/plotExports");
    case FileKind::SessionExport:
        return QStringLiteral("fileDialogs/sessionExports");
    case FileKind::Protocol:
        return QStringLiteral("fileDialogs/protocols");
    case FileKind::Study:
        return QStringLiteral("fileDialogs/studies");
    case FileKind::TopicMap:
        return QStringLiteral("fileDialogs/topicMaps");
    }
    return QString();
}

} // namespace

QString FileDialogs::startFolder(FileKind kind)
{
    QString home;
    if (kind == FileKind::Session)
        home = StudioFolders::sessions();
    else if (kind == FileKind::Pattern)
        home = StudioFolders::patterns();
    if (!home.isEmpty()) {
        QDir().mkpath(home); // the studio's own folders: a dialog opens in them even when new
        return home;
    }
    const QString last = QSettings().value(settingsKey(kind)).toString();
    if (!last.isEmpty() && QFileInfo(last).isDir())
        return last;
    if (kind == FileKind::Protocol && !exampleStudies().isEmpty())
        return exampleStudies();
    // A folder that is not there would leave the dialog where the last one was: for a new
    // study, among the example protocols it was just picked from.
    const QString documents = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
    return QFileInfo(documents).isDir() ? documents : QDir::homePath();
}

QString FileDialogs::exampleStudies()
{
    const QStringList places{QDir(QCoreApplication::applicationDirPath())
                                 .filePath(QStringLiteral(SEMHAP_STUDIES_FROM_BINARY)),
                             QStringLiteral(SEMHAP_SOURCE_STUDIES)};
    for (const QString &place : places) {
        if (QFileInfo(place).isDir())
            return QFileInfo(place).canonicalFilePath();
    }
    return QString();
}

bool FileDialogs::hasRemembered(FileKind kind)
{
    const QString key = settingsKey(kind);
    return !key.isEmpty() && QSettings().contains(key);
}

void FileDialogs::remember(FileKind kind, const QString &path)
{
    const QString key = settingsKey(kind);
    if (!key.isEmpty() && !path.isEmpty())
        QSettings().setValue(key, QFileInfo(path).absolutePath());
}

QString FileDialogs::openFile(QWidget *parent, FileKind kind, const QString &caption,
                              const QString &filter)
{
    const QString path = QFileDialog::getOpenFileName(parent, caption, startFolder(kind), filter);
    remember(kind, path);
    return path;
}

QString FileDialogs::saveFile(QWidget *parent, FileKind kind, const QString &caption,
                              const QString &name, const QString &filter, QString *picked)
{
    const QString start = startFolder(kind); // made if it is the kind's own folder
    const QString offered = QFileInfo(name).isAbsolute() ? name : QDir(start).filePath(name);
    const QString path = QFileDialog::getSaveFileName(parent, caption, offered, filter, picked);
    remember(kind, path);
    return path;
}

QString FileDialogs::folder(QWidget *parent, FileKind kind, const QString &caption)
{
    const QString dir = QFileDialog::getExistingDirectory(parent, caption, startFolder(kind));
    if (!dir.isEmpty())
        remember(kind, QDir(dir).filePath(QStringLiteral("."))); // the folder itself
    return dir;
}

} // namespace semhap
