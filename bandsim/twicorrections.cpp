// SPDX-License-Identifier: MIT
#include "twicorrections.h"

#include <avr_twi.h>
#include <sim_avr.h>

namespace semhap {

namespace {

// ATmega328P data addresses and TWI status codes (the datasheet, table 22-2).
constexpr std::uint16_t Twsr = 0xB9; ///< status in bits 7…3, the prescaler in bits 1…0
constexpr std::uint16_t Twcr = 0xBC;
constexpr std::uint8_t Twint = 0x80;
constexpr std::uint8_t AddressAck = 0x18;
constexpr std::uint8_t AddressNack = 0x20;
constexpr std::uint8_t DataAck = 0x28;
constexpr std::uint8_t DataNack = 0x30;

} // namespace

TwiCorrections::TwiCorrections(avr_t *avr) : m_avr(avr)
{
    const std::uint32_t twi = AVR_IOCTL_TWI_GETIRQ(0);
    // A second write handler on TWCR: simavr calls it after the TWI module's own.
    avr_register_io_write(avr, Twcr, &TwiCorrections::onControlWrite, this);
    avr_irq_register_notify(avr_io_getirq(avr, twi, TWI_IRQ_OUTPUT), &TwiCorrections::onMessage,
                            this);
    avr_irq_register_notify(avr_io_getirq(avr, twi, TWI_IRQ_STATUS), &TwiCorrections::onStatus,
                            this);
}

void TwiCorrections::onControlWrite(avr_t *avr, std::uint16_t, std::uint8_t value, void *)
{
    // The next status arrives later, from a timer, and sets TWINT again.
    if (value & Twint)
        avr->data[Twcr] = std::uint8_t(avr->data[Twcr] & ~Twint);
}

void TwiCorrections::onMessage(avr_irq_t *, std::uint32_t value, void *param)
{
    avr_twi_msg_irq_t message;
    message.u.v = value;
    if (message.u.twi.msg & TWI_COND_START)
        static_cast<TwiCorrections *>(param)->m_addressSent = (message.u.twi.addr & 1) == 0;
}

void TwiCorrections::onStatus(avr_irq_t *, std::uint32_t value, void *param)
{
    auto *self = static_cast<TwiCorrections *>(param);
    if (!self->m_addressSent)
        return;
    self->m_addressSent = false;
    std::uint8_t status = 0;
    if (value == DataAck)
        status = AddressAck;
    else if (value == DataNack)
        status = AddressNack;
    if (status != 0)
        self->m_avr->data[Twsr] = std::uint8_t((self->m_avr->data[Twsr] & 0x07) | status);
}

} // namespace semhap
