/* SPDX-License-Identifier: MIT */
#ifndef SEMHAP_UART_H
#define SEMHAP_UART_H

#include <stddef.h>
#include <stdint.h>

/* The host link: the UART at 250000 baud, 8N1, with interrupt-driven ring buffers. */

/* What the link has lost, for a debugger or the simulator (not on the wire). */
typedef struct uart_counters
{
    uint16_t rx_lost;    /* bytes lost: the receive ring was full, or the UART overran */
    uint16_t tx_dropped; /* replies dropped: the line stayed full too long */
} uart_counters;

extern volatile uart_counters uart_lost;

/* Starts the UART; bytes flow once interrupts are enabled. */
void uart_start(void);

/* Whether received bytes wait in the ring (call with interrupts off before sleeping). */
uint8_t uart_has_input(void);

/* Takes up to `size` received bytes into `bytes`; returns how many. */
uint8_t uart_read(uint8_t *bytes, uint8_t size);

/*
 * semhap_band_hw's write: queues one whole reply. When the ring has no room it waits for
 * the line to drain it (at most UART_TX_WAIT_MS), then drops the reply whole rather than
 * send a part of it.
 */
void uart_write(void *context, const uint8_t *bytes, size_t size);

#endif
