/* SPDX-License-Identifier: MIT */
/*
 * The main loop every reference board shares: bytes from the UART go to the protocol core,
 * the core's poll runs the band's watchdog and overpressure check, and between interrupts
 * the chip sleeps. Timer0's overflow wakes it at least every 1.024 ms.
 */
#include "board.h"
#include "clock.h"
#include "uart.h"

#include <avr/interrupt.h>
#include <avr/io.h>
#include <avr/sleep.h>
#include <avr/wdt.h>

/*
 * The hardware watchdog resets a hung chip: a reset leaves every pin floating (the valve
 * drivers' pull-downs close the valves) and start-up drives every output to 0. 120 ms is
 * far above the main loop's longest pass (an I2C timeout, a reply waiting for the line:
 * about 20 ms) and below the protocol's own 250 ms.
 */
#define HARDWARE_WATCHDOG WDTO_120MS

/* Runs before the C start-up code: after a watchdog reset the watchdog stays on at its
 * shortest period (16 ms) until WDRF is cleared, and start-up must not outlast it. */
static void watchdog_off(void) __attribute__((naked, used, section(".init3")));
static void watchdog_off(void)
{
    MCUSR = 0;
    wdt_disable();
}

static semhap_band band;
static semhap_band_hw hw;

int main(void)
{
    const semhap_board *board = &semhap_this_board;
    clock_start();
    uart_start();
    board->init();
    set_sleep_mode(SLEEP_MODE_IDLE);
    sei();
    hw.write = uart_write;
    hw.millis = clock_band_millis;
    hw.set_output = board->set_output;
    hw.read_sensor = board->read_sensor;
    if (semhap_band_init(&band, board->model, &hw) != 0) {
        /* The model does not fit the wire (a build mistake): stay silent at rest. */
        for (;;)
            sleep_mode();
    }
    wdt_enable(HARDWARE_WATCHDOG);
    for (;;) {
        uint8_t bytes[32];
        const uint8_t n = uart_read(bytes, sizeof bytes);
        if (n > 0)
            semhap_band_receive(&band, bytes, n);
        semhap_band_poll(&band);
        if (board->service)
            board->service();
        wdt_reset();
        /* Sleeps only when no byte waits; an interrupt between the check and the sleep
         * still wakes it, since the instruction after sei runs before any interrupt. */
        cli();
        if (!uart_has_input()) {
            sleep_enable();
            sei();
            sleep_cpu();
            sleep_disable();
        }
        sei();
    }
}
