/* SPDX-License-Identifier: MIT */
/*
 * pneumatic6: six valves on the chip's six hardware PWM outputs (8 bits, 976 Hz: every
 * timer in fast PWM with prescaler 64) and a pressure sensor on ADC0. Channel bK's value v
 * sets the compare register to v >> 8: open (v >> 8) + 1 counts of 256, fully open at 255;
 * 0 disconnects the compare output and holds the pin low instead, since fast PWM would
 * still leave that one-count spike each period.
 */
#include "board.h"

#include <avr/io.h>
#include <stddef.h>

#define VALVE_COUNT 6
/* The overpressure level: ADC 980 of 1023 (4.79 V with AVcc at 5 V), above a 0.2…4.7 V
 * sensor's full scale, in the sensor range of band.h (see SCALED). */
#define OVERPRESSURE_ADC 980u
/* A first conversion takes 25 ADC clocks (200 µs at 125 kHz). */
#define ADC_WAIT_SPINS 2000u

/* One valve: its compare register, its timer's control register A and compare bit there,
 * its port and pin. */
typedef struct valve
{
    volatile uint8_t *compare;
    volatile uint8_t *control;
    uint8_t connect;
    volatile uint8_t *port;
    uint8_t pin;
} valve;

static const valve valves[VALVE_COUNT] = {
    {&OCR0A, &TCCR0A, _BV(COM0A1), &PORTD, _BV(PD6)},  /* b1: D6, OC0A */
    {&OCR0B, &TCCR0A, _BV(COM0B1), &PORTD, _BV(PD5)},  /* b2: D5, OC0B */
    {&OCR1AL, &TCCR1A, _BV(COM1A1), &PORTB, _BV(PB1)}, /* b3: D9, OC1A */
    {&OCR1BL, &TCCR1A, _BV(COM1B1), &PORTB, _BV(PB2)}, /* b4: D10, OC1B */
    {&OCR2A, &TCCR2A, _BV(COM2A1), &PORTB, _BV(PB3)},  /* b5: D11, OC2A */
    {&OCR2B, &TCCR2A, _BV(COM2B1), &PORTD, _BV(PD3)},  /* b6: D3, OC2B */
};

/* A 10-bit reading across the 16-bit sensor range, 1023 to 65535, by repeating its top
 * bits below it: strictly increasing, so "at or above the scaled level" is exactly "at or
 * above 980". */
#define SCALED(adc) ((uint16_t)((adc) << 6 | (adc) >> 4))

static uint16_t latest_adc;

static void pneumatic6_init(void)
{
    uint16_t spins;
    uint8_t v;
    for (v = 0; v < VALVE_COUNT; ++v)
        *valves[v].port &= (uint8_t)~valves[v].pin;
    DDRD |= _BV(PD6) | _BV(PD5) | _BV(PD3);
    DDRB |= _BV(PB1) | _BV(PB2) | _BV(PB3);
    /* Timer0 runs the clock in fast PWM already (clock.c). Timer1: 8-bit fast PWM (mode
     * 5); Timer2: fast PWM (mode 3); both at prescaler 64. Outputs stay disconnected. */
    TCCR1A = _BV(WGM10);
    /* Whole 16-bit writes set the high bytes (and the shared TEMP byte) to 0 once; from
     * then on writing the low byte alone is a whole write. */
    OCR1A = 0;
    OCR1B = 0;
    TCCR1B = _BV(WGM12) | _BV(CS11) | _BV(CS10);
    TCCR2A = _BV(WGM21) | _BV(WGM20);
    TCCR2B = _BV(CS22);
    /* ADC0 against AVcc, 125 kHz ADC clock; the pin's digital input off. */
    ADMUX = _BV(REFS0);
    DIDR0 = _BV(ADC0D);
    ADCSRA = _BV(ADEN) | _BV(ADSC) | _BV(ADPS2) | _BV(ADPS1) | _BV(ADPS0);
    for (spins = 0; spins < ADC_WAIT_SPINS && (ADCSRA & _BV(ADSC)); ++spins)
        ;
    latest_adc = ADC;
    ADCSRA |= _BV(ADSC);
}

static void pneumatic6_set_output(void *context, uint8_t channel, uint16_t value)
{
    const valve *v = &valves[channel];
    const uint8_t duty = (uint8_t)(value >> 8);
    (void)context;
    if (duty == 0) {
        /* The pin's PORT bit is 0: it drives low. The compare register goes to 0 as well,
         * so that it too reads "closed" (a simulator's PWM readout watches it). */
        *v->control &= (uint8_t)~v->connect;
        *v->compare = 0;
        return;
    }
    *v->compare = duty;
    *v->control |= v->connect;
}

/* The latest finished conversion; starts the next one. Never waits. */
static uint16_t pneumatic6_read_sensor(void *context, uint8_t sensor)
{
    (void)context;
    (void)sensor;
    if (!(ADCSRA & _BV(ADSC))) {
        latest_adc = ADC;
        ADCSRA |= _BV(ADSC);
    }
    return SCALED(latest_adc);
}

static const semhap_band_channel channels[VALVE_COUNT] = {
    SEMHAP_BOARD_CHANNEL("b1"), SEMHAP_BOARD_CHANNEL("b2"), SEMHAP_BOARD_CHANNEL("b3"),
    SEMHAP_BOARD_CHANNEL("b4"), SEMHAP_BOARD_CHANNEL("b5"), SEMHAP_BOARD_CHANNEL("b6")};

static const semhap_band_model model = {
    "pneumatic6", {1, 0, 0}, VALVE_COUNT, channels, 0, 0, SCALED(OVERPRESSURE_ADC)};

const semhap_board semhap_this_board = {&model, pneumatic6_init, pneumatic6_set_output,
                                        pneumatic6_read_sensor, NULL};
