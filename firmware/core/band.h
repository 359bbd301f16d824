/* SPDX-License-Identifier: MIT */
#ifndef SEMHAP_BAND_H
#define SEMHAP_BAND_H

/*
 * The band side of the wristband wire protocol (devices/PROTOCOL.md) as a portable C99
 * library: no heap, no OS, fixed buffers. A board provides a small hardware interface
 * (semhap_band_hw), feeds the bytes it receives to semhap_band_receive() and calls
 * semhap_band_poll() from its main loop; the library does the rest — resynchronising
 * decoding, replies, clamping, the watchdog, the overpressure cut-off and the counters.
 * The reference boards (firmware/boards) and `semhap emulate` are built on it.
 */

#include "wire.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Room for the band's largest reply, encoded with its delimiter; a board with a small
 * model may define less (semhap_band_init checks that its identify reply fits). */
#ifndef SEMHAP_BAND_TX_MAX
#define SEMHAP_BAND_TX_MAX (SEMHAP_MAX_ENCODED_FRAME + 1)
#endif

#define SEMHAP_BAND_WATCHDOG_MS 250

/* What a board must provide; `context` is passed back to every call. */
typedef struct semhap_band_hw
{
    void *context;
    /* Sends bytes to the host; may drop them when the line is full, as a UART would. */
    void (*write)(void *context, const uint8_t *bytes, size_t size);
    /* A millisecond clock (any epoch, wrapping at 2^32). */
    uint32_t (*millis)(void *context);
    /* Drives output `channel` to `value`: 0…65535 across the channel's limits. */
    void (*set_output)(void *context, uint8_t channel, uint16_t value);
    /* Reads sensor `sensor` (0…65535); may be NULL on a board without sensors. */
    uint16_t (*read_sensor)(void *context, uint8_t sensor);
} semhap_band_hw;

/* One output channel as the identify reply describes it. */
typedef struct semhap_band_channel
{
    const char *name; /* at most SEMHAP_MAX_NAME bytes of UTF-8 */
    float min;        /* physical value of wire value 0 */
    float max;        /* physical value of wire value 65535 */
    uint16_t limit;   /* the highest wire value the band applies: the device's own clamp */
} semhap_band_channel;

/* What a band is: its name, firmware version, channels and safety settings. */
typedef struct semhap_band_model
{
    const char *name; /* at most SEMHAP_MAX_NAME bytes */
    uint8_t firmware[3];
    uint8_t channel_count; /* at most SEMHAP_MAX_CHANNELS */
    const semhap_band_channel *channels;
    uint16_t watchdog_ms;    /* silence before every output goes to 0; 0 means 250 ms */
    int8_t pressure_sensor;  /* the sensor watched for overpressure; -1 for none */
    uint16_t overpressure;   /* a reading at or above which every output goes to 0 */
} semhap_band_model;

/* Frames thrown away, by reason (the sum is the status's "frames garbled"). */
typedef struct semhap_band_errors
{
    uint32_t cobs;
    uint32_t truncated;
    uint32_t crc;
    uint32_t version;
    uint32_t unknown_type;
    uint32_t malformed;
    uint32_t oversize;
} semhap_band_errors;

/* A band's whole state; treat the fields as read-only outside band.c. */
typedef struct semhap_band
{
    const semhap_band_model *model;
    const semhap_band_hw *hw;
    uint16_t values[SEMHAP_MAX_CHANNELS]; /* what the outputs are driven to now */
    uint16_t flags;                       /* status flags since the last status */
    uint32_t received;                    /* valid frames */
    uint32_t dropped;                     /* sequence-number gaps */
    semhap_band_errors errors;
    uint32_t watchdog_trips;
    uint32_t last_frame_ms;
    uint16_t last_sequence;
    uint8_t heard;       /* a valid frame has arrived since start */
    uint8_t overpressure; /* the pressure sensor reads at or above the limit now */
    uint8_t rx_overflow;
    uint16_t rx_length;
    uint8_t rx[SEMHAP_MAX_ENCODED_FRAME];
    uint8_t tx[SEMHAP_BAND_TX_MAX];
} semhap_band;

/*
 * Starts a band at rest (every output driven to 0). Returns 0, or -1 when the model
 * cannot be described on the wire (too many channels, a name too long, an identify reply
 * larger than SEMHAP_BAND_TX_MAX).
 */
int semhap_band_init(semhap_band *band, const semhap_band_model *model,
                     const semhap_band_hw *hw);

/* Feeds bytes from the host; complete frames are handled (and answered) at once. */
void semhap_band_receive(semhap_band *band, const uint8_t *bytes, size_t size);

/* Runs the watchdog and the overpressure check; call at least every millisecond or so. */
void semhap_band_poll(semhap_band *band);

/* Every frame the band has thrown away (the status's "frames garbled"). */
uint32_t semhap_band_garbled(const semhap_band *band);

#ifdef __cplusplus
}
#endif

#endif
