// SPDX-License-Identifier: MIT
#include "framedecoder.h"

namespace semhap {

void FrameDecoder::reset()
{
    m_length = 0;
    m_overflow = false;
}

bool FrameDecoder::finishFrame()
{
    const int length = m_length;
    const bool overflow = m_overflow;
    reset();
    if (overflow) {
        ++m_counters.oversize;
        return false;
    }
    if (length == 0)
        return false;
    const int size = protocol::cobsDecode(m_buffer.data(), length, m_decoded.data());
    if (size < 0) {
        ++m_counters.cobs;
        return false;
    }
    protocol::FrameError error = protocol::FrameError::None;
    if (protocol::decodeFrame(m_decoded.data(), size, &m_message, &error)) {
        ++m_counters.frames;
        return true;
    }
    switch (error) {
    case protocol::FrameError::Truncated:
        ++m_counters.truncated;
        break;
    case protocol::FrameError::Crc:
        ++m_counters.crc;
        break;
    case protocol::FrameError::Version:
        ++m_counters.version;
        break;
    case protocol::FrameError::UnknownType:
        ++m_counters.unknownType;
        break;
    case protocol::FrameError::Malformed:
        ++m_counters.malformed;
        break;
    case protocol::FrameError::Oversize:
        ++m_counters.oversize;
        break;
    case protocol::FrameError::Cobs:
    case protocol::FrameError::None:
        ++m_counters.cobs;
        break;
    }
    return false;
}

} // namespace semhap
