// SPDX-License-Identifier: MIT
#pragma once

#include <QString>

namespace semhap {

/**
 * Where a document was wrong and why, rendered the one way every loader reports it:
 * `FILE:LINE[:COL]: reason` for text positions, `FILE: /json/pointer: reason` for JSON.
 */
struct LoadError
{
    QString file;    ///< file name as the user gave it (or a resource path)
    int line = 0;    ///< 1-based line, 0 when the error is not tied to a line
    int column = 0;  ///< 1-based column, 0 when unknown
    QString pointer; ///< RFC 6901 JSON pointer into the document; empty: the whole file
    QString reason;  ///< one sentence, no trailing period

    bool isSet() const { return !reason.isEmpty(); }
    QString toString() const;

    static LoadError at(const QString &file, const QString &pointer, const QString &reason);
    static LoadError atLine(const QString &file, int line, int column, const QString &reason);
};

/** Appends a JSON pointer token, escaping `~` and `/` as RFC 6901 asks. */
QString jsonPointerChild(const QString &pointer, const QString &token);
QString jsonPointerChild(const QString &pointer, int index);

} // namespace semhap
