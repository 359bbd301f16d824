// SPDX-License-Identifier: MIT
#include "contactframereader.h"

#include <QIODevice>

namespace semhap {

namespace {

bool isBlank(const QByteArray &line)
{
    for (const char c : line) {
        if (c != ' ' && c != '\t' && c != '\r')
            return false;
    }
    return true;
}

} // namespace

ContactFrameReader::ContactFrameReader(QIODevice *device, const QString &fileName)
    : m_device(device), m_fileName(fileName)
{}

bool ContactFrameReader::next(ContactFrame *frame)
{
    QByteArray line;
    for (;;) {
        const LineResult result = readLine(&line);
        if (result == LineResult::End)
            return false;
        if (result == LineResult::TooLong) {
            reject(QStringLiteral("line longer than %1 bytes").arg(MaxLineLength));
            continue;
        }
        if (isBlank(line))
            continue;
        QString reason;
        if (m_parser.parse(line, frame, &reason)) {
            ++m_frameCount;
            return true;
        }
        reject(reason);
    }
}

ContactFrameReader::LineResult ContactFrameReader::readLine(QByteArray *line)
{
    // QIODevice::readLine stores at most size - 1 bytes and a terminating NUL.
    if (m_buffer.isEmpty())
        m_buffer.resize(MaxLineLength + 2);
    const qint64 capacity = m_buffer.size();
    qint64 length = m_device->readLine(m_buffer.data(), capacity);
    if (length <= 0)
        return LineResult::End;
    ++m_lineNumber;
    if (length == capacity - 1 && m_buffer.at(length - 1) != '\n') {
        // Drain the rest of the overlong line without keeping it.
        do {
            length = m_device->readLine(m_buffer.data(), capacity);
        } while (length == capacity - 1 && m_buffer.at(length - 1) != '\n');
        return LineResult::TooLong;
    }
    if (m_buffer.at(length - 1) == '\n')
        --length;
    qint64 start = 0;
    // A UTF-8 byte order mark some editors write is not part of the first frame.
    if (m_lineNumber == 1 && length >= 3 && m_buffer.startsWith("\xEF\xBB\xBF"))
        start = 3;
    *line = QByteArray::fromRawData(m_buffer.constData() + start, length - start);
    return LineResult::Line;
}

void ContactFrameReader::reject(const QString &reason)
{
    ++m_rejectedCount;
    m_lastError = LoadError::atLine(m_fileName, m_lineNumber, 0, reason);
    if (m_onError)
        m_onError(m_lastError);
}

} // namespace semhap
