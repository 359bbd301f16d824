// SPDX-License-Identifier: MIT
#include "outputfile.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QIODevice>

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace semhap {

namespace {

/** Bytes gathered before they go to the system in one write. */
constexpr qint64 BufferSize = 64 * 1024;

QString systemReason(int error)
{
    return QString::fromLocal8Bit(std::strerror(error));
}

/** Where a path that may not exist yet would be: its real folder and its name. */
QString futurePath(const QString &path)
{
    const QFileInfo info(path);
    const QString folder = info.absoluteDir().canonicalPath();
    return folder.isEmpty() ? info.absoluteFilePath()
                            : folder + QLatin1Char('/') + info.fileName();
}

/**
 * The process's umask, read without changing it: umask() can only be read by setting it,
 * which would race with other threads creating files (the studio's recorder).
 */
mode_t processUmask()
{
    QFile status(QStringLiteral("/proc/self/status"));
    if (status.open(QIODevice::ReadOnly)) {
        for (QByteArray line = status.readLine(); !line.isEmpty(); line = status.readLine()) {
            if (line.startsWith("Umask:"))
                return mode_t(line.mid(6).trimmed().toUInt(nullptr, 8));
        }
    }
    return 022; // the usual one, where /proc does not say
}

/** The file a path writes: a symbolic link's final target, else the path itself. */
QString resolvedTarget(const QString &path)
{
    QFileInfo info(path);
    for (int hops = 0; info.isSymLink() && hops < 40; ++hops) {
        const QString target = info.symLinkTarget();
        if (target.isEmpty())
            break;
        info.setFile(target);
    }
    return info.absoluteFilePath();
}

} // namespace

/** The device callers write to: gathers bytes and hands them to the descriptor. */
class OutputFile::Writer : public QIODevice
{
public:
    explicit Writer(OutputFile &file) : m_file(file) { open(QIODevice::WriteOnly); }

    bool isSequential() const override { return true; }
    bool flush()
    {
        if (m_file.failed())
            return false;
        const bool ok = m_file.writeAll(m_buffer.constData(), m_buffer.size());
        m_buffer.clear();
        return ok;
    }

protected:
    qint64 readData(char *, qint64) override { return -1; }
    qint64 writeData(const char *data, qint64 size) override
    {
        if (m_file.failed())
            return -1;
        if (m_buffer.size() + size > BufferSize && !flush())
            return -1;
        if (size >= BufferSize)
            return m_file.writeAll(data, size) ? size : -1;
        m_buffer.append(data, size);
        return size;
    }

private:
    OutputFile &m_file;
    QByteArray m_buffer;
};

OutputFile::OutputFile(const QString &path) : m_path(path) {}

OutputFile::~OutputFile()
{
    discard();
}

std::unique_ptr<OutputFile> OutputFile::forDescriptor(int fd, const QString &name)
{
    auto file = std::make_unique<OutputFile>(name);
    file->m_fd = fd;
    file->m_ownsFd = false;
    file->m_writer = std::make_unique<Writer>(*file);
    return file;
}

LoadError OutputFile::cannotWrite(const QString &reason) const
{
    return LoadError::at(m_path, QString(), QStringLiteral("cannot write: ") + reason);
}

bool OutputFile::open(LoadError *error)
{
    struct stat info = {};
    const QByteArray encoded = QFile::encodeName(m_path);
    const bool exists = ::stat(encoded.constData(), &info) == 0;
    if (exists && S_ISDIR(info.st_mode)) {
        *error = cannotWrite(QStringLiteral("it is a folder"));
        return false;
    }
    if (exists && !S_ISREG(info.st_mode)) {
        // A FIFO with no reader would block open() for ever; with O_NONBLOCK it fails with
        // ENXIO instead. Writes then block as usual.
        m_fd = ::open(encoded.constData(), O_WRONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
        if (m_fd < 0) {
            const int code = errno;
            *error = cannotWrite(code == ENXIO && S_ISFIFO(info.st_mode)
                                     ? QStringLiteral("no process reads the FIFO")
                                     : systemReason(code));
            return false;
        }
        ::fcntl(m_fd, F_SETFL, ::fcntl(m_fd, F_GETFL) & ~O_NONBLOCK);
        m_writer = std::make_unique<Writer>(*this);
        return true;
    }
    // Renaming over a file one may not write would get round its permissions.
    if (exists && ::access(encoded.constData(), W_OK) != 0) {
        *error = cannotWrite(systemReason(errno));
        return false;
    }
    m_target = resolvedTarget(m_path);
    const QFileInfo target(m_target);
    QByteArray pattern = QFile::encodeName(target.absolutePath() + QStringLiteral("/.") +
                                           target.fileName() + QStringLiteral(".XXXXXX"));
    m_fd = ::mkostemp(pattern.data(), O_CLOEXEC);
    if (m_fd < 0) {
        *error = cannotWrite(systemReason(errno));
        m_target.clear();
        return false;
    }
    m_temporary = QFile::decodeName(pattern);
    // The new file gets the old one's permissions, or what a new file would get.
    mode_t mode = info.st_mode & 07777;
    if (!exists)
        mode = 0666 & ~processUmask();
    ::fchmod(m_fd, mode);
    m_writer = std::make_unique<Writer>(*this);
    return true;
}

QIODevice *OutputFile::device() const
{
    return m_writer.get();
}

bool OutputFile::flush()
{
    return m_writer && m_writer->flush();
}

LoadError OutputFile::writeError() const
{
    return cannotWrite(systemReason(m_errno));
}

bool OutputFile::writeAll(const char *data, qint64 size)
{
    while (size > 0) {
        const ssize_t written = ::write(m_fd, data, size_t(size));
        if (written < 0) {
            if (errno == EINTR)
                continue;
            m_errno = errno;
            return false;
        }
        data += written;
        size -= written;
    }
    return true;
}

bool OutputFile::commit(LoadError *error)
{
    if (!m_writer) {
        *error = cannotWrite(QStringLiteral("not open"));
        return false;
    }
    bool ok = m_writer->flush();
    if (ok && !m_temporary.isEmpty()) {
        // The data must be on the disk before the name points at it.
        if (::fsync(m_fd) != 0 || ::close(m_fd) != 0) {
            m_errno = errno;
            ok = false;
        }
        m_fd = -1;
        if (ok && ::rename(QFile::encodeName(m_temporary).constData(),
                           QFile::encodeName(m_target).constData()) != 0) {
            m_errno = errno;
            ok = false;
        }
        if (ok)
            m_temporary.clear();
    }
    if (!ok)
        *error = writeError();
    discard();
    return ok;
}

void OutputFile::discard()
{
    m_writer.reset();
    if (m_fd >= 0 && m_ownsFd)
        ::close(m_fd);
    m_fd = -1;
    if (!m_temporary.isEmpty())
        ::unlink(QFile::encodeName(m_temporary).constData());
    m_temporary.clear();
}

bool OutputFile::write(const QString &path, const QByteArray &bytes, LoadError *error)
{
    OutputFile file(path);
    if (!file.open(error))
        return false;
    file.device()->write(bytes);
    return file.commit(error);
}

bool OutputFile::sameFile(const QString &a, const QString &b)
{
    struct stat first = {};
    struct stat second = {};
    const bool firstExists = ::stat(QFile::encodeName(a).constData(), &first) == 0;
    const bool secondExists = ::stat(QFile::encodeName(b).constData(), &second) == 0;
    // A character device (/dev/null, a terminal) keeps nothing that writing could lose:
    // several outputs and inputs may share it.
    if (firstExists && secondExists)
        return !S_ISCHR(first.st_mode) && first.st_dev == second.st_dev &&
               first.st_ino == second.st_ino;
    if (firstExists != secondExists)
        return false;
    return futurePath(a) == futurePath(b);
}

} // namespace semhap
