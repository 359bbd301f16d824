/* SPDX-License-Identifier: MIT */
#include "wire.h"

uint16_t semhap_crc16(const uint8_t *data, size_t size, uint16_t crc)
{
    size_t i;
    int bit;
    for (i = 0; i < size; ++i) {
        crc = (uint16_t)(crc ^ ((unsigned)data[i] << 8));
        for (bit = 0; bit < 8; ++bit)
            crc = (crc & 0x8000u) ? (uint16_t)(((unsigned)crc << 1) ^ 0x1021u)
                                  : (uint16_t)(crc << 1);
    }
    return crc;
}

size_t semhap_cobs_encode(const uint8_t *in, size_t size, uint8_t *out)
{
    size_t code_at = 0;
    size_t o = 1;
    uint8_t code = 1;
    size_t i;
    for (i = 0; i < size; ++i) {
        if (in[i] != 0) {
            out[o++] = in[i];
            ++code;
        }
        if (in[i] == 0 || code == 0xFF) {
            out[code_at] = code;
            code = 1;
            code_at = o++;
        }
    }
    out[code_at] = code;
    return o;
}

long semhap_cobs_decode(const uint8_t *in, size_t size, uint8_t *out)
{
    size_t i = 0;
    size_t o = 0;
    while (i < size) {
        const size_t code = in[i++];
        size_t k;
        if (code == 0 || i + code - 1 > size)
            return -1;
        for (k = 1; k < code; ++k) {
            if (in[i] == 0)
                return -1;
            out[o++] = in[i++];
        }
        if (code != 0xFF && i < size)
            out[o++] = 0;
    }
    return (long)o;
}

/* Skips a string (length byte, at most SEMHAP_MAX_NAME bytes); 0 when it does not fit. */
static int skip_text(const uint8_t *payload, size_t size, size_t *at)
{
    size_t length;
    if (*at >= size)
        return 0;
    length = payload[(*at)++];
    if (length > SEMHAP_MAX_NAME || size - *at < length)
        return 0;
    *at += length;
    return 1;
}

static int identify_reply_fits(const uint8_t *payload, size_t size)
{
    size_t at = 3;
    size_t count;
    size_t c;
    if (size < at || !skip_text(payload, size, &at) || at >= size)
        return 0;
    count = payload[at++];
    if (count > SEMHAP_MAX_CHANNELS)
        return 0;
    for (c = 0; c < count; ++c) {
        if (!skip_text(payload, size, &at) || size - at < 8)
            return 0;
        at += 8;
    }
    return at == size;
}

static int payload_fits(uint8_t type, const uint8_t *payload, size_t size)
{
    switch (type) {
    case SEMHAP_IDENTIFY_REQUEST:
    case SEMHAP_STOP_ALL:
    case SEMHAP_STATUS_REQUEST:
        return size == 0;
    case SEMHAP_IDENTIFY_REPLY:
        return identify_reply_fits(payload, size);
    case SEMHAP_SET_VALUES:
        return size >= 1 && payload[0] <= SEMHAP_MAX_CHANNELS && size == 1u + 2u * payload[0];
    case SEMHAP_HEARTBEAT:
    case SEMHAP_HEARTBEAT_REPLY:
        return size == 8;
    case SEMHAP_STATUS:
        return size == 16;
    default:
        return 0;
    }
}

enum semhap_frame_error semhap_check_frame(const uint8_t *frame, size_t size)
{
    if (size > SEMHAP_MAX_FRAME)
        return SEMHAP_FRAME_OVERSIZE;
    if (size < SEMHAP_HEADER_SIZE + SEMHAP_CRC_SIZE)
        return SEMHAP_FRAME_TRUNCATED;
    if (semhap_crc16(frame, size - SEMHAP_CRC_SIZE, 0xFFFF) !=
        SEMHAP_U16(frame[size - 2], frame[size - 1]))
        return SEMHAP_FRAME_CRC;
    if (frame[0] != SEMHAP_PROTOCOL_VERSION)
        return SEMHAP_FRAME_VERSION;
    if (frame[1] < SEMHAP_IDENTIFY_REQUEST || frame[1] > SEMHAP_STATUS)
        return SEMHAP_FRAME_UNKNOWN_TYPE;
    if (!payload_fits(frame[1], frame + SEMHAP_HEADER_SIZE,
                      size - SEMHAP_HEADER_SIZE - SEMHAP_CRC_SIZE))
        return SEMHAP_FRAME_MALFORMED;
    return SEMHAP_FRAME_OK;
}

size_t semhap_seal_frame(uint8_t *frame, uint8_t type, uint16_t sequence, size_t payload)
{
    const size_t length = SEMHAP_HEADER_SIZE + payload;
    uint16_t crc;
    frame[0] = SEMHAP_PROTOCOL_VERSION;
    frame[1] = type;
    frame[2] = (uint8_t)(sequence & 0xFF);
    frame[3] = (uint8_t)(sequence >> 8);
    crc = semhap_crc16(frame, length, 0xFFFF);
    frame[length] = (uint8_t)(crc & 0xFF);
    frame[length + 1] = (uint8_t)(crc >> 8);
    return length + SEMHAP_CRC_SIZE;
}
