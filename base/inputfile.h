// SPDX-License-Identifier: MIT
#pragma once

#include <QByteArray>
#include <QString>

namespace semhap {

/**
 * The rules for reading what a user names: a document (a pattern, router, device model,
 * scene, AHAP or `.haptic` file) must be a regular file of at most MaxDocumentSize bytes and
 * is read whole; a stream (contact frames) may also be a pipe or FIFO, read as it comes.
 * Devices such as `/dev/zero` are refused, so no argument can read without end.
 */
class InputFile
{
public:
    /** The largest document read (bytes): far above any real pattern, router or scene. */
    static constexpr qint64 MaxDocumentSize = 64 * 1024 * 1024;

    /** Reads a whole document; false with a reason such as "a device, not a regular file". */
    static bool readDocument(const QString &path, QByteArray *bytes, QString *reason);
    /** Whether `path` may be read as a stream (a regular file, a pipe or a FIFO). */
    static bool checkStream(const QString &path, QString *reason);
    /**
     * Whether a name given for a pattern, router, device model (`.json`) or scene (`.xml`)
     * names a file rather than a built-in: it holds a `/` or ends with the extension.
     */
    static bool namesFile(const QString &nameOrPath,
                          QLatin1String extension = QLatin1String(".json"));
};

} // namespace semhap
