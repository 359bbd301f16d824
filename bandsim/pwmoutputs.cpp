// SPDX-License-Identifier: MIT
#include "pwmoutputs.h"

#include <sim_avr.h>

#include <algorithm>

namespace semhap {

namespace {

// ATmega328P data addresses (the datasheet's register summary).
constexpr std::uint16_t Ddrb = 0x24, Portb = 0x25, Ddrd = 0x2A, Portd = 0x2B;
constexpr std::uint16_t Tccr0a = 0x44, Tccr0b = 0x45, Ocr0a = 0x47, Ocr0b = 0x48;
constexpr std::uint16_t Tccr1a = 0x80, Tccr1b = 0x81, Ocr1al = 0x88, Ocr1ah = 0x89, Ocr1bl = 0x8A,
                        Ocr1bh = 0x8B;
constexpr std::uint16_t Tccr2a = 0xB0, Tccr2b = 0xB1, Ocr2a = 0xB3, Ocr2b = 0xB4;

/** Where a channel's output comes from. */
struct Output
{
    int timer;             ///< 0, 1 or 2
    bool b;                ///< compare unit B (else A)
    std::uint16_t ocr;     ///< its compare register (the low byte for Timer1)
    std::uint16_t ocrHigh; ///< Timer1's high byte, else 0
    std::uint16_t ddr, port;
    int bit;
};

constexpr std::array<Output, PwmOutputs::Count> Outputs{{
    {0, false, Ocr0a, 0, Ddrd, Portd, 6},       // b1: D6
    {0, true, Ocr0b, 0, Ddrd, Portd, 5},        // b2: D5
    {1, false, Ocr1al, Ocr1ah, Ddrb, Portb, 1}, // b3: D9
    {1, true, Ocr1bl, Ocr1bh, Ddrb, Portb, 2},  // b4: D10
    {2, false, Ocr2a, 0, Ddrb, Portb, 3},       // b5: D11
    {2, true, Ocr2b, 0, Ddrd, Portd, 3},        // b6: D3
}};

constexpr std::array<std::uint16_t, 18> Watched{Ddrb,   Portb,  Ddrd,   Portd,  Tccr0a, Tccr0b,
                                                Ocr0a,  Ocr0b,  Tccr1a, Tccr1b, Ocr1al, Ocr1ah,
                                                Ocr1bl, Ocr1bh, Tccr2a, Tccr2b, Ocr2a,  Ocr2b};

} // namespace

PwmOutputs::PwmOutputs(avr_t *avr, OutputHandler changed)
    : m_avr(avr), m_changed(std::move(changed))
{
    for (const std::uint16_t address : Watched)
        avr_irq_register_notify(avr_iomem_getirq(avr, address, nullptr, AVR_IOMEM_IRQ_ALL),
                                &PwmOutputs::onWrite, this);
}

void PwmOutputs::onWrite(avr_irq_t *, std::uint32_t, void *param)
{
    static_cast<PwmOutputs *>(param)->update();
}

double PwmOutputs::duty(int channel) const
{
    const Output &o = Outputs[size_t(channel)];
    const std::uint8_t *data = m_avr->data;
    const std::uint16_t tccra = o.timer == 0 ? Tccr0a : o.timer == 1 ? Tccr1a : Tccr2a;
    const std::uint16_t tccrb = std::uint16_t(tccra + 1);
    const int com = (data[tccra] >> (o.b ? 4 : 6)) & 3;
    // Waveform generation mode: WGMn1:0 in TCCRnA, WGMn2 (and WGM13) in TCCRnB.
    const int wgm = (data[tccra] & 3) | ((data[tccrb] >> 1) & (o.timer == 1 ? 0xC : 0x4));
    const bool fastPwm8 = o.timer == 1 ? wgm == 5 : wgm == 3;
    const bool running = (data[tccrb] & 7) != 0;
    if (com >= 2 && fastPwm8 && running) {
        const int ocr = std::min(255, data[o.ocr] | (o.ocrHigh ? data[o.ocrHigh] << 8 : 0));
        return com == 2 ? (ocr + 1) / 256.0 : (255 - ocr) / 256.0;
    }
    const bool output = data[o.ddr] & (1 << o.bit);
    return output && (data[o.port] & (1 << o.bit)) ? 1.0 : 0.0;
}

void PwmOutputs::update()
{
    for (int c = 0; c < Count; ++c) {
        const double d = duty(c);
        if (d != m_duties[size_t(c)]) {
            m_duties[size_t(c)] = d;
            if (m_changed)
                m_changed(c, d);
        }
    }
}

} // namespace semhap
