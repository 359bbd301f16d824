// SPDX-License-Identifier: MIT
#pragma once

#include "wire.h"

#include <QByteArray>
#include <QString>
#include <QStringList>

#include <array>
#include <cstdint>
#include <vector>

namespace semhap {

/**
 * The wristband wire protocol (devices/PROTOCOL.md): messages as values, and their encoding
 * into COBS frames so that a byte stream resynchronises at the next zero after garbage.
 */
namespace protocol {

// The sizes and codes are the band firmware's (firmware/core/wire.h), so both sides share them.
constexpr std::uint8_t ProtocolVersion = SEMHAP_PROTOCOL_VERSION;
/** Header: version, type, 16-bit sequence number (little-endian). */
constexpr int HeaderSize = SEMHAP_HEADER_SIZE;
constexpr int CrcSize = SEMHAP_CRC_SIZE;
/** Largest payload a frame may carry; anything longer is an oversize frame. */
constexpr int MaxPayload = SEMHAP_MAX_PAYLOAD;
constexpr int MaxFrame = SEMHAP_MAX_FRAME;
/** Largest COBS-encoded frame, without its delimiter (one overhead byte per 254). */
constexpr int MaxEncodedFrame = SEMHAP_MAX_ENCODED_FRAME;
/** Channels a set-values message may carry, as the core's frames. */
constexpr int MaxWireChannels = SEMHAP_MAX_CHANNELS;
/** Channel names in an identify reply are at most this long (UTF-8 bytes). */
constexpr int MaxNameLength = SEMHAP_MAX_NAME;

/** What a frame carries; the values are the wire's type byte. */
enum class MessageType : std::uint8_t
{
    IdentifyRequest = SEMHAP_IDENTIFY_REQUEST,
    IdentifyReply = SEMHAP_IDENTIFY_REPLY,
    SetValues = SEMHAP_SET_VALUES,
    StopAll = SEMHAP_STOP_ALL,
    Heartbeat = SEMHAP_HEARTBEAT,
    HeartbeatReply = SEMHAP_HEARTBEAT_REPLY,
    StatusRequest = SEMHAP_STATUS_REQUEST,
    Status = SEMHAP_STATUS
};

/** One channel as the device describes it: its name and physical limits. */
struct WireChannel
{
    QString name;
    float min = 0.0f;
    float max = 1.0f;
};

/** What a device says it is, so the host can check it against the model it expects. */
struct Identity
{
    QString model;
    std::uint8_t firmwareMajor = 0;
    std::uint8_t firmwareMinor = 0;
    std::uint8_t firmwarePatch = 0;
    std::vector<WireChannel> channels;
};

/** Error flags of a status message (a bit set). */
enum StatusFlag : std::uint16_t
{
    WatchdogTripped = SEMHAP_WATCHDOG_TRIPPED, ///< setpoints were zeroed: the host went quiet
    ChannelCountMismatch = SEMHAP_CHANNEL_COUNT_MISMATCH,
    Overpressure = SEMHAP_OVERPRESSURE
};

/** The device's counters and error flags: what a status (or acknowledge) reports. */
struct DeviceStatus
{
    std::uint16_t flags = 0;
    std::uint32_t framesReceived = 0;
    std::uint32_t framesDropped = 0; ///< sequence gaps seen by the device
    std::uint32_t framesGarbled = 0; ///< CRC, COBS, truncated, oversize or unknown type
    std::uint16_t acknowledged = 0;  ///< sequence number of the frame this status answers
};

/** One decoded or to-be-encoded message; only the fields of its type are meaningful. */
struct Message
{
    MessageType type = MessageType::Heartbeat;
    std::uint16_t sequence = 0;
    int channelCount = 0;                                ///< SetValues
    std::array<std::uint16_t, MaxWireChannels> values{}; ///< SetValues, 0..65535
    std::uint64_t timestamp = 0;                         ///< Heartbeat(Reply): host µs
    Identity identity;                                   ///< IdentifyReply
    DeviceStatus status;                                 ///< Status
};

/** CRC-16/CCITT-FALSE (poly 0x1021, init 0xFFFF, no reflection, no final xor). */
std::uint16_t crc16(const std::uint8_t *data, size_t size, std::uint16_t crc = 0xFFFF);

/** Maps a value in [min, max] to the wire's 0..65535 (clamped; NaN maps to 0). */
std::uint16_t toWire(double value, double min, double max);
/** Maps a wire value back to [min, max]. */
double fromWire(std::uint16_t value, double min, double max);

/** Encodes `message` as a COBS frame followed by its 0x00 delimiter, appended to `out`. */
void encode(const Message &message, QByteArray *out);
/**
 * Fast path for the hot loop: a set-values frame written into `out` (at least
 * MaxEncodedFrame + 1 bytes) without touching the heap; returns the byte count.
 */
int encodeSetValues(std::uint16_t sequence, const std::uint16_t *values, int count,
                    std::uint8_t *out);

/** Why a frame was rejected. */
enum class FrameError
{
    None,
    Cobs,      ///< the COBS code bytes do not match the frame's length
    Truncated, ///< shorter than header and CRC
    Crc,
    Version,
    UnknownType,
    Malformed, ///< the payload's length or content does not fit its type
    Oversize   ///< longer than the largest frame
};

/**
 * Decodes one COBS-decoded frame (header, payload, CRC); false with `error` when it is
 * not a valid message of this protocol version.
 */
bool decodeFrame(const std::uint8_t *frame, int size, Message *message, FrameError *error);

/**
 * COBS-decodes `size` bytes (no delimiter) into `out` (room for `size` bytes); returns the
 * decoded length or -1 when the code bytes are inconsistent.
 */
int cobsDecode(const std::uint8_t *in, int size, std::uint8_t *out);
/** COBS-encodes `size` bytes into `out` (room for size + size / 254 + 1); returns the length. */
int cobsEncode(const std::uint8_t *in, int size, std::uint8_t *out);

/** Names a message type for logs and errors ("set-values"). */
QString typeName(MessageType type);

} // namespace protocol
} // namespace semhap
