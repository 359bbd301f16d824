/* SPDX-License-Identifier: MIT */
#ifndef SEMHAP_CLOCK_H
#define SEMHAP_CLOCK_H

#include <stdint.h>

/*
 * Starts Timer0 in fast PWM mode with prescaler 64 (976.5625 Hz, the mode every timer of
 * the reference boards runs in, so pneumatic6 can use its two compare outputs) and counts
 * milliseconds from its overflow interrupt.
 */
void clock_start(void);

/* Milliseconds since clock_start(), wrapping at 2^32: the band's clock. */
uint32_t clock_millis(void);

/* semhap_band_hw's millis. */
uint32_t clock_band_millis(void *context);

#endif
