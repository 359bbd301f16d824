// SPDX-License-Identifier: MIT
#pragma once

#include "contactframeparser.h"
#include "loaderror.h"

#include <QByteArray>
#include <QString>

#include <functional>

class QIODevice;

namespace semhap {

/**
 * Reads contact frames from a JSON Lines stream (spec section 1), so a run can replay a
 * file or standard input. Bad lines are reported as `FILE:LINE: reason`, counted and
 * skipped; reading goes on with the next line.
 */
class ContactFrameReader
{
public:
    using ErrorHandler = std::function<void(const LoadError &error)>;

    /** Lines longer than this (in bytes, without the newline) are rejected unparsed. */
    static constexpr qint64 MaxLineLength = 1024 * 1024;

    /**
     * Reads from `device`, which the caller opened and keeps alive; `fileName` is how
     * errors name the stream (e.g. `-` for standard input).
     */
    ContactFrameReader(QIODevice *device, const QString &fileName);

    /** Where rejected lines are reported; without one they are only counted. */
    void setErrorHandler(ErrorHandler handler) { m_onError = std::move(handler); }

    /** Reads up to the next valid frame; false at the end of the stream. */
    bool next(ContactFrame *frame);

    /** The 1-based number of the last line read. */
    int lineNumber() const { return m_lineNumber; }
    /** How many frames next() has returned. */
    int frameCount() const { return m_frameCount; }
    /** How many lines were rejected, for the report at the end of a run. */
    int rejectedCount() const { return m_rejectedCount; }
    /** The last rejection, for callers that poll rather than install a handler. */
    const LoadError &lastError() const { return m_lastError; }

    /** The frames' parser (its maximum gap). */
    ContactFrameParser &parser() { return m_parser; }
    /** The actors named so far; frames refer to them by id. */
    const ActorTable &actors() const { return m_parser.actors(); }
    ActorTable &actors() { return m_parser.actors(); }

private:
    enum class LineResult
    {
        Line,
        TooLong,
        End
    };
    LineResult readLine(QByteArray *line);
    void reject(const QString &reason);

    QIODevice *m_device;
    QString m_fileName;
    ErrorHandler m_onError;
    ContactFrameParser m_parser;
    LoadError m_lastError;
    QByteArray m_buffer; ///< reused for every line, so reading allocates once
    int m_lineNumber = 0;
    int m_frameCount = 0;
    int m_rejectedCount = 0;
};

} // namespace semhap
