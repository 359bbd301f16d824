/* SPDX-License-Identifier: MIT */
#include "band.h"

#include <string.h>

static size_t text_length(const char *s)
{
    return s ? strlen(s) : 0;
}

/* The identify reply's payload size for `model`. */
static size_t identify_size(const semhap_band_model *model)
{
    size_t size = 3 + 1 + text_length(model->name) + 1;
    uint8_t c;
    for (c = 0; c < model->channel_count; ++c)
        size += 1 + text_length(model->channels[c].name) + 8;
    return size;
}

static uint16_t watchdog_ms(const semhap_band *band)
{
    return band->model->watchdog_ms ? band->model->watchdog_ms : SEMHAP_BAND_WATCHDOG_MS;
}

static void drive(semhap_band *band, uint8_t channel, uint16_t value)
{
    if (band->values[channel] == value)
        return;
    band->values[channel] = value;
    band->hw->set_output(band->hw->context, channel, value);
}

static void rest(semhap_band *band)
{
    uint8_t c;
    for (c = 0; c < band->model->channel_count; ++c)
        drive(band, c, 0);
}

int semhap_band_init(semhap_band *band, const semhap_band_model *model,
                     const semhap_band_hw *hw)
{
    uint8_t c;
    size_t payload;
    memset(band, 0, sizeof *band);
    band->model = model;
    band->hw = hw;
    if (model->channel_count > SEMHAP_MAX_CHANNELS ||
        text_length(model->name) > SEMHAP_MAX_NAME)
        return -1;
    for (c = 0; c < model->channel_count; ++c) {
        if (text_length(model->channels[c].name) > SEMHAP_MAX_NAME)
            return -1;
    }
    payload = identify_size(model);
    if (payload > SEMHAP_MAX_PAYLOAD)
        return -1;
    /* COBS adds one byte per 254 and one more; then the delimiter. */
    payload += SEMHAP_HEADER_SIZE + SEMHAP_CRC_SIZE;
    if (payload + payload / 254 + 2 > SEMHAP_BAND_TX_MAX)
        return -1;
    /* Driven once, whatever the outputs did before the reset. */
    for (c = 0; c < model->channel_count; ++c)
        hw->set_output(hw->context, c, 0);
    return 0;
}

uint32_t semhap_band_garbled(const semhap_band *band)
{
    const semhap_band_errors *e = &band->errors;
    return e->cobs + e->truncated + e->crc + e->version + e->unknown_type + e->malformed +
           e->oversize;
}

static uint8_t *put16(uint8_t *p, uint16_t v)
{
    p[0] = (uint8_t)(v & 0xFF);
    p[1] = (uint8_t)(v >> 8);
    return p + 2;
}

static uint8_t *put32(uint8_t *p, uint32_t v)
{
    return put16(put16(p, (uint16_t)(v & 0xFFFF)), (uint16_t)(v >> 16));
}

static uint8_t *put_text(uint8_t *p, const char *s)
{
    const size_t n = text_length(s);
    *p++ = (uint8_t)n;
    if (n > 0)
        memcpy(p, s, n);
    return p + n;
}

static uint8_t *put_float(uint8_t *p, float v)
{
    uint32_t bits;
    memcpy(&bits, &v, sizeof bits);
    return put32(p, bits);
}

/* Seals the reply whose payload ends at `end` in band->rx, encodes and writes it. */
static void send_reply(semhap_band *band, uint8_t type, uint16_t sequence, const uint8_t *end)
{
    const size_t payload = (size_t)(end - (band->rx + SEMHAP_HEADER_SIZE));
    const size_t length = semhap_seal_frame(band->rx, type, sequence, payload);
    const size_t n = semhap_cobs_encode(band->rx, length, band->tx);
    band->tx[n] = 0;
    band->hw->write(band->hw->context, band->tx, n + 1);
}

static void reply_status(semhap_band *band, uint16_t sequence)
{
    uint8_t *p = band->rx + SEMHAP_HEADER_SIZE;
    p = put16(p, band->flags);
    p = put16(p, sequence);
    p = put32(p, band->received);
    p = put32(p, band->dropped);
    p = put32(p, semhap_band_garbled(band));
    band->flags = 0;
    send_reply(band, SEMHAP_STATUS, sequence, p);
}

static void reply_identify(semhap_band *band, uint16_t sequence)
{
    const semhap_band_model *model = band->model;
    uint8_t *p = band->rx + SEMHAP_HEADER_SIZE;
    uint8_t c;
    *p++ = model->firmware[0];
    *p++ = model->firmware[1];
    *p++ = model->firmware[2];
    p = put_text(p, model->name);
    *p++ = model->channel_count;
    for (c = 0; c < model->channel_count; ++c) {
        p = put_text(p, model->channels[c].name);
        p = put_float(p, model->channels[c].min);
        p = put_float(p, model->channels[c].max);
    }
    send_reply(band, SEMHAP_IDENTIFY_REPLY, sequence, p);
}

static void set_values(semhap_band *band, const uint8_t *payload)
{
    const semhap_band_model *model = band->model;
    const uint8_t count = payload[0];
    uint8_t c;
    if (count != model->channel_count)
        band->flags |= SEMHAP_CHANNEL_COUNT_MISMATCH;
    if (band->overpressure)
        return; /* the valves stay shut until the pressure has fallen */
    for (c = 0; c < count && c < model->channel_count; ++c) {
        uint16_t value = SEMHAP_U16(payload[1 + 2 * c], payload[2 + 2 * c]);
        if (value > model->channels[c].limit)
            value = model->channels[c].limit;
        drive(band, c, value);
    }
}

/* Handles the valid frame at band->rx. */
static void handle(semhap_band *band)
{
    const uint8_t type = band->rx[1];
    const uint16_t sequence = SEMHAP_U16(band->rx[2], band->rx[3]);
    uint8_t *payload = band->rx + SEMHAP_HEADER_SIZE;
    band->last_frame_ms = band->hw->millis(band->hw->context);
    ++band->received;
    if (band->heard && sequence != (uint16_t)(band->last_sequence + 1))
        band->dropped += (uint16_t)(sequence - band->last_sequence - 1);
    band->heard = 1;
    band->last_sequence = sequence;
    switch (type) {
    case SEMHAP_SET_VALUES:
        set_values(band, payload);
        break;
    case SEMHAP_STOP_ALL:
        rest(band);
        reply_status(band, sequence);
        break;
    case SEMHAP_HEARTBEAT:
        /* The timestamp stays where it is: the reply's payload is the request's. */
        send_reply(band, SEMHAP_HEARTBEAT_REPLY, sequence, payload + 8);
        break;
    case SEMHAP_STATUS_REQUEST:
        reply_status(band, sequence);
        break;
    case SEMHAP_IDENTIFY_REQUEST:
        reply_identify(band, sequence);
        break;
    default:
        break; /* a reply from another band on a shared line: nothing to answer */
    }
}

static void count_error(semhap_band *band, enum semhap_frame_error error)
{
    semhap_band_errors *e = &band->errors;
    switch (error) {
    case SEMHAP_FRAME_OK:
        break;
    case SEMHAP_FRAME_COBS:
        ++e->cobs;
        break;
    case SEMHAP_FRAME_TRUNCATED:
        ++e->truncated;
        break;
    case SEMHAP_FRAME_CRC:
        ++e->crc;
        break;
    case SEMHAP_FRAME_VERSION:
        ++e->version;
        break;
    case SEMHAP_FRAME_UNKNOWN_TYPE:
        ++e->unknown_type;
        break;
    case SEMHAP_FRAME_MALFORMED:
        ++e->malformed;
        break;
    case SEMHAP_FRAME_OVERSIZE:
        ++e->oversize;
        break;
    }
}

/* A delimiter arrived: decode what came before it in place and handle it. */
static void finish_frame(semhap_band *band)
{
    const size_t length = band->rx_length;
    const uint8_t overflow = band->rx_overflow;
    long size;
    enum semhap_frame_error error;
    band->rx_length = 0;
    band->rx_overflow = 0;
    if (overflow) {
        count_error(band, SEMHAP_FRAME_OVERSIZE);
        return;
    }
    if (length == 0) {
        /* An empty frame: a host starting afresh (PROTOCOL.md). Its numbers start again,
         * and the jump back to them is no gap. */
        band->heard = 0;
        return;
    }
    size = semhap_cobs_decode(band->rx, length, band->rx);
    if (size < 0) {
        count_error(band, SEMHAP_FRAME_COBS);
        return;
    }
    error = semhap_check_frame(band->rx, (size_t)size);
    if (error != SEMHAP_FRAME_OK) {
        count_error(band, error);
        return;
    }
    handle(band);
}

void semhap_band_receive(semhap_band *band, const uint8_t *bytes, size_t size)
{
    size_t i;
    for (i = 0; i < size; ++i) {
        if (bytes[i] == 0)
            finish_frame(band);
        else if (band->rx_length < SEMHAP_MAX_ENCODED_FRAME)
            band->rx[band->rx_length++] = bytes[i];
        else
            band->rx_overflow = 1;
    }
}

void semhap_band_poll(semhap_band *band)
{
    const semhap_band_model *model = band->model;
    const uint32_t now = band->hw->millis(band->hw->context);
    uint8_t c;
    uint8_t active = 0;
    if (model->pressure_sensor >= 0 && band->hw->read_sensor) {
        const uint16_t pressure =
            band->hw->read_sensor(band->hw->context, (uint8_t)model->pressure_sensor);
        band->overpressure = pressure >= model->overpressure;
        if (band->overpressure) {
            band->flags |= SEMHAP_OVERPRESSURE;
            rest(band);
        }
    }
    for (c = 0; c < model->channel_count; ++c) {
        if (band->values[c] != 0)
            active = 1;
    }
    if (active && (uint32_t)(now - band->last_frame_ms) > watchdog_ms(band)) {
        rest(band);
        band->flags |= SEMHAP_WATCHDOG_TRIPPED;
        ++band->watchdog_trips;
    }
}
