// SPDX-License-Identifier: MIT
#pragma once

#include <QByteArrayView>
#include <QString>
#include <QtEndian>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <vector>

namespace semhap {

/**
 * Writes one ROS 2 message in little-endian CDR, as rosbag2 stores it: the encapsulation
 * header, then each field in the order of its `.msg` text, each number aligned to its size.
 * It writes into a buffer it keeps from message to message, so a message allocates nothing.
 */
class CdrWriter
{
public:
    CdrWriter() { clear(); }
    /** Starts a new message. */
    void clear();

    void boolean(bool value) { uint8(value ? 1 : 0); }
    void uint8(std::uint8_t value) { put(value); }
    void int32(std::int32_t value) { put(value); }
    void uint32(std::uint32_t value) { put(value); }
    void float64(double value)
    {
        std::uint64_t bits = 0;
        std::memcpy(&bits, &value, sizeof bits);
        put(bits);
    }
    /** A string: its length with the terminating zero, its bytes, the zero. */
    void string(QByteArrayView utf8);
    void string(const QByteArray &utf8) { string(QByteArrayView(utf8)); }
    /** A string given as text: encoded to UTF-8 straight into the message. */
    void string(QStringView text);
    void string(const QString &text) { string(QStringView(text)); }
    /** A sequence's length, before its elements. */
    void sequence(std::uint32_t count) { uint32(count); }
    /** A time as builtin_interfaces/Time: whole seconds and nanoseconds. */
    void time(std::int64_t nanoseconds);

    /** The message so far; valid until the next write. */
    QByteArrayView bytes() const { return {m_bytes.data(), qsizetype(m_size)}; }

private:
    /** Room for n more bytes at the end. */
    char *grow(size_t n)
    {
        if (m_size + n > m_bytes.size())
            m_bytes.resize(std::max(m_bytes.size() * 2, m_size + n));
        char *at = m_bytes.data() + m_size;
        m_size += n;
        return at;
    }
    template<typename T> void put(T value)
    {
        // Alignment counts from after the 4-byte encapsulation header.
        const size_t pad = (sizeof(T) - (m_size - 4) % sizeof(T)) % sizeof(T);
        char *at = grow(pad + sizeof(T));
        std::memset(at, 0, pad);
        qToLittleEndian(value, at + pad);
    }

    std::vector<char> m_bytes;
    size_t m_size = 0;
};

} // namespace semhap
