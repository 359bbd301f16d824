/* SPDX-License-Identifier: MIT */
#include "clock.h"

#include <avr/interrupt.h>
#include <avr/io.h>
#include <util/atomic.h>

/* An overflow comes every 64 * 256 cycles: 1.024 ms at 16 MHz. The 24 µs beyond the
 * millisecond are counted in eighths (3 per overflow, 125 make a millisecond), as
 * Arduino's millis() does, so the clock does not drift. */
#if F_CPU != 16000000UL
#error "the reference boards run at 16 MHz"
#endif
#define FRACTION_PER_OVERFLOW 3
#define FRACTION_PER_MS 125

static volatile uint32_t clock_ms;
static volatile uint8_t clock_fraction;

ISR(TIMER0_OVF_vect)
{
    uint32_t ms = clock_ms + 1;
    uint8_t fraction = (uint8_t)(clock_fraction + FRACTION_PER_OVERFLOW);
    if (fraction >= FRACTION_PER_MS) {
        fraction = (uint8_t)(fraction - FRACTION_PER_MS);
        ++ms;
    }
    clock_ms = ms;
    clock_fraction = fraction;
}

void clock_start(void)
{
    TCCR0A = _BV(WGM01) | _BV(WGM00);
    TCCR0B = _BV(CS01) | _BV(CS00);
    TIMSK0 = _BV(TOIE0);
}

uint32_t clock_millis(void)
{
    uint32_t ms;
    ATOMIC_BLOCK(ATOMIC_RESTORESTATE)
    {
        ms = clock_ms;
    }
    return ms;
}

uint32_t clock_band_millis(void *context)
{
    (void)context;
    return clock_millis();
}
