/* SPDX-License-Identifier: MIT */
#ifndef SEMHAP_WIRE_H
#define SEMHAP_WIRE_H

/*
 * The framing of the wristband wire protocol (devices/PROTOCOL.md), shared by the host
 * and the band: CRC-16/CCITT-FALSE, COBS, and the protocol's sizes and codes. Portable C99,
 * no heap; the host's protocol code calls these too, so both sides frame alike.
 */

#include <stddef.h>
#include <stdint.h>

/* A little-endian u16 from two bytes. Unsigned before the shift: on an AVR an int has 16
 * bits, and 0xFF << 8 in a signed int would overflow. */
#define SEMHAP_U16(lo, hi) ((uint16_t)((unsigned)(lo) | ((unsigned)(hi) << 8)))

#ifdef __cplusplus
extern "C" {
#endif

#define SEMHAP_PROTOCOL_VERSION 1
#define SEMHAP_HEADER_SIZE 4
#define SEMHAP_CRC_SIZE 2
/* Largest payload; a longer frame is oversize. */
#define SEMHAP_MAX_PAYLOAD 512
#define SEMHAP_MAX_FRAME (SEMHAP_HEADER_SIZE + SEMHAP_MAX_PAYLOAD + SEMHAP_CRC_SIZE)
/* Largest COBS-encoded frame without its delimiter (one overhead byte per 254). */
#define SEMHAP_MAX_ENCODED_FRAME (SEMHAP_MAX_FRAME + SEMHAP_MAX_FRAME / 254 + 1)
#define SEMHAP_MAX_CHANNELS 16
#define SEMHAP_MAX_NAME 32

/* Message types: the wire's type byte. */
enum semhap_message_type
{
    SEMHAP_IDENTIFY_REQUEST = 0x01,
    SEMHAP_IDENTIFY_REPLY = 0x02,
    SEMHAP_SET_VALUES = 0x03,
    SEMHAP_STOP_ALL = 0x04,
    SEMHAP_HEARTBEAT = 0x05,
    SEMHAP_HEARTBEAT_REPLY = 0x06,
    SEMHAP_STATUS_REQUEST = 0x07,
    SEMHAP_STATUS = 0x08
};

/* Error flags of a status message. */
enum semhap_status_flag
{
    SEMHAP_WATCHDOG_TRIPPED = 0x0001,
    SEMHAP_CHANNEL_COUNT_MISMATCH = 0x0002,
    SEMHAP_OVERPRESSURE = 0x0004
};

/* Why a frame was rejected. */
enum semhap_frame_error
{
    SEMHAP_FRAME_OK = 0,
    SEMHAP_FRAME_COBS,       /* code bytes do not match the frame's length */
    SEMHAP_FRAME_TRUNCATED,  /* shorter than header and CRC */
    SEMHAP_FRAME_CRC,
    SEMHAP_FRAME_VERSION,
    SEMHAP_FRAME_UNKNOWN_TYPE,
    SEMHAP_FRAME_MALFORMED,  /* the payload's length or content does not fit its type */
    SEMHAP_FRAME_OVERSIZE
};

/* CRC-16/CCITT-FALSE of `size` bytes, continuing from `crc` (0xFFFF to start). */
uint16_t semhap_crc16(const uint8_t *data, size_t size, uint16_t crc);

/* COBS-encodes `size` bytes into `out` (room for size + size / 254 + 1); returns the length. */
size_t semhap_cobs_encode(const uint8_t *in, size_t size, uint8_t *out);

/*
 * COBS-decodes `size` bytes (no delimiter) into `out`, which may be `in` itself: the output
 * never overtakes the input. Returns the decoded length, or -1 when the code bytes are
 * inconsistent.
 */
long semhap_cobs_decode(const uint8_t *in, size_t size, uint8_t *out);

/*
 * Checks a COBS-decoded frame (header, payload, CRC) as the protocol defines a valid one:
 * length, CRC, version, a known type and a payload that fits its type.
 */
enum semhap_frame_error semhap_check_frame(const uint8_t *frame, size_t size);

/*
 * Seals a frame whose payload is already at `frame + SEMHAP_HEADER_SIZE`: writes the
 * header and CRC; returns the frame's length.
 */
size_t semhap_seal_frame(uint8_t *frame, uint8_t type, uint16_t sequence, size_t payload);

#ifdef __cplusplus
}
#endif

#endif
