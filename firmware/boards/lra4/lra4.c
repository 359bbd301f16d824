/* SPDX-License-Identifier: MIT */
/*
 * lra4: four LRAs through DRV2605L drivers in real-time-playback mode, each behind its own
 * channel of a TCA9548A multiplexer (the DRV2605L has one fixed address). Channel mK is
 * DRV2605L K-1 on multiplexer channel K-1; its value v is written as RTP_INPUT = v >> 8.
 */
#include "board.h"
#include "clock.h"
#include "twi.h"

#include <avr/io.h>
#include <stddef.h>
#include <util/delay.h>

#define LRA_COUNT 4
/* D2: every DRV2605L's EN (firmware/README.md). */
#define LRA4_ENABLE PD2
#define MUX_ADDRESS 0x70
#define DRV_ADDRESS 0x5A

/* DRV2605L registers and the values of the set-up (firmware/README.md). */
#define DRV_MODE 0x01
#define DRV_RTP_INPUT 0x02
#define DRV_LIBRARY 0x03
#define DRV_RATED_VOLTAGE 0x16
#define DRV_OD_CLAMP 0x17
#define DRV_FEEDBACK 0x1A
#define DRV_CONTROL2 0x1C
#define DRV_CONTROL3 0x1D
#define MODE_INTERNAL_TRIGGER 0x00 /* out of standby */
#define MODE_RTP 0x05
/* N_ERM_LRA = 1 (an LRA); brake factor, loop gain and back-EMF gain at their defaults. */
#define FEEDBACK_LRA 0xB6
/*
 * The LRA's drive, for a 2.0 V rms LRA at 170–175 Hz (the datasheet's closed-loop formula:
 * V = 20.58 mV · RATED_VOLTAGE / sqrt(1 − 1.5 ms · f), SAMPLE_TIME 300 µs). Another LRA
 * needs other values: see firmware/README.md.
 */
#define LRA4_RATED_VOLTAGE 0x53
/* Overdrive clamp, 21.96 mV per step: 3.0 V peak. */
#define LRA4_OD_CLAMP 0x89
/* BIDIR_INPUT = 0: RTP 0x00…0xFF is 0…rated voltage (in the default bidirectional mode the
 * lower half of the range would be no drive at all); the other fields at their defaults. */
#define CONTROL2_UNIDIRECTIONAL 0x75
/* DATA_FORMAT_RTP = 1 (unsigned); the other fields at their defaults. */
#define CONTROL3_RTP_UNSIGNED 0xA8
#define LIBRARY_LRA 6
/* A driver that failed is tried again this long after; a new value for it waits as well. */
#define RETRY_MS 10

/* Failed I2C writes since start, for a debugger or the simulator (not on the wire). */
uint16_t lra4_i2c_failures;

static uint16_t wanted[LRA_COUNT]; /* what the band drives each channel to */
static uint32_t retry_at[LRA_COUNT]; /* meaningful only while its backoff bit is set */
static uint8_t ready;   /* bit k: DRV2605L k is set up for real-time playback */
static uint8_t pending; /* bit k: channel k's value has not reached its driver yet */
static uint8_t backoff; /* bit k: driver k failed and waits until retry_at[k] */

static uint8_t drv_write(uint8_t reg, uint8_t value)
{
    const uint8_t bytes[2] = {reg, value};
    return twi_write(DRV_ADDRESS, bytes, sizeof bytes) == TWI_OK;
}

static uint8_t drv_setup(void)
{
    return drv_write(DRV_MODE, MODE_INTERNAL_TRIGGER) && drv_write(DRV_FEEDBACK, FEEDBACK_LRA) &&
           drv_write(DRV_RATED_VOLTAGE, LRA4_RATED_VOLTAGE) &&
           drv_write(DRV_OD_CLAMP, LRA4_OD_CLAMP) &&
           drv_write(DRV_CONTROL2, CONTROL2_UNIDIRECTIONAL) &&
           drv_write(DRV_CONTROL3, CONTROL3_RTP_UNSIGNED) && drv_write(DRV_LIBRARY, LIBRARY_LRA) &&
           drv_write(DRV_MODE, MODE_RTP);
}

/* Brings channel k's driver to its wanted value, setting it up first if it needs it. */
static uint8_t deliver(uint8_t k)
{
    const uint8_t bit = (uint8_t)(1u << k);
    if (twi_write(MUX_ADDRESS, &bit, 1) != TWI_OK)
        return 0;
    if (!(ready & bit)) {
        if (!drv_setup())
            return 0;
        ready |= bit;
    }
    return drv_write(DRV_RTP_INPUT, (uint8_t)(wanted[k] >> 8));
}

static void update(uint8_t k)
{
    const uint8_t bit = (uint8_t)(1u << k);
    if (deliver(k)) {
        pending &= (uint8_t)~bit;
        backoff &= (uint8_t)~bit;
        return;
    }
    ++lra4_i2c_failures;
    /* A driver that stopped answering may have lost power and its set-up with it. */
    ready &= (uint8_t)~bit;
    pending |= bit;
    backoff |= bit;
    retry_at[k] = clock_millis() + RETRY_MS;
}

static uint8_t due(uint8_t k)
{
    /* Only a driver that failed waits: comparing with a stale retry time would read as
     * "not yet" for 24.8 days at a time once the clock has run past 2^31 ms. */
    return !(backoff & (1u << k)) || (int32_t)(clock_millis() - retry_at[k]) >= 0;
}

static void lra4_init(void)
{
    twi_init();
    /* The drivers' EN, pulled down on the board: off while this chip resets or sits in its
     * boot loader (its pins float then), whatever amplitude they last had. */
    PORTD |= _BV(LRA4_ENABLE);
    DDRD |= _BV(LRA4_ENABLE);
    /* The DRV2605L takes 250 µs after EN before it answers I2C. */
    _delay_ms(1);
}

static void lra4_set_output(void *context, uint8_t channel, uint16_t value)
{
    (void)context;
    wanted[channel] = value;
    pending |= (uint8_t)(1u << channel);
    if (due(channel))
        update(channel);
}

static void lra4_service(void)
{
    uint8_t k;
    for (k = 0; pending && k < LRA_COUNT; ++k) {
        if ((pending & (1u << k)) && due(k))
            update(k);
    }
}

static const semhap_band_channel channels[LRA_COUNT] = {
    SEMHAP_BOARD_CHANNEL("m1"), SEMHAP_BOARD_CHANNEL("m2"), SEMHAP_BOARD_CHANNEL("m3"),
    SEMHAP_BOARD_CHANNEL("m4")};

static const semhap_band_model model = {"lra4", {1, 0, 0}, LRA_COUNT, channels, 0, -1, 0};

const semhap_board semhap_this_board = {&model, lra4_init, lra4_set_output, NULL, lra4_service};
