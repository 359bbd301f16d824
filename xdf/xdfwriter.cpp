// SPDX-License-Identifier: MIT
#include "xdfwriter.h"

#include <QIODevice>
#include <QtEndian>

#include <cstring>

namespace semhap {

namespace {

/** The Boundary chunk's content, the same in every XDF file (its specification's UUID). */
constexpr unsigned char BoundaryUuid[16] = {0x43, 0xA5, 0x46, 0xDC, 0xCB, 0xF5, 0x41, 0x0F,
                                            0xB3, 0x0E, 0xD5, 0x46, 0x73, 0x83, 0xCB, 0xE4};

} // namespace

template<typename T> void XdfWriter::append(QByteArray &to, T value)
{
    char bytes[sizeof(T)];
    qToLittleEndian(value, bytes);
    to.append(bytes, int(sizeof(T)));
}

void XdfWriter::appendLength(QByteArray &to, quint64 value)
{
    if (value <= 0xFF) {
        append<quint8>(to, 1);
        append<quint8>(to, quint8(value));
    } else if (value <= 0xFFFFFFFFu) {
        append<quint8>(to, 4);
        append<quint32>(to, quint32(value));
    } else {
        append<quint8>(to, 8);
        append<quint64>(to, value);
    }
}

bool XdfWriter::writeChunk(Tag tag)
{
    // The length counts the tag and the content.
    m_head.clear();
    appendLength(m_head, quint64(m_content.size()) + 2);
    append<quint16>(m_head, quint16(tag));
    const bool ok =
        m_out->write(m_head) == m_head.size() && m_out->write(m_content) == m_content.size();
    m_content.clear();
    return ok;
}

bool XdfWriter::writeFileHeader(const QByteArray &xml)
{
    if (m_out->write("XDF:", 4) != 4)
        return false;
    m_content = xml;
    return writeChunk(Tag::FileHeader);
}

bool XdfWriter::writeStreamHeader(quint32 stream, const QByteArray &xml)
{
    append<quint32>(m_content, stream);
    m_content.append(xml);
    return writeChunk(Tag::StreamHeader);
}

bool XdfWriter::writeSamples(quint32 stream, const std::vector<double> &stamps,
                             const std::vector<float> &values)
{
    const size_t channels = stamps.empty() ? 0 : values.size() / stamps.size();
    append<quint32>(m_content, stream);
    appendLength(m_content, stamps.size());
    for (size_t i = 0; i < stamps.size(); ++i) {
        append<quint8>(m_content, 8);
        append<double>(m_content, stamps[i]);
        for (size_t c = 0; c < channels; ++c)
            append<float>(m_content, values[i * channels + c]);
    }
    return writeChunk(Tag::Samples);
}

bool XdfWriter::writeStringSamples(quint32 stream, const std::vector<double> &stamps,
                                   const QList<QByteArray> &values)
{
    append<quint32>(m_content, stream);
    appendLength(m_content, stamps.size());
    for (size_t i = 0; i < stamps.size(); ++i) {
        append<quint8>(m_content, 8);
        append<double>(m_content, stamps[i]);
        appendLength(m_content, quint64(values[qsizetype(i)].size()));
        m_content.append(values[qsizetype(i)]);
    }
    return writeChunk(Tag::Samples);
}

bool XdfWriter::writeClockOffset(quint32 stream, double collectionTime, double offset)
{
    append<quint32>(m_content, stream);
    append<double>(m_content, collectionTime);
    append<double>(m_content, offset);
    return writeChunk(Tag::ClockOffset);
}

bool XdfWriter::writeBoundary()
{
    m_content.append(reinterpret_cast<const char *>(BoundaryUuid), int(sizeof(BoundaryUuid)));
    return writeChunk(Tag::Boundary);
}

bool XdfWriter::writeStreamFooter(quint32 stream, const QByteArray &xml)
{
    append<quint32>(m_content, stream);
    m_content.append(xml);
    return writeChunk(Tag::StreamFooter);
}

} // namespace semhap
