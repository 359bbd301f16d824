// SPDX-License-Identifier: MIT
#include "pressuresensor.h"

#include <avr_adc.h>
#include <sim_avr.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>

namespace semhap {

PressureSensor::PressureSensor(avr_t *avr)
    : m_adc0(avr_io_getirq(avr, AVR_IOCTL_ADC_GETIRQ, ADC_IRQ_ADC0))
{
    avr_raise_irq(m_adc0, std::uint32_t(std::lround(m_volts * 1000.0)));
}

void PressureSensor::update(const std::vector<double> &pressures)
{
    const double mean =
        pressures.empty()
            ? 0.0
            : std::accumulate(pressures.begin(), pressures.end(), 0.0) / double(pressures.size());
    m_volts = EmptyVolts + (FullVolts - EmptyVolts) * std::clamp(mean, 0.0, 1.0);
    avr_raise_irq(m_adc0, std::uint32_t(std::lround(m_volts * 1000.0))); // in millivolts
}

} // namespace semhap
