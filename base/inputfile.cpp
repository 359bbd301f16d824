// SPDX-License-Identifier: MIT
#include "inputfile.h"

#include <QFile>

#include <cerrno>
#include <cstring>
#include <sys/stat.h>

namespace semhap {

namespace {

/** stat() of `path`, following links; false with the system's reason. */
bool statOf(const QString &path, struct stat *info, QString *reason)
{
    if (::stat(QFile::encodeName(path).constData(), info) == 0)
        return true;
    *reason = QString::fromLocal8Bit(std::strerror(errno));
    return false;
}

QString kindOf(mode_t mode)
{
    if (S_ISDIR(mode))
        return QStringLiteral("a folder");
    if (S_ISCHR(mode) || S_ISBLK(mode))
        return QStringLiteral("a device");
    if (S_ISSOCK(mode))
        return QStringLiteral("a socket");
    if (S_ISFIFO(mode))
        return QStringLiteral("a FIFO");
    return QStringLiteral("a special file");
}

} // namespace

bool InputFile::readDocument(const QString &path, QByteArray *bytes, QString *reason)
{
    // Qt's resources (the built-in library) are regular files of their own kind.
    const bool resource = path.startsWith(QLatin1Char(':'));
    if (!resource) {
        struct stat info = {};
        if (!statOf(path, &info, reason))
            return false;
        if (!S_ISREG(info.st_mode)) {
            *reason = kindOf(info.st_mode) + QStringLiteral(", not a regular file");
            return false;
        }
        if (info.st_size > MaxDocumentSize) {
            *reason = QStringLiteral("%1 bytes, more than the %2 MiB a document may have")
                          .arg(qint64(info.st_size))
                          .arg(MaxDocumentSize / (1024 * 1024));
            return false;
        }
    }
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        *reason = file.errorString();
        return false;
    }
    // The file may grow between the check and the read: read one byte past the limit.
    *bytes = file.read(MaxDocumentSize + 1);
    if (file.error() != QFileDevice::NoError) {
        *reason = file.errorString();
        return false;
    }
    if (bytes->size() > MaxDocumentSize) {
        bytes->clear();
        *reason = QStringLiteral("more than the %1 MiB a document may have")
                      .arg(MaxDocumentSize / (1024 * 1024));
        return false;
    }
    return true;
}

bool InputFile::namesFile(const QString &nameOrPath, QLatin1String extension)
{
    return nameOrPath.contains(QLatin1Char('/')) ||
           nameOrPath.endsWith(extension, Qt::CaseInsensitive);
}

bool InputFile::checkStream(const QString &path, QString *reason)
{
    struct stat info = {};
    if (!statOf(path, &info, reason))
        return false;
    if (S_ISREG(info.st_mode) || S_ISFIFO(info.st_mode))
        return true;
    *reason = kindOf(info.st_mode) + QStringLiteral(", not a regular file or a pipe");
    return false;
}

} // namespace semhap
