// SPDX-License-Identifier: MIT
#include "mcapwriter.h"

#include <QIODevice>
#include <QtEndian>

#include <zlib.h>
#include <zstd.h>

#include <algorithm>

namespace semhap {

namespace {

const char Magic[8] = {'\x89', 'M', 'C', 'A', 'P', '0', '\r', '\n'};

/** Little-endian appends for record bodies. */
struct Body
{
    QByteArray bytes;

    template<typename T> Body &number(T value)
    {
        char b[sizeof(T)];
        qToLittleEndian(value, b);
        bytes.append(b, sizeof(T));
        return *this;
    }
    Body &string(const QString &text)
    {
        const QByteArray utf8 = text.toUtf8();
        number(std::uint32_t(utf8.size()));
        bytes += utf8;
        return *this;
    }
    Body &data32(const QByteArray &data)
    {
        number(std::uint32_t(data.size()));
        bytes += data;
        return *this;
    }
    Body &stringMap(const std::map<QString, QString> &values)
    {
        Body entries;
        for (const auto &[key, value] : values)
            entries.string(key).string(value);
        return data32(entries.bytes);
    }
};

QByteArray recordBytes(std::uint8_t opcode, QByteArrayView body)
{
    Body r;
    r.bytes.reserve(9 + body.size());
    r.bytes.append(char(opcode));
    r.number(std::uint64_t(body.size()));
    r.bytes += body;
    return r.bytes;
}

std::uint32_t crc(std::uint32_t running, QByteArrayView bytes)
{
    return std::uint32_t(
        ::crc32(running, reinterpret_cast<const Bytef *>(bytes.constData()), uInt(bytes.size())));
}

} // namespace

McapWriter::McapWriter(QIODevice *out) : m_out(out) {}

bool McapWriter::write(QByteArrayView bytes)
{
    if (!m_error.isEmpty())
        return false;
    if (m_out->write(bytes.data(), bytes.size()) != bytes.size()) {
        m_error = m_out->errorString();
        return false;
    }
    m_offset += std::uint64_t(bytes.size());
    return true;
}

bool McapWriter::record(std::uint8_t opcode, QByteArrayView body)
{
    const QByteArray bytes = recordBytes(opcode, body);
    m_dataCrc = crc(m_dataCrc, bytes);
    return write(bytes);
}

bool McapWriter::begin(const QString &profile, const QString &library)
{
    const QByteArray magic(Magic, sizeof Magic);
    m_dataCrc = crc(0, magic);
    return write(magic) && record(0x01, Body().string(profile).string(library).bytes);
}

std::uint16_t McapWriter::addSchema(const QString &name, const QString &encoding,
                                    const QByteArray &data)
{
    const auto id = std::uint16_t(m_schemas.size() + 1);
    Body body;
    body.number(id).string(name).string(encoding).data32(data);
    m_schemas.push_back(body.bytes);
    record(0x03, body.bytes);
    return id;
}

std::uint16_t McapWriter::addChannel(std::uint16_t schemaId, const QString &topic,
                                     const QString &messageEncoding)
{
    const auto id = std::uint16_t(m_channels.size());
    Body body;
    body.number(id).number(schemaId).string(topic).string(messageEncoding).stringMap({});
    m_channels.push_back(body.bytes);
    m_channelCounts[id] = 0;
    record(0x04, body.bytes);
    return id;
}

bool McapWriter::addMessage(std::uint16_t channel, std::uint64_t logTime, QByteArrayView data)
{
    const auto sequence = std::uint32_t(m_channelCounts[channel]++);
    m_index[channel].emplace_back(logTime, std::uint64_t(m_chunk.size()));
    // Straight into the chunk: opcode, length, the fields, the data.
    char head[1 + 8 + 2 + 4 + 8 + 8];
    head[0] = 0x05;
    qToLittleEndian(std::uint64_t(2 + 4 + 8 + 8 + data.size()), head + 1);
    qToLittleEndian(channel, head + 9);
    qToLittleEndian(sequence, head + 11);
    qToLittleEndian(logTime, head + 15);
    qToLittleEndian(logTime, head + 23);
    m_chunk.insert(m_chunk.end(), head, head + sizeof head);
    m_chunk.insert(m_chunk.end(), data.begin(), data.end());
    m_chunkStart = std::min(m_chunkStart, logTime);
    m_chunkEnd = std::max(m_chunkEnd, logTime);
    m_start = std::min(m_start, logTime);
    m_end = std::max(m_end, logTime);
    ++m_messageCount;
    return m_chunk.size() < size_t(ChunkSize) || flushChunk();
}

bool McapWriter::flushChunk()
{
    if (m_chunk.empty())
        return m_error.isEmpty();
    const QByteArrayView chunk(m_chunk.data(), qsizetype(m_chunk.size()));
    m_compressed.resize(std::max(m_compressed.size(), ZSTD_compressBound(m_chunk.size())));
    const size_t size = ZSTD_compress(m_compressed.data(), m_compressed.size(), chunk.data(),
                                      size_t(chunk.size()), 3);
    if (ZSTD_isError(size)) {
        m_error = QStringLiteral("zstd: %1").arg(QLatin1String(ZSTD_getErrorName(size)));
        return false;
    }
    const QByteArrayView compressed(m_compressed.data(), qsizetype(size));
    ChunkIndex index;
    index.start = m_chunkStart;
    index.end = m_chunkEnd;
    index.offset = m_offset;
    index.compressed = size;
    index.uncompressed = std::uint64_t(chunk.size());
    // The Chunk record's head, then the compressed records written as they are: a chunk is
    // never copied into its record.
    Body body;
    body.number(m_chunkStart).number(m_chunkEnd).number(std::uint64_t(chunk.size()));
    body.number(crc(0, chunk)).string(QStringLiteral("zstd"));
    body.number(std::uint64_t(size));
    Body head;
    head.bytes.append(char(0x06));
    head.number(std::uint64_t(body.bytes.size()) + size);
    head.bytes += body.bytes;
    m_dataCrc = crc(crc(m_dataCrc, head.bytes), compressed);
    if (!write(head.bytes) || !write(compressed))
        return false;
    index.length = m_offset - index.offset;
    const std::uint64_t indexesStart = m_offset;
    for (auto &[channel, entries] : m_index) {
        if (entries.empty())
            continue;
        // Written in place: the index has a record per message of the chunk.
        Body message;
        message.number(channel).number(std::uint32_t(entries.size() * 16));
        const qsizetype at = message.bytes.size();
        message.bytes.resize(at + qsizetype(entries.size() * 16));
        char *entry = message.bytes.data() + at;
        for (const auto &[time, offset] : entries) {
            qToLittleEndian(time, entry);
            qToLittleEndian(offset, entry + 8);
            entry += 16;
        }
        index.indexOffsets[channel] = m_offset;
        if (!record(0x07, message.bytes))
            return false;
    }
    index.indexLength = m_offset - indexesStart;
    m_chunkIndexes.push_back(index);
    m_chunk.clear(); // its capacity serves the next chunk
    for (auto &entry : m_index)
        entry.second.clear();
    m_chunkStart = UINT64_MAX;
    m_chunkEnd = 0;
    return true;
}

bool McapWriter::addMetadata(const QString &name, const std::map<QString, QString> &values)
{
    Body body;
    body.string(name).stringMap(values);
    const std::uint64_t offset = m_offset;
    if (!record(0x0C, body.bytes))
        return false;
    Body index;
    index.number(offset).number(m_offset - offset).string(name);
    m_metadataIndex.emplace_back(offset, index.bytes);
    return true;
}

bool McapWriter::end()
{
    if (!flushChunk() || !record(0x0F, Body().number(m_dataCrc).bytes))
        return false;
    // The summary: each group of records, and where each group lies.
    const std::uint64_t summaryStart = m_offset;
    std::uint32_t summaryCrc = 0;
    std::vector<std::tuple<std::uint8_t, std::uint64_t, std::uint64_t>> groups;
    const auto group = [&](std::uint8_t opcode, const std::vector<QByteArray> &bodies) {
        if (bodies.empty())
            return true;
        const std::uint64_t start = m_offset;
        for (const QByteArray &body : bodies) {
            const QByteArray bytes = recordBytes(opcode, body);
            summaryCrc = crc(summaryCrc, bytes);
            if (!write(bytes))
                return false;
        }
        groups.emplace_back(opcode, start, m_offset - start);
        return true;
    };
    Body statistics;
    statistics.number(m_messageCount)
        .number(std::uint16_t(m_schemas.size()))
        .number(std::uint32_t(m_channels.size()))
        .number(std::uint32_t(0))
        .number(std::uint32_t(m_metadataIndex.size()))
        .number(std::uint32_t(m_chunkIndexes.size()))
        .number(m_messageCount ? m_start : 0)
        .number(m_messageCount ? m_end : 0);
    Body counts;
    for (const auto &[channel, count] : m_channelCounts)
        counts.number(channel).number(count);
    statistics.data32(counts.bytes);
    std::vector<QByteArray> chunkIndexes;
    for (const ChunkIndex &c : m_chunkIndexes) {
        Body offsets;
        for (const auto &[channel, offset] : c.indexOffsets)
            offsets.number(channel).number(offset);
        Body body;
        body.number(c.start).number(c.end).number(c.offset).number(c.length);
        body.data32(offsets.bytes).number(c.indexLength).string(QStringLiteral("zstd"));
        body.number(c.compressed).number(c.uncompressed);
        chunkIndexes.push_back(body.bytes);
    }
    std::vector<QByteArray> metadataIndexes;
    for (const auto &entry : m_metadataIndex)
        metadataIndexes.push_back(entry.second);
    if (!group(0x03, m_schemas) || !group(0x04, m_channels) || !group(0x0B, {statistics.bytes}) ||
        !group(0x08, chunkIndexes) || !group(0x0D, metadataIndexes))
        return false;
    const std::uint64_t offsetsStart = m_offset;
    for (const auto &[opcode, start, length] : groups) {
        Body body;
        body.number(opcode).number(start).number(length);
        const QByteArray bytes = recordBytes(0x0E, body.bytes);
        summaryCrc = crc(summaryCrc, bytes);
        if (!write(bytes))
            return false;
    }
    // The Footer's CRC covers the summary through its own summary_offset_start.
    Body footer;
    footer.number(summaryStart).number(offsetsStart);
    QByteArray head = recordBytes(0x02, QByteArray(footer.bytes + QByteArray(4, '\0')));
    head.chop(4);
    summaryCrc = crc(summaryCrc, head);
    footer.number(summaryCrc);
    return write(recordBytes(0x02, footer.bytes)) && write(QByteArray(Magic, sizeof Magic));
}

} // namespace semhap
