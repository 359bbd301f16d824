// SPDX-License-Identifier: MIT
#pragma once

#include "protocol.h"

#include <array>
#include <cstdint>

namespace semhap {

/** What a decoder has thrown away, by reason: the device's and the host's link quality. */
struct DecoderCounters
{
    std::uint32_t frames = 0; ///< valid messages delivered
    std::uint32_t cobs = 0;
    std::uint32_t truncated = 0;
    std::uint32_t crc = 0;
    std::uint32_t version = 0;
    std::uint32_t unknownType = 0;
    std::uint32_t malformed = 0;
    std::uint32_t oversize = 0;

    /** Every rejected frame, whatever the reason. */
    std::uint32_t errors() const
    {
        return cobs + truncated + crc + version + unknownType + malformed + oversize;
    }
};

/**
 * Turns a byte stream (serial, UDP datagrams, HID report contents) into messages: bytes
 * collect up to each 0x00 delimiter, so garbage costs at most the frame it lands in and
 * decoding picks up again at the next delimiter. Fixed memory; any input is safe.
 */
class FrameDecoder
{
public:
    /**
     * Feeds bytes; calls `onMessage(const protocol::Message &)` for each valid frame
     * completed by them. Empty frames (two delimiters in a row) are ignored: senders may
     * lead with a delimiter to flush a half-received frame.
     */
    template<typename Callback>
    void feed(const std::uint8_t *data, size_t size, Callback &&onMessage)
    {
        for (size_t i = 0; i < size; ++i) {
            if (data[i] != 0) {
                if (m_length < protocol::MaxEncodedFrame)
                    m_buffer[size_t(m_length++)] = data[i];
                else
                    m_overflow = true;
                continue;
            }
            if (finishFrame())
                onMessage(static_cast<const protocol::Message &>(m_message));
        }
    }

    const DecoderCounters &counters() const { return m_counters; }
    /** Forgets a half-received frame (after a reconnect). */
    void reset();

private:
    bool finishFrame();

    std::array<std::uint8_t, protocol::MaxEncodedFrame> m_buffer{};
    std::array<std::uint8_t, protocol::MaxEncodedFrame> m_decoded{};
    int m_length = 0;
    bool m_overflow = false;
    protocol::Message m_message;
    DecoderCounters m_counters;
};

} // namespace semhap
