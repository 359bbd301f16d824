// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <cstdint>
#include <functional>

struct avr_t;
struct avr_irq_t;

namespace semhap {

/**
 * pneumatic6's six valve outputs, read from the chip's timer registers as the pins would
 * drive them: OC0A, OC0B, OC1A, OC1B, OC2A, OC2B (D6, D5, D9, D10, D11, D3). An output
 * connected to its timer in 8-bit fast PWM has a duty of (OCR + 1) / 256 (non-inverting)
 * or (255 − OCR) / 256 (inverting); a disconnected output, or one in any other waveform
 * mode or with its timer stopped, reads its pin: 1 when it is an output driven high, else 0.
 * Recomputed at every firmware write to the timers' or ports' registers.
 */
class PwmOutputs
{
public:
    static constexpr int Count = 6;
    /** A channel's duty changed. */
    using OutputHandler = std::function<void(int channel, double duty)>;

    PwmOutputs(avr_t *avr, OutputHandler changed);

    double output(int channel) const { return m_duties[size_t(channel)]; }

private:
    static void onWrite(avr_irq_t *irq, std::uint32_t value, void *param);
    void update();
    double duty(int channel) const;

    avr_t *m_avr;
    OutputHandler m_changed;
    std::array<double, Count> m_duties{};
};

} // namespace semhap
