// SPDX-License-Identifier: MIT
#include "cdrwriter.h"

namespace semhap {

void CdrWriter::clear()
{
    m_size = 0;
    std::memcpy(grow(4), "\x00\x01\x00\x00", 4); // CDR, little-endian
}

void CdrWriter::string(QByteArrayView utf8)
{
    uint32(std::uint32_t(utf8.size() + 1));
    char *at = grow(size_t(utf8.size()) + 1);
    std::memcpy(at, utf8.data(), size_t(utf8.size()));
    at[utf8.size()] = '\0';
}

void CdrWriter::string(QStringView text)
{
    // Names are ASCII nearly always: those are copied byte for byte, the rest encoded.
    for (const QChar c : text) {
        if (c.unicode() >= 0x80) {
            string(QByteArrayView(text.toUtf8()));
            return;
        }
    }
    uint32(std::uint32_t(text.size() + 1));
    char *at = grow(size_t(text.size()) + 1);
    for (const QChar c : text)
        *at++ = char(c.unicode());
    *at = '\0';
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
