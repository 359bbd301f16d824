// SPDX-License-Identifier: MIT
#pragma once

#include <QByteArray>
#include <QString>

#include <cstdint>
#include <map>
#include <vector>

class QIODevice;

namespace semhap {

/**
 * Writes an MCAP file (https://mcap.dev/spec) that any reader opens indexed: messages in
 * zstd chunks, each with its message indexes; then a summary with the schemas, channels,
 * statistics and the chunk and metadata indexes, the summary offsets, and every CRC.
 */
class McapWriter
{
public:
    /** Chunks are closed at about this many bytes of records, before compression. */
    static constexpr int ChunkSize = 1 << 20;

    /** Writes to `out`, which the caller opened and keeps alive. */
    explicit McapWriter(QIODevice *out);

    /** The magic and the Header record; `profile` is e.g. ros2. */
    bool begin(const QString &profile, const QString &library);
    /** A schema; its id. */
    std::uint16_t addSchema(const QString &name, const QString &encoding, const QByteArray &data);
    /** A channel on schema `schemaId`; its id. */
    std::uint16_t addChannel(std::uint16_t schemaId, const QString &topic,
                             const QString &messageEncoding);
    /** A message; times in nanoseconds. Messages may come in any order. */
    bool addMessage(std::uint16_t channel, std::uint64_t logTime, QByteArrayView data);
    /** A Metadata record of name and key-value pairs. */
    bool addMetadata(const QString &name, const std::map<QString, QString> &values);
    /** The last chunk, the data end and the summary; false with error() on a failed write. */
    bool end();

    /** Why a write failed, from the device; empty while all went well. */
    QString error() const { return m_error; }
    std::uint64_t messageCount() const { return m_messageCount; }

private:
    struct ChunkIndex
    {
        std::uint64_t start = 0, end = 0, offset = 0, length = 0;
        std::map<std::uint16_t, std::uint64_t> indexOffsets;
        std::uint64_t indexLength = 0, compressed = 0, uncompressed = 0;
    };

    bool write(QByteArrayView bytes);
    bool record(std::uint8_t opcode, QByteArrayView body);
    bool flushChunk();

    QIODevice *m_out;
    QString m_error;
    std::uint64_t m_offset = 0;
    std::uint32_t m_dataCrc = 0;
    std::vector<QByteArray> m_schemas;  ///< Schema record bodies, by id - 1
    std::vector<QByteArray> m_channels; ///< Channel record bodies, by id
    std::vector<char> m_chunk;          ///< the open chunk's records
    std::vector<char> m_compressed;     ///< the last chunk compressed; kept for its capacity
    std::uint64_t m_chunkStart = UINT64_MAX, m_chunkEnd = 0;
    std::map<std::uint16_t, std::vector<std::pair<std::uint64_t, std::uint64_t>>> m_index;
    std::vector<ChunkIndex> m_chunkIndexes;
    std::vector<std::pair<std::uint64_t, QByteArray>> m_metadataIndex; ///< offset, body
    std::map<std::uint16_t, std::uint64_t> m_channelCounts;
    std::uint64_t m_messageCount = 0;
    std::uint64_t m_start = UINT64_MAX, m_end = 0;
};

} // namespace semhap
