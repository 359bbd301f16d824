// SPDX-License-Identifier: MIT
#include "drv2605lbus.h"

#include <avr_twi.h>
#include <sim_avr.h>

#include <algorithm>

namespace semhap {

namespace {

// The drivers' EN on the ATmega328P: PD2; port D's registers in data space.
constexpr std::uint16_t DDRD_ADDRESS = 0x2A;
constexpr std::uint16_t PORTD_ADDRESS = 0x2B;
constexpr std::uint8_t EnableBit = 1u << 2;

/** A DRV2605L's registers after power-on or DEV_RESET (the datasheet's register map). */
std::array<std::uint8_t, 256> resetRegisters()
{
    std::array<std::uint8_t, 256> r{};
    r[0x00] = 0xE0; // STATUS: DEVICE_ID 7, the DRV2605L
    r[0x01] = 0x40; // MODE: standby, internal trigger
    r[0x03] = 0x01; // LIBRARY_SEL
    r[0x04] = 0x01; // the first waveform sequencer slot
    r[0x11] = 0x05; // audio-to-vibe control and levels
    r[0x12] = 0x19;
    r[0x13] = 0xFF;
    r[0x14] = 0x19;
    r[0x15] = 0xFF;
    r[0x16] = 0x3E; // RATED_VOLTAGE
    r[0x17] = 0x8C; // OD_CLAMP
    r[0x18] = 0x0C; // A_CAL_COMP
    r[0x19] = 0x6C; // A_CAL_BEMF
    r[0x1A] = 0x36; // FEEDBACK: an ERM until told otherwise
    r[0x1B] = 0x93; // CONTROL1
    r[0x1C] = 0xF5; // CONTROL2: bidirectional input
    r[0x1D] = 0xA0; // CONTROL3: signed RTP data
    r[0x1E] = 0x20; // CONTROL4
    r[0x1F] = 0x80; // CONTROL5
    r[0x20] = 0x33; // LRA_OPEN_LOOP_PERIOD
    return r;
}

} // namespace

Drv2605lBus::Drv2605lBus(avr_t *avr, int channels, WriteHandler written, OutputHandler changed)
    : m_avr(avr), m_written(std::move(written)), m_changed(std::move(changed)),
      m_registers(size_t(channels), resetRegisters()), m_outputs(size_t(channels), 0.0)
{
    const std::uint32_t twi = AVR_IOCTL_TWI_GETIRQ(0);
    m_toMaster = avr_io_getirq(avr, twi, TWI_IRQ_INPUT);
    avr_irq_register_notify(avr_io_getirq(avr, twi, TWI_IRQ_OUTPUT), &Drv2605lBus::onMessage,
                            this);
}

void Drv2605lBus::onMessage(avr_irq_t *, std::uint32_t value, void *param)
{
    avr_twi_msg_irq_t message;
    message.u.v = value;
    static_cast<Drv2605lBus *>(param)->message(std::uint8_t(message.u.twi.msg),
                                               std::uint8_t(message.u.twi.addr),
                                               std::uint8_t(message.u.twi.data));
}

void Drv2605lBus::followEnable()
{
    // Driven high only as an output at 1: an input (a reset) floats, and the pull-down wins.
    const bool enabled =
        (m_avr->data[DDRD_ADDRESS] & EnableBit) && (m_avr->data[PORTD_ADDRESS] & EnableBit);
    if (enabled == m_enabled)
        return;
    m_enabled = enabled;
    for (size_t k = 0; k < m_registers.size(); ++k)
        update(int(k));
}

void Drv2605lBus::acknowledge(std::uint8_t address)
{
    avr_raise_irq(m_toMaster, avr_twi_irq_msg(TWI_COND_ACK, address, 1));
}

void Drv2605lBus::message(std::uint8_t kind, std::uint8_t address, std::uint8_t data)
{
    if (kind & TWI_COND_STOP) {
        m_target = Target::None;
        return;
    }
    if (kind & TWI_COND_START) {
        followEnable();
        m_address = address;
        m_pointerSet = false;
        const std::uint8_t device = address >> 1;
        const std::uint8_t connected =
            std::uint8_t(m_muxControl & ((1u << m_registers.size()) - 1u));
        if (device == MuxAddress)
            m_target = Target::Mux;
        else if (device == DriverAddress && connected != 0 && m_enabled)
            m_target = Target::Drivers;
        else
            m_target = Target::None; // nobody answers: the master sees a NACK
        if (m_target != Target::None)
            acknowledge(address);
        return;
    }
    if (m_target == Target::None)
        return;
    if (kind & TWI_COND_WRITE) {
        acknowledge(address);
        write(data);
    } else if (kind & TWI_COND_READ) {
        avr_raise_irq(m_toMaster, avr_twi_irq_msg(TWI_COND_READ, address, read()));
    }
}

void Drv2605lBus::write(std::uint8_t data)
{
    if (m_target == Target::Mux) {
        m_muxControl = data;
        return;
    }
    if (!m_pointerSet) {
        m_pointer = data;
        m_pointerSet = true;
        return;
    }
    for (size_t k = 0; k < m_registers.size(); ++k) {
        if (m_muxControl & (1u << k))
            writeDriver(int(k), m_pointer, data);
    }
    ++m_pointer; // the DRV2605L increments its pointer after each byte
}

std::uint8_t Drv2605lBus::read()
{
    if (m_target == Target::Mux)
        return m_muxControl;
    // Several connected drivers answer at once: the open-drain bus reads their AND.
    std::uint8_t value = 0xFF;
    for (size_t k = 0; k < m_registers.size(); ++k) {
        if (m_muxControl & (1u << k))
            value &= m_registers[k][m_pointer];
    }
    ++m_pointer;
    return value;
}

void Drv2605lBus::writeDriver(int channel, std::uint8_t reg, std::uint8_t value)
{
    if (m_written)
        m_written(channel, reg, value);
    std::array<std::uint8_t, 256> &r = m_registers[size_t(channel)];
    if (reg == Mode && (value & 0x80))
        r = resetRegisters(); // DEV_RESET
    else if (reg != 0x00)     // STATUS is read-only
        r[reg] = value;
    update(channel);
}

void Drv2605lBus::update(int channel)
{
    const std::array<std::uint8_t, 256> &r = m_registers[size_t(channel)];
    const std::uint8_t rtp = r[RtpInput];
    int level = std::int8_t(rtp); // signed data: 0x7F is full drive, negatives brake
    int full = 127;
    if (r[Control3] & 0x08) { // unsigned data
        const bool bidirectional = r[Control2] & 0x80;
        level = bidirectional ? rtp - 128 : rtp;
        full = bidirectional ? 127 : 255;
    }
    const bool playing =
        m_enabled && !(r[Mode] & 0x40) && (r[Mode] & 0x07) == 5 && (r[Feedback] & 0x80);
    const double output = playing ? std::max(0, level) / double(full) : 0.0;
    if (output != m_outputs[size_t(channel)]) {
        m_outputs[size_t(channel)] = output;
        if (m_changed)
            m_changed(channel, output);
    }
}

} // namespace semhap
