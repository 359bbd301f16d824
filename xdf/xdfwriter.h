// SPDX-License-Identifier: MIT
#pragma once

#include <QByteArray>
#include <QList>

#include <vector>

class QIODevice;

namespace semhap {

/**
 * Writes the chunks of an XDF 1.0 file, the Lab Streaming Layer's recording format: the
 * magic code `XDF:`, then chunks, each its length, a 16-bit tag and its content, every number
 * little-endian; lengths and counts are variable-length (a byte saying 1, 4 or 8, then the
 * number in that many bytes). Every sample is written with its time stamp. Each call writes
 * at once; a false return means the device refused a write (its errorString() says why).
 */
class XdfWriter
{
public:
    /** The chunk tags of XDF 1.0. */
    enum class Tag : quint16
    {
        FileHeader = 1,
        StreamHeader = 2,
        Samples = 3,
        ClockOffset = 4,
        Boundary = 5,
        StreamFooter = 6
    };

    explicit XdfWriter(QIODevice *out) : m_out(out) {}

    /** The magic code and the FileHeader chunk (`<info><version>1.0</version>…</info>`). */
    bool writeFileHeader(const QByteArray &xml);
    bool writeStreamHeader(quint32 stream, const QByteArray &xml);
    /**
     * A Samples chunk of a float32 stream: sample i has time stamp `stamps[i]` and the
     * `values.size() / stamps.size()` values from `values[i * channels]`.
     */
    bool writeSamples(quint32 stream, const std::vector<double> &stamps,
                      const std::vector<float> &values);
    /** A Samples chunk of a one-channel string stream (markers). */
    bool writeStringSamples(quint32 stream, const std::vector<double> &stamps,
                            const QList<QByteArray> &values);
    /**
     * A ClockOffset chunk: at `collectionTime` (on the stream's clock), the stream's time
     * stamps plus `offset` were the recording machine's clock.
     */
    bool writeClockOffset(quint32 stream, double collectionTime, double offset);
    /** A Boundary chunk: the fixed 16 bytes a damaged file's reader can find again. */
    bool writeBoundary();
    bool writeStreamFooter(quint32 stream, const QByteArray &xml);

private:
    static void appendLength(QByteArray &to, quint64 value);
    template<typename T> static void append(QByteArray &to, T value);
    /** Writes the chunk whose content m_content holds, and empties it. */
    bool writeChunk(Tag tag);

    QIODevice *m_out;
    QByteArray m_head;    ///< a chunk's length and tag
    QByteArray m_content; ///< the chunk being made; both kept to spare their allocations
};

} // namespace semhap
