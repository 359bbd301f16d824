// SPDX-License-Identifier: MIT
#pragma once

#include <QByteArray>

#include <cstdint>

namespace semhap {

/**
 * Writes one ROS 2 message in little-endian CDR, as rosbag2 stores it: the encapsulation
 * header, then each field in the order of its `.msg` text, each number aligned to its size.
 */
class CdrWriter
{
public:
    CdrWriter() { clear(); }
    /** Starts a new message. */
    void clear();

    void boolean(bool value) { uint8(value ? 1 : 0); }
    void uint8(std::uint8_t value);
    void int32(std::int32_t value);
    void uint32(std::uint32_t value);
    void float64(double value);
    /** A string: its length with the terminating zero, its bytes, the zero. */
    void string(const QByteArray &utf8);
    /** A sequence's length, before its elements. */
    void sequence(std::uint32_t count) { uint32(count); }
    /** A time as builtin_interfaces/Time: whole seconds and nanoseconds. */
    void time(std::int64_t nanoseconds);

    const QByteArray &bytes() const { return m_bytes; }

private:
    void align(int size);
    template<typename T> void put(T value);

    QByteArray m_bytes;
};

} // namespace semhap
