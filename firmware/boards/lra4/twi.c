/* SPDX-License-Identifier: MIT */
#include "twi.h"

#include <avr/io.h>
#include <util/delay.h>
#include <util/twi.h>

#define TWI_HZ 400000UL
/* SCL = F_CPU / (16 + 2 * TWBR) with prescaler 1: 12 at 16 MHz. */
#define TWI_BITRATE ((F_CPU / TWI_HZ - 16) / 2)
/* A byte takes 22.5 µs at 400 kHz; a device may stretch the clock, but not for 1 ms. */
#define TWI_WAIT_US 1000
#define TWI_SDA _BV(PC4)
#define TWI_SCL _BV(PC5)

static void enable(void)
{
    TWSR = 0;
    TWBR = (uint8_t)TWI_BITRATE;
    TWCR = _BV(TWEN);
}

void twi_init(void)
{
    /* The pull-ups are the breakouts' (10 kΩ); the pins' own stay off, so that recover()
     * can drive them open-drain through DDRC alone. */
    PORTC &= (uint8_t) ~(TWI_SDA | TWI_SCL);
    enable();
}

/* Waits for the TWI to finish its step; 0 when it did not in TWI_WAIT_US. */
static uint8_t wait(void)
{
    uint16_t us;
    for (us = 0; us < TWI_WAIT_US; ++us) {
        if (TWCR & _BV(TWINT))
            return 1;
        _delay_us(1);
    }
    return 0;
}

/* Frees a bus a device holds: nine clocks let it finish the byte it thinks it is sending,
 * then a stop resets every device's bus state. Open drain by hand: a line is pulled low
 * as an output (its PORT bit is 0) and released as an input. */
static void recover(void)
{
    uint8_t i;
    TWCR = 0;
    DDRC &= (uint8_t) ~(TWI_SDA | TWI_SCL);
    for (i = 0; i < 9; ++i) {
        DDRC |= TWI_SCL;
        _delay_us(5);
        DDRC &= (uint8_t)~TWI_SCL;
        _delay_us(5);
    }
    DDRC |= TWI_SCL;
    DDRC |= TWI_SDA;
    _delay_us(5);
    DDRC &= (uint8_t)~TWI_SCL;
    _delay_us(5);
    DDRC &= (uint8_t)~TWI_SDA;
    _delay_us(5);
    enable();
}

static enum twi_result send(uint8_t byte)
{
    uint8_t status;
    TWDR = byte;
    TWCR = _BV(TWINT) | _BV(TWEN);
    if (!wait())
        return TWI_BUS;
    status = TW_STATUS;
    /* A real chip reports an acknowledged address as TW_MT_SLA_ACK (0x18); Debian's simavr
     * 1.6 reports it as TW_MT_DATA_ACK (0x28). Either means the device answered. */
    if (status == TW_MT_SLA_ACK || status == TW_MT_DATA_ACK)
        return TWI_OK;
    if (status == TW_MT_SLA_NACK || status == TW_MT_DATA_NACK)
        return TWI_NACK;
    return TWI_BUS;
}

enum twi_result twi_write(uint8_t address, const uint8_t *bytes, uint8_t size)
{
    enum twi_result result = TWI_BUS;
    uint8_t i;
    TWCR = _BV(TWINT) | _BV(TWSTA) | _BV(TWEN);
    if (wait() && (TW_STATUS == TW_START || TW_STATUS == TW_REP_START))
        result = send((uint8_t)(address << 1 | TW_WRITE));
    for (i = 0; i < size && result == TWI_OK; ++i)
        result = send(bytes[i]);
    if (result != TWI_BUS) {
        uint16_t us;
        TWCR = _BV(TWINT) | _BV(TWSTO) | _BV(TWEN);
        for (us = 0; us < TWI_WAIT_US && (TWCR & _BV(TWSTO)); ++us)
            _delay_us(1);
        if (!(TWCR & _BV(TWSTO)))
            return result;
        result = TWI_BUS;
    }
    recover();
    return result;
}
