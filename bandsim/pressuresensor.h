// SPDX-License-Identifier: MIT
#pragma once

#include <vector>

struct avr_t;
struct avr_irq_t;

namespace semhap {

/**
 * pneumatic6's pressure sensor on ADC0, a 0.2…4.7 V sensor over its full scale: it reads
 * the mean of the six bellows' modelled pressures (the device model's response to the valve
 * duties, what the log's `values` hold), 0 → 0.2 V, 1 → 4.7 V. Even all six bellows full
 * read 4.7 V, ADC 961 of 1023: below the firmware's overpressure level (980), as a sound
 * band in normal use stays.
 */
class PressureSensor
{
public:
    static constexpr double EmptyVolts = 0.2;
    static constexpr double FullVolts = 4.7;

    explicit PressureSensor(avr_t *avr);
    /** Sets the sensor's voltage from the bellows' pressures (each 0…1). */
    void update(const std::vector<double> &pressures);
    double volts() const { return m_volts; }

private:
    avr_irq_t *m_adc0;
    double m_volts = EmptyVolts;
};

} // namespace semhap
