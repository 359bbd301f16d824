// SPDX-License-Identifier: MIT
#pragma once

#include <QByteArray>
#include <QFile>
#include <QString>

#include <cstdint>
#include <map>
#include <vector>

namespace semhap {

/** A Schema record of an MCAP file: how a channel's messages are laid out. */
struct McapSchema
{
    std::uint16_t id = 0;
    QString name;     ///< e.g. geometry_msgs/msg/WrenchStamped
    QString encoding; ///< e.g. ros2msg
    QByteArray data;  ///< the schema itself, e.g. the .msg text with its dependencies
};

/** A Channel record: a topic and the encoding of its messages. */
struct McapChannel
{
    std::uint16_t id = 0;
    std::uint16_t schemaId = 0; ///< 0: the messages carry no schema
    QString topic;
    QString messageEncoding; ///< e.g. cdr, json
    std::map<QString, QString> metadata;
};

/** A Metadata record: named key-value pairs, such as a recording's settings. */
struct McapMetadata
{
    QString name;
    std::map<QString, QString> values;
};

/** One message. Its bytes stay valid until the reader's next call of next(). */
struct McapMessage
{
    std::uint16_t channelId = 0;
    std::uint32_t sequence = 0;
    std::uint64_t logTime = 0;     ///< ns
    std::uint64_t publishTime = 0; ///< ns
    const char *data = nullptr;
    std::size_t size = 0;
};

/**
 * Reads an MCAP file (https://mcap.dev/spec) from start to end as a stream, so that a file
 * with or without its summary and indexes reads alike: messages in file order, chunks
 * unpacked (zstd, lz4 or none) as they come, and every CRC the file gives checked. A
 * malformed file stops the reading with an error located by its byte offset.
 */
class McapReader
{
public:
    /** The largest chunk unpacked, in bytes: a chunk claiming more is an error, not memory. */
    static constexpr std::uint64_t MaxChunkSize = std::uint64_t(1) << 28;

    explicit McapReader(const QString &path);
    /** Reads a file already in memory (standard input's, a fuzzer's); errors name it `name`. */
    McapReader(const QByteArray &bytes, const QString &name);

    /** Opens the file and reads its magic and Header record; false with error() if bad. */
    bool open();
    /** The next message in file order; false at the end, or on an error that error() says. */
    bool next(McapMessage *message);

    /** The channel of this id read so far, or nullptr. */
    const McapChannel *channel(std::uint16_t id) const;
    /** The schema of this id read so far, or nullptr. */
    const McapSchema *schema(std::uint16_t id) const;
    /** The channels read so far, by id; all of them once next() has returned false. */
    const std::map<std::uint16_t, McapChannel> &channels() const { return m_channels; }
    /** The Metadata records read so far, in file order. */
    const std::vector<McapMetadata> &metadata() const { return m_metadata; }
    /** The Header record's profile (e.g. ros2) and writing library. */
    QString profile() const { return m_profile; }
    QString library() const { return m_library; }
    /** Whether the file ended with a summary section (and so, usually, its indexes). */
    bool hasSummary() const { return m_hasSummary; }
    /** True once the footer and closing magic have been read. */
    bool atEnd() const { return m_state == State::Done; }
    /** How far the reading is: the offset of the next record, of size() bytes. */
    std::uint64_t position() const { return m_pos; }
    std::uint64_t size() const { return m_size; }
    /** `FILE: offset N: reason`, or empty. */
    QString error() const { return m_error; }

private:
    enum class State
    {
        Closed,
        Data,
        Summary,
        Done,
        Failed
    };
    struct Cursor;

    bool fail(std::uint64_t offset, const QString &reason);
    bool record(Cursor &at, std::uint8_t opcode, const char *body, std::uint64_t length,
                std::uint64_t offset, bool inChunk, McapMessage *message, bool *isMessage);
    bool unpack(const char *body, std::uint64_t length, std::uint64_t offset);
    bool nextInChunk(McapMessage *message, bool *isMessage);

    QFile m_file;
    QByteArray m_inMemory;
    bool m_fromMemory = false;
    const char *m_bytes = nullptr; ///< the mapped file, or m_inMemory
    std::uint64_t m_size = 0;
    std::uint64_t m_pos = 0;
    State m_state = State::Closed;
    QString m_error;
    QString m_profile;
    QString m_library;
    bool m_hasSummary = false;
    std::uint32_t m_dataCrc = 0;      ///< of the data section read so far
    std::uint64_t m_summaryStart = 0; ///< where the first record after DataEnd begins

    /// The unpacked records of the last chunk, kept until the next one: the last message
    /// returned points into it.
    QByteArray m_chunk;
    std::uint64_t m_chunkPos = 0;    ///< the next record's place in it
    std::uint64_t m_chunkOffset = 0; ///< the chunk record's place in the file

    std::map<std::uint16_t, McapSchema> m_schemas;
    std::map<std::uint16_t, McapChannel> m_channels;
    std::vector<McapMetadata> m_metadata;
};

} // namespace semhap
