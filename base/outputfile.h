// SPDX-License-Identifier: MIT
#pragma once

#include "loaderror.h"

#include <QString>

#include <memory>

class QIODevice;

namespace semhap {

/**
 * A file written so that nothing is lost. A regular file, or one that does not exist yet,
 * is written to a temporary beside it and renamed over it by commit(): until then the old
 * file stays whole, and a failed or abandoned write leaves it so. A symbolic link is
 * followed: its target is replaced, the link kept. A FIFO, a terminal or another device is
 * written directly and never replaced; a FIFO no process reads fails at once instead of
 * blocking. Writes are buffered here and every system error is kept (QFileDevice's own
 * buffer can lose one), so a full disk always reads `PATH: cannot write: reason`.
 */
class OutputFile
{
public:
    explicit OutputFile(const QString &path);
    /** Discards the temporary of a file not committed. */
    ~OutputFile();
    OutputFile(const OutputFile &) = delete;
    OutputFile &operator=(const OutputFile &) = delete;

    /** An output on a descriptor already open (standard output), named `name` in errors. */
    static std::unique_ptr<OutputFile> forDescriptor(int fd, const QString &name);

    /** Opens for writing; false with `PATH: cannot write: reason`. */
    bool open(LoadError *error);
    /** What to write to, once open. */
    QIODevice *device() const;
    /**
     * Hands what was written so far to the system, so that a pipe's reader sees it now;
     * false once a write failed.
     */
    bool flush();
    /** The path as the user gave it. */
    const QString &path() const { return m_path; }
    /** True once a write has failed (the disk is full, the reader went away). */
    bool failed() const { return m_errno != 0; }
    /** `PATH: cannot write: reason` of the failure, for failed(). */
    LoadError writeError() const;
    /**
     * Hands everything written to the file: flushes it and, for a regular file, syncs the
     * temporary and renames it over the target. False with `PATH: cannot write: reason`.
     */
    bool commit(LoadError *error);

    /** Writes a whole file the safe way (open, write, commit); false with the error. */
    static bool write(const QString &path, const QByteArray &bytes, LoadError *error);

    /**
     * True when `a` and `b` name the same file: the same inode once links are followed, or,
     * for files not yet there, the same path in the same real folder. Never for a character
     * device such as /dev/null: nothing written there can overwrite what another reads.
     */
    static bool sameFile(const QString &a, const QString &b);

private:
    class Writer;
    friend class Writer;

    LoadError cannotWrite(const QString &reason) const;
    /** Writes `size` bytes to the descriptor, whole; false (errno kept) on failure. */
    bool writeAll(const char *data, qint64 size);
    void discard();

    QString m_path;
    QString m_target;    ///< the file the temporary replaces; empty: written directly
    QString m_temporary; ///< the temporary beside it
    int m_fd = -1;
    bool m_ownsFd = true;
    int m_errno = 0;
    std::unique_ptr<Writer> m_writer;
};

} // namespace semhap
