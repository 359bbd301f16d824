/* SPDX-License-Identifier: MIT */
#ifndef SEMHAP_BOARD_H
#define SEMHAP_BOARD_H

/*
 * What a reference board adds to the common firmware (main.c): its model and its outputs.
 * The common part owns the UART, the millisecond clock (Timer0), the watchdog and the main
 * loop; a board owns everything else on the chip.
 */

#include "band.h"

/* One reference board. */
typedef struct semhap_board
{
    const semhap_band_model *model;
    /* Sets the board's peripherals up with every output at rest; interrupts are off. */
    void (*init)(void);
    /* semhap_band_hw's set_output and read_sensor (the latter may be NULL). */
    void (*set_output)(void *context, uint8_t channel, uint16_t value);
    uint16_t (*read_sensor)(void *context, uint8_t sensor);
    /* Called on every pass of the main loop (may be NULL): retries, housekeeping. */
    void (*service)(void);
} semhap_board;

/* A channel of the built-in models: 0…1, driven across its whole wire range. */
#define SEMHAP_BOARD_CHANNEL(name)                                                                \
    {                                                                                             \
        (name), 0.0f, 1.0f, 65535                                                                 \
    }

/* The board this image is built for (lra4.c or pneumatic6.c defines it). */
extern const semhap_board semhap_this_board;

#endif
