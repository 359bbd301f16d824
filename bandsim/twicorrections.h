// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>

struct avr_t;
struct avr_irq_t;

namespace semhap {

/**
 * Makes simavr 1.6's TWI (Debian's; fixed upstream later) behave as the ATmega328P's does
 * for a master, so that firmware written against the datasheet runs unchanged:
 * - writing TWCR with TWINT set clears TWINT (1.6 leaves it set, so a firmware that polls
 *   TWINT sees its next byte done at once, with the old status);
 * - an address byte's acknowledge reads as 0x18 / 0x20 (SLA+W ACK / NACK), where 1.6
 *   reports a data byte's 0x28 / 0x30 whenever TWDR was loaded before TWINT was cleared —
 *   which is always.
 * On a simavr without these faults both corrections find nothing to do.
 */
class TwiCorrections
{
public:
    explicit TwiCorrections(avr_t *avr);

private:
    static void onControlWrite(avr_t *avr, std::uint16_t address, std::uint8_t value, void *param);
    static void onMessage(avr_irq_t *irq, std::uint32_t value, void *param);
    static void onStatus(avr_irq_t *irq, std::uint32_t value, void *param);

    avr_t *m_avr;
    bool m_addressSent = false; ///< an SLA+W went out; its status comes next
};

} // namespace semhap
