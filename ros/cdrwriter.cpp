// SPDX-License-Identifier: MIT
#include "cdrwriter.h"

#include <QtEndian>

#include <cstring>

namespace semhap {

void CdrWriter::clear()
{
    m_bytes.resize(0); // keeps the capacity: a message after the first allocates nothing
    m_bytes.append("\x00\x01\x00\x00", 4); // CDR, little-endian
}

void CdrWriter::align(int size)
{
    // Alignment counts from after the encapsulation header.
    const qsizetype at = m_bytes.size() - 4;
    const qsizetype padded = (at + size - 1) / size * size;
    m_bytes.append(padded - at, '\0');
}

template<typename T> void CdrWriter::put(T value)
{
    align(int(sizeof(T)));
    char bytes[sizeof(T)];
    qToLittleEndian(value, bytes);
    m_bytes.append(bytes, sizeof(T));
}

void CdrWriter::uint8(std::uint8_t value)
{
    m_bytes.append(char(value));
}

void CdrWriter::int32(std::int32_t value)
{
    put(value);
}

void CdrWriter::uint32(std::uint32_t value)
{
    put(value);
}

void CdrWriter::float64(double value)
{
    std::uint64_t bits = 0;
    std::memcpy(&bits, &value, sizeof bits);
    put(bits);
}

void CdrWriter::string(const QByteArray &utf8)
{
    uint32(std::uint32_t(utf8.size() + 1));
    m_bytes.append(utf8);
    m_bytes.append('\0');
}

void CdrWriter::time(std::int64_t nanoseconds)
{
    // Floor division, so that a time before the epoch keeps nanosec in 0 … 999999999.
    std::int64_t sec = nanoseconds / 1000000000;
    std::int64_t nsec = nanoseconds % 1000000000;
    if (nsec < 0) {
        nsec += 1000000000;
        --sec;
    }
    int32(std::int32_t(sec));
    uint32(std::uint32_t(nsec));
}

} // namespace semhap
