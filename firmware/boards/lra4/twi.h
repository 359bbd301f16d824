/* SPDX-License-Identifier: MIT */
#ifndef SEMHAP_TWI_H
#define SEMHAP_TWI_H

#include <stdint.h>

/* How an I2C write ended. */
enum twi_result
{
    TWI_OK,
    TWI_NACK, /* nobody answered the address, or the device refused a byte */
    TWI_BUS   /* the bus did not move in time (held low, no pull-ups), or arbitration lost */
};

/* Starts the TWI as master at 400 kHz on A4 (SDA) and A5 (SCL). */
void twi_init(void);

/*
 * Writes `size` bytes to the device at 7-bit `address`. Every wait is bounded (about 1 ms);
 * after a bus fault the bus is recovered (nine clocks and a stop) and the TWI restarted,
 * so a stuck bus never hangs the caller.
 */
enum twi_result twi_write(uint8_t address, const uint8_t *bytes, uint8_t size);

#endif
