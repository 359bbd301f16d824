// SPDX-License-Identifier: MIT
#include "mcapreader.h"

#include <QtEndian>

#include <lz4frame.h>
#include <zlib.h>
#include <zstd.h>

#include <cstring>
#include <memory>

namespace semhap {

namespace {

const char Magic[8] = {'\x89', 'M', 'C', 'A', 'P', '0', '\r', '\n'};
constexpr std::uint64_t RecordHead = 9; // opcode (1) and length (8)

enum Opcode : std::uint8_t
{
    Header = 0x01,
    Footer = 0x02,
    Schema = 0x03,
    Channel = 0x04,
    Message = 0x05,
    Chunk = 0x06,
    MessageIndex = 0x07,
    ChunkIndex = 0x08,
    Attachment = 0x09,
    AttachmentIndex = 0x0A,
    Statistics = 0x0B,
    Metadata = 0x0C,
    MetadataIndex = 0x0D,
    SummaryOffset = 0x0E,
    DataEnd = 0x0F,
};

QString recordName(std::uint8_t opcode)
{
    static const std::pair<std::uint8_t, const char *> names[] = {
        {Header, "Header"},
        {Footer, "Footer"},
        {Schema, "Schema"},
        {Channel, "Channel"},
        {Message, "Message"},
        {Chunk, "Chunk"},
        {MessageIndex, "MessageIndex"},
        {ChunkIndex, "ChunkIndex"},
        {Attachment, "Attachment"},
        {AttachmentIndex, "AttachmentIndex"},
        {Statistics, "Statistics"},
        {Metadata, "Metadata"},
        {MetadataIndex, "MetadataIndex"},
        {SummaryOffset, "SummaryOffset"},
        {DataEnd, "DataEnd"},
    };
    for (const auto &[code, name] : names) {
        if (code == opcode)
            return QLatin1String(name);
    }
    return QStringLiteral("record 0x%1").arg(opcode, 2, 16, QLatin1Char('0'));
}

std::uint32_t crc32Of(std::uint32_t crc, const char *data, std::uint64_t size)
{
    // zlib's crc32 takes at most a uInt at a time.
    const auto *bytes = reinterpret_cast<const Bytef *>(data);
    while (size > 0) {
        const auto part = uInt(std::min<std::uint64_t>(size, 1u << 30));
        crc = std::uint32_t(::crc32(crc, bytes, part));
        bytes += part;
        size -= part;
    }
    return crc;
}

} // namespace

/** Bounded little-endian reads of one record's fields. */
struct McapReader::Cursor
{
    const char *p;
    const char *end;

    std::uint64_t left() const { return std::uint64_t(end - p); }

    template<typename T> bool number(T *value)
    {
        if (left() < sizeof(T))
            return false;
        *value = qFromLittleEndian<T>(p);
        p += sizeof(T);
        return true;
    }
    bool string(QString *value)
    {
        std::uint32_t size = 0;
        if (!number(&size) || left() < size)
            return false;
        *value = QString::fromUtf8(p, qsizetype(size));
        p += size;
        return true;
    }
    bool bytes32(QByteArray *value)
    {
        std::uint32_t size = 0;
        if (!number(&size) || left() < size)
            return false;
        *value = QByteArray(p, qsizetype(size));
        p += size;
        return true;
    }
    bool map(std::map<QString, QString> *value)
    {
        std::uint32_t size = 0;
        if (!number(&size) || left() < size)
            return false;
        Cursor entries{p, p + size};
        while (entries.left() > 0) {
            QString key;
            QString text;
            if (!entries.string(&key) || !entries.string(&text))
                return false;
            (*value)[key] = text;
        }
        p += size;
        return true;
    }
};

McapReader::McapReader(const QString &path) : m_file(path) {}

McapReader::McapReader(const QByteArray &bytes, const QString &name)
    : m_file(name), m_inMemory(bytes), m_fromMemory(true)
{}

bool McapReader::fail(std::uint64_t offset, const QString &reason)
{
    m_state = State::Failed;
    m_error = QStringLiteral("%1: offset %2: %3").arg(m_file.fileName()).arg(offset).arg(reason);
    return false;
}

bool McapReader::open()
{
    if (m_fromMemory) {
        m_bytes = m_inMemory.constData();
        m_size = std::uint64_t(m_inMemory.size());
    } else if (!m_file.open(QIODevice::ReadOnly)) {
        m_state = State::Failed;
        m_error =
            QStringLiteral("%1: cannot read: %2").arg(m_file.fileName(), m_file.errorString());
        return false;
    } else {
        m_size = std::uint64_t(m_file.size());
    }
    if (!m_fromMemory && m_size > 0) {
        m_bytes = reinterpret_cast<const char *>(m_file.map(0, qint64(m_size)));
        if (!m_bytes) {
            m_state = State::Failed;
            m_error =
                QStringLiteral("%1: cannot read: %2").arg(m_file.fileName(), m_file.errorString());
            return false;
        }
    }
    if (m_size < sizeof Magic || std::memcmp(m_bytes, Magic, sizeof Magic) != 0)
        return fail(0, QStringLiteral("not an MCAP file (no MCAP magic)"));
    m_pos = sizeof Magic;
    m_dataCrc = crc32Of(0, m_bytes, sizeof Magic);
    if (m_size - m_pos < RecordHead || std::uint8_t(m_bytes[m_pos]) != Header)
        return fail(m_pos, QStringLiteral("expected the Header record"));
    const std::uint64_t length = qFromLittleEndian<std::uint64_t>(m_bytes + m_pos + 1);
    if (length > m_size - m_pos - RecordHead)
        return fail(m_pos, QStringLiteral("Header record runs past the end of the file"));
    Cursor at{m_bytes + m_pos + RecordHead, m_bytes + m_pos + RecordHead + length};
    if (!at.string(&m_profile) || !at.string(&m_library))
        return fail(m_pos, QStringLiteral("truncated Header record"));
    m_dataCrc = crc32Of(m_dataCrc, m_bytes + m_pos, RecordHead + length);
    m_pos += RecordHead + length;
    m_state = State::Data;
    return true;
}

const McapChannel *McapReader::channel(std::uint16_t id) const
{
    const auto it = m_channels.find(id);
    return it == m_channels.end() ? nullptr : &it->second;
}

const McapSchema *McapReader::schema(std::uint16_t id) const
{
    const auto it = m_schemas.find(id);
    return it == m_schemas.end() ? nullptr : &it->second;
}

bool McapReader::next(McapMessage *message)
{
    while (m_state == State::Data || m_state == State::Summary) {
        bool isMessage = false;
        if (m_chunkPos < std::uint64_t(m_chunk.size())) {
            if (!nextInChunk(message, &isMessage))
                return false;
            if (isMessage)
                return true;
            continue;
        }
        const std::uint64_t offset = m_pos;
        if (m_size - offset < RecordHead)
            return fail(offset, QStringLiteral("the file ends without its Footer (truncated?)"));
        const auto opcode = std::uint8_t(m_bytes[offset]);
        const std::uint64_t length = qFromLittleEndian<std::uint64_t>(m_bytes + offset + 1);
        if (length > m_size - offset - RecordHead)
            return fail(offset, QStringLiteral("%1 of %2 bytes runs past the end of the file")
                                    .arg(recordName(opcode))
                                    .arg(length));
        const char *body = m_bytes + offset + RecordHead;
        m_pos = offset + RecordHead + length;
        if (m_state == State::Data && opcode != DataEnd && opcode != Footer)
            m_dataCrc = crc32Of(m_dataCrc, m_bytes + offset, RecordHead + length);
        Cursor at{body, body + length};
        if (!record(at, opcode, body, length, offset, false, message, &isMessage))
            return false;
        if (isMessage)
            return true;
    }
    return false;
}

bool McapReader::nextInChunk(McapMessage *message, bool *isMessage)
{
    const char *records = m_chunk.constData();
    const auto size = std::uint64_t(m_chunk.size());
    const std::uint64_t at = m_chunkPos;
    const auto where = [&](const QString &reason) {
        return fail(m_chunkOffset, QStringLiteral("chunk's record at %1: %2").arg(at).arg(reason));
    };
    if (size - at < RecordHead)
        return where(QStringLiteral("truncated record"));
    const auto opcode = std::uint8_t(records[at]);
    const std::uint64_t length = qFromLittleEndian<std::uint64_t>(records + at + 1);
    if (length > size - at - RecordHead)
        return where(QStringLiteral("%1 of %2 bytes runs past the end of the chunk")
                         .arg(recordName(opcode))
                         .arg(length));
    const char *body = records + at + RecordHead;
    m_chunkPos = at + RecordHead + length;
    if (opcode != Schema && opcode != Channel && opcode != Message)
        return where(QStringLiteral("%1 in a chunk, which holds only Schema, Channel and "
                                    "Message records")
                         .arg(recordName(opcode)));
    Cursor cursor{body, body + length};
    if (!record(cursor, opcode, body, length, m_chunkOffset, true, message, isMessage))
        return false;
    return true;
}

bool McapReader::record(Cursor &at, std::uint8_t opcode, const char *body, std::uint64_t length,
                        std::uint64_t offset, bool inChunk, McapMessage *message, bool *isMessage)
{
    // Inside a chunk the caller locates the error within it; at the top, the record's offset.
    const auto malformed = [&](const QString &reason) {
        if (inChunk)
            return fail(offset, QStringLiteral("chunk's record at %1: %2")
                                    .arg(m_chunkPos - RecordHead - length)
                                    .arg(reason));
        return fail(offset, reason);
    };
    const auto truncated = [&] {
        return malformed(QStringLiteral("truncated %1 record").arg(recordName(opcode)));
    };
    switch (opcode) {
    case Schema: {
        McapSchema s;
        if (!at.number(&s.id) || !at.string(&s.name) || !at.string(&s.encoding) ||
            !at.bytes32(&s.data))
            return truncated();
        if (s.id == 0)
            return malformed(QStringLiteral("schema id 0 is reserved for no schema"));
        const auto known = m_schemas.find(s.id);
        if (known == m_schemas.end())
            m_schemas.emplace(s.id, s);
        else if (known->second.name != s.name || known->second.encoding != s.encoding ||
                 known->second.data != s.data)
            return malformed(QStringLiteral("schema %1 is defined twice, differently").arg(s.id));
        return true;
    }
    case Channel: {
        McapChannel c;
        if (!at.number(&c.id) || !at.number(&c.schemaId) || !at.string(&c.topic) ||
            !at.string(&c.messageEncoding) || !at.map(&c.metadata))
            return truncated();
        if (c.schemaId != 0 && !m_schemas.count(c.schemaId))
            return malformed(QStringLiteral("channel %1 (%2) names schema %3, which no Schema "
                                            "record before it defines")
                                 .arg(c.id)
                                 .arg(c.topic)
                                 .arg(c.schemaId));
        const auto known = m_channels.find(c.id);
        if (known == m_channels.end())
            m_channels.emplace(c.id, c);
        else if (known->second.topic != c.topic || known->second.schemaId != c.schemaId ||
                 known->second.messageEncoding != c.messageEncoding)
            return malformed(QStringLiteral("channel %1 is defined twice, differently").arg(c.id));
        return true;
    }
    case Message: {
        if (m_state != State::Data)
            return malformed(QStringLiteral("a Message after the data section's end"));
        if (!at.number(&message->channelId) || !at.number(&message->sequence) ||
            !at.number(&message->logTime) || !at.number(&message->publishTime))
            return truncated();
        if (!m_channels.count(message->channelId))
            return malformed(
                QStringLiteral("a message on channel %1, which no Channel record before it "
                               "defines")
                    .arg(message->channelId));
        message->data = at.p;
        message->size = std::size_t(at.left());
        *isMessage = true;
        return true;
    }
    case Chunk:
        if (m_state != State::Data)
            return malformed(QStringLiteral("a Chunk after the data section's end"));
        return unpack(body, length, offset);
    case Attachment: {
        std::uint64_t logTime = 0;
        std::uint64_t createTime = 0;
        QString name;
        QString mediaType;
        std::uint64_t size = 0;
        std::uint32_t crc = 0;
        if (!at.number(&logTime) || !at.number(&createTime) || !at.string(&name) ||
            !at.string(&mediaType) || !at.number(&size) || at.left() < size)
            return truncated();
        at.p += size;
        const auto covered = std::uint64_t(at.p - body);
        if (!at.number(&crc))
            return truncated();
        if (crc != 0 && crc32Of(0, body, covered) != crc)
            return malformed(QStringLiteral("attachment %1: CRC mismatch").arg(name));
        return true;
    }
    case Metadata: {
        McapMetadata m;
        if (!at.string(&m.name) || !at.map(&m.values))
            return truncated();
        if (m_state == State::Data)
            m_metadata.push_back(m);
        return true;
    }
    case DataEnd: {
        std::uint32_t crc = 0;
        if (!at.number(&crc))
            return truncated();
        if (m_state != State::Data)
            return malformed(QStringLiteral("a second DataEnd record"));
        if (crc != 0 && crc != m_dataCrc)
            return malformed(QStringLiteral("data section CRC mismatch"));
        m_state = State::Summary;
        m_summaryStart = m_pos;
        return true;
    }
    case Footer: {
        std::uint64_t summaryStart = 0;
        std::uint64_t summaryOffsetStart = 0;
        std::uint32_t crc = 0;
        if (!at.number(&summaryStart) || !at.number(&summaryOffsetStart) || !at.number(&crc))
            return truncated();
        if (m_size - m_pos != sizeof Magic ||
            std::memcmp(m_bytes + m_pos, Magic, sizeof Magic) != 0)
            return fail(m_pos, QStringLiteral("expected the closing MCAP magic after the Footer"));
        m_hasSummary = summaryStart != 0;
        if (m_hasSummary) {
            if (m_state != State::Summary || summaryStart != m_summaryStart)
                return malformed(QStringLiteral("the Footer's summary start %1 is not where the "
                                                "summary begins")
                                     .arg(summaryStart));
            // From the summary's first byte through the Footer's summary_offset_start.
            const std::uint64_t covered = offset + RecordHead + 16 - summaryStart;
            if (crc != 0 && crc32Of(0, m_bytes + summaryStart, covered) != crc)
                return malformed(QStringLiteral("summary CRC mismatch"));
        }
        m_state = State::Done;
        return true;
    }
    case Header:
        return malformed(QStringLiteral("a second Header record"));
    case 0x00:
        return malformed(QStringLiteral("opcode 0x00, which no record has"));
    default:
        // Indexes, statistics and records of later versions or of other applications: the
        // stream needs none of them, and the specification asks readers to skip the unknown.
        return true;
    }
}

bool McapReader::unpack(const char *body, std::uint64_t length, std::uint64_t offset)
{
    Cursor at{body, body + length};
    std::uint64_t startTime = 0;
    std::uint64_t endTime = 0;
    std::uint64_t size = 0;
    std::uint32_t crc = 0;
    QString compression;
    std::uint64_t stored = 0;
    if (!at.number(&startTime) || !at.number(&endTime) || !at.number(&size) || !at.number(&crc) ||
        !at.string(&compression) || !at.number(&stored) || at.left() != stored)
        return fail(offset, QStringLiteral("truncated Chunk record"));
    if (size > MaxChunkSize)
        return fail(offset, QStringLiteral("a chunk of %1 bytes unpacked, more than the %2 "
                                           "this reader takes")
                                .arg(size)
                                .arg(MaxChunkSize));
    m_chunk.resize(qsizetype(size));
    char *out = m_chunk.data();
    if (compression.isEmpty()) {
        if (stored != size)
            return fail(
                offset,
                QStringLiteral("an uncompressed chunk of %1 bytes says %2").arg(stored).arg(size));
        std::memcpy(out, at.p, size);
    } else if (compression == QLatin1String("zstd")) {
        const std::size_t got = ZSTD_decompress(out, size, at.p, stored);
        if (ZSTD_isError(got))
            return fail(
                offset,
                QStringLiteral("zstd chunk: %1").arg(QLatin1String(ZSTD_getErrorName(got))));
        if (got != size)
            return fail(offset, QStringLiteral("zstd chunk unpacks to %1 bytes, not the %2 it "
                                               "says")
                                    .arg(got)
                                    .arg(size));
    } else if (compression == QLatin1String("lz4")) {
        LZ4F_dctx *context = nullptr;
        if (LZ4F_isError(LZ4F_createDecompressionContext(&context, LZ4F_VERSION)))
            return fail(offset, QStringLiteral("lz4: out of memory"));
        const std::unique_ptr<LZ4F_dctx, decltype(&LZ4F_freeDecompressionContext)> owner(
            context, &LZ4F_freeDecompressionContext);
        std::size_t in = 0;
        std::size_t produced = 0;
        std::size_t hint = 1;
        while (hint != 0) {
            std::size_t outSize = size - produced;
            std::size_t inSize = stored - in;
            if (inSize == 0)
                return fail(offset, QStringLiteral("lz4 chunk ends mid-frame"));
            hint = LZ4F_decompress(context, out + produced, &outSize, at.p + in, &inSize, nullptr);
            if (LZ4F_isError(hint))
                return fail(
                    offset,
                    QStringLiteral("lz4 chunk: %1").arg(QLatin1String(LZ4F_getErrorName(hint))));
            in += inSize;
            produced += outSize;
            if (outSize == 0 && inSize == 0 && hint != 0)
                return fail(offset, QStringLiteral("lz4 chunk unpacks to more than the %1 "
                                                   "bytes it says")
                                        .arg(size));
        }
        if (produced != size || in != stored)
            return fail(offset, QStringLiteral("lz4 chunk unpacks to %1 bytes, not the %2 it "
                                               "says")
                                    .arg(produced)
                                    .arg(size));
    } else {
        return fail(offset, QStringLiteral("chunk compression '%1' is not read (zstd, lz4 or "
                                           "none)")
                                .arg(compression));
    }
    if (crc != 0 && crc32Of(0, out, size) != crc)
        return fail(offset, QStringLiteral("chunk CRC mismatch"));
    m_chunkPos = 0;
    m_chunkOffset = offset;
    return true;
}

} // namespace semhap
