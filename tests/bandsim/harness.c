/* SPDX-License-Identifier: MIT */
/*
 * A test image for the simulator harness itself (tests/bandsim), not a band: it holds the
 * simulated chip to the ATmega328P datasheet where simavr 1.6 departs from it, and the
 * UART bridge to lossless flow.
 * - TWI: a master that polls TWINT and accepts only the datasheet's status codes (START
 *   0x08, SLA+W ACK 0x18, data ACK 0x28) sets the four DRV2605L behind the TCA9548A up for
 *   real-time playback four ways; at the first other status it stops. Their outputs, by
 *   the DRV2605L datasheet: m1 unsigned and unidirectional, RTP 0x80 → 0x80 / 255; m2
 *   unsigned and bidirectional (CONTROL2's default), RTP 0xC0 → 0x40 / 127; m3 signed
 *   (CONTROL3's default), RTP 0x40 → 0x40 / 127; m4 left in standby, RTP 0xFF → 0.
 * - UART: echoes every byte it receives, polling, at 250000 baud; an 'E' lets the drivers'
 *   EN (PD2) float, as a reset does.
 * - ADC and PWM (pneumatic6): b2…b6 fully open, b1's duty the pressure sensor's reading
 *   (ADC0 against AVcc) / 4, again and again: with the simulated bellows b1 settles where
 *   the sensor's reading and its own duty agree.
 */
#include <avr/io.h>
#include <stdint.h>
#include <util/twi.h>

static uint8_t step(uint8_t control, uint8_t expected)
{
    TWCR = control;
    while (!(TWCR & _BV(TWINT)))
        ;
    return TW_STATUS == expected;
}

static uint8_t write(uint8_t address, uint8_t first, uint8_t second, uint8_t count)
{
    uint8_t ok = step(_BV(TWINT) | _BV(TWSTA) | _BV(TWEN), TW_START);
    if (ok) {
        TWDR = (uint8_t)(address << 1);
        ok = step(_BV(TWINT) | _BV(TWEN), TW_MT_SLA_ACK);
    }
    if (ok) {
        TWDR = first;
        ok = step(_BV(TWINT) | _BV(TWEN), TW_MT_DATA_ACK);
    }
    if (ok && count > 1) {
        TWDR = second;
        ok = step(_BV(TWINT) | _BV(TWEN), TW_MT_DATA_ACK);
    }
    TWCR = _BV(TWINT) | _BV(TWSTO) | _BV(TWEN);
    return ok;
}

int main(void)
{
    /* Driver, register, value. */
    static const uint8_t setup[][3] = {
        {0, 0x01, 0x00}, {0, 0x1A, 0xB6}, {0, 0x1C, 0x75}, {0, 0x1D, 0xA8}, {0, 0x01, 0x05},
        {0, 0x02, 0x80}, {1, 0x01, 0x00}, {1, 0x1A, 0xB6}, {1, 0x1D, 0xA8}, {1, 0x01, 0x05},
        {1, 0x02, 0xC0}, {2, 0x01, 0x00}, {2, 0x1A, 0xB6}, {2, 0x01, 0x05}, {2, 0x02, 0x40},
        {3, 0x1A, 0xB6}, {3, 0x02, 0xFF}};
    uint8_t i;
    uint8_t selected = 0xFF;
    UBRR0 = 3;
    UCSR0C = _BV(UCSZ01) | _BV(UCSZ00);
    UCSR0B = _BV(RXEN0) | _BV(TXEN0);
    /* PD2 is the drivers' EN (lra4): high, as the firmware drives it. */
    PORTD = _BV(PD2);
    DDRD = _BV(PD6) | _BV(PD5) | _BV(PD3) | _BV(PD2);
    DDRB = _BV(PB1) | _BV(PB2) | _BV(PB3);
    TCCR0A = _BV(COM0A1) | _BV(COM0B1) | _BV(WGM01) | _BV(WGM00);
    TCCR0B = _BV(CS01) | _BV(CS00);
    TCCR1A = _BV(COM1A1) | _BV(COM1B1) | _BV(WGM10);
    TCCR1B = _BV(WGM12) | _BV(CS11) | _BV(CS10);
    TCCR2A = _BV(COM2A1) | _BV(COM2B1) | _BV(WGM21) | _BV(WGM20);
    TCCR2B = _BV(CS22);
    OCR0B = 255;
    OCR1A = 255;
    OCR1B = 255;
    OCR2A = 255;
    OCR2B = 255;
    ADMUX = _BV(REFS0);
    ADCSRA = _BV(ADEN) | _BV(ADSC) | _BV(ADPS2) | _BV(ADPS1) | _BV(ADPS0);
    TWBR = 12;
    for (i = 0; i < sizeof setup / sizeof setup[0]; ++i) {
        if (setup[i][0] != selected) {
            selected = setup[i][0];
            if (!write(0x70, (uint8_t)(1u << selected), 0, 1))
                break;
        }
        if (!write(0x5A, setup[i][1], setup[i][2], 2))
            break;
    }
    for (;;) {
        if (!(ADCSRA & _BV(ADSC))) {
            OCR0A = (uint8_t)(ADC >> 2);
            ADCSRA |= _BV(ADSC);
        }
        if (UCSR0A & _BV(RXC0)) {
            const uint8_t byte = UDR0;
            if (byte == 'E')
                DDRD &= (uint8_t)~_BV(PD2); /* EN floats, as in a reset: drivers off */
            while (!(UCSR0A & _BV(UDRE0)))
                ;
            UDR0 = byte;
        }
    }
}
