/* SPDX-License-Identifier: MIT */
#include "uart.h"

#include "clock.h"

#include <avr/interrupt.h>
#include <avr/io.h>

/* 250000 baud is exact at 16 MHz: 16 MHz / (16 * (3 + 1)), no double speed. */
#define UART_UBRR 3
/* Powers of two, so the indices wrap with a mask. 128 bytes are 5 ms of a full line. */
#define UART_RX_SIZE 128
#define UART_TX_SIZE 128
/* A full ring drains in 5 ms at 250000 baud; the hardware watchdog allows 120 ms. */
#define UART_TX_WAIT_MS 20

static uint8_t rx_ring[UART_RX_SIZE];
static volatile uint8_t rx_head; /* written by the interrupt */
static volatile uint8_t rx_tail; /* written by the main loop */
static uint8_t tx_ring[UART_TX_SIZE];
static volatile uint8_t tx_head; /* written by the main loop */
static volatile uint8_t tx_tail; /* written by the interrupt */

volatile uart_counters uart_lost;

ISR(USART_RX_vect)
{
    const uint8_t status = UCSR0A;
    const uint8_t byte = UDR0;
    const uint8_t next = (uint8_t)((rx_head + 1) & (UART_RX_SIZE - 1));
    /* A framing error's byte goes in too: the frame's CRC rejects it, and a lost
     * delimiter costs no more than the frames around it. */
    if (status & _BV(DOR0))
        ++uart_lost.rx_lost;
    if (next == rx_tail) {
        ++uart_lost.rx_lost;
        return;
    }
    rx_ring[rx_head] = byte;
    rx_head = next;
}

ISR(USART_UDRE_vect)
{
    const uint8_t tail = tx_tail;
    if (tail == tx_head) {
        UCSR0B &= (uint8_t)~_BV(UDRIE0);
        return;
    }
    UDR0 = tx_ring[tail];
    tx_tail = (uint8_t)((tail + 1) & (UART_TX_SIZE - 1));
}

void uart_start(void)
{
    UBRR0 = UART_UBRR;
    UCSR0A = 0;
    UCSR0C = _BV(UCSZ01) | _BV(UCSZ00);
    UCSR0B = _BV(RXEN0) | _BV(TXEN0) | _BV(RXCIE0);
}

uint8_t uart_has_input(void)
{
    return rx_head != rx_tail;
}

uint8_t uart_read(uint8_t *bytes, uint8_t size)
{
    uint8_t tail = rx_tail;
    uint8_t n = 0;
    while (n < size && tail != rx_head) {
        bytes[n++] = rx_ring[tail];
        tail = (uint8_t)((tail + 1) & (UART_RX_SIZE - 1));
    }
    rx_tail = tail;
    return n;
}

static uint8_t tx_room(void)
{
    return (uint8_t)((tx_tail - tx_head - 1) & (UART_TX_SIZE - 1));
}

void uart_write(void *context, const uint8_t *bytes, size_t size)
{
    const uint32_t start = clock_millis();
    uint8_t head = tx_head;
    size_t i;
    (void)context;
    if (size > UART_TX_SIZE - 1) {
        ++uart_lost.tx_dropped;
        return;
    }
    while (tx_room() < size) {
        if ((uint32_t)(clock_millis() - start) > UART_TX_WAIT_MS) {
            ++uart_lost.tx_dropped;
            return;
        }
    }
    for (i = 0; i < size; ++i) {
        tx_ring[head] = bytes[i];
        head = (uint8_t)((head + 1) & (UART_TX_SIZE - 1));
    }
    tx_head = head;
    /* The interrupt switches itself off when the ring is empty; this switches it on. */
    UCSR0B |= _BV(UDRIE0);
}
