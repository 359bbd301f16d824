// SPDX-License-Identifier: MIT
#pragma once

#include <QString>

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

struct avr_t;

namespace semhap {

class FirmwareImage;

/**
 * The simulated chip of the reference boards: an ATmega328P at 16 MHz and 5 V in simavr,
 * its flash loaded from an image. Runs in slices up to a given cycle; a sleeping chip
 * skips ahead to its next event (a timer, the end of the slice) at no cost, so an idle
 * band is cheap. simavr's own pacing (usleep while the chip sleeps) is off: the caller
 * paces the chip to the wall clock.
 */
class AvrCore
{
public:
    static constexpr std::uint32_t Frequency = 16000000;

    AvrCore();
    ~AvrCore();
    AvrCore(const AvrCore &) = delete;
    AvrCore &operator=(const AvrCore &) = delete;

    /** Makes the chip and loads `image` into its flash; false with `error`. */
    bool load(const FirmwareImage &image, QString *error);
    /** The chip, for peripherals to attach to its IRQs; null before load(). */
    avr_t *avr() const { return m_avr.get(); }

    /** Cycles since power-on. */
    std::uint64_t cycle() const;
    /** Simulated seconds since power-on. */
    double seconds() const { return double(cycle()) / Frequency; }
    /** The cycle at `seconds` of simulated time. */
    static std::uint64_t cycleAt(double seconds);

    /**
     * Calls `callback` every `period` cycles of simulated time, from inside the simulation
     * (kept across a reset of the chip by its watchdog).
     */
    void every(std::uint64_t period, std::function<void()> callback);
    /**
     * Runs the chip until `cycle` (a sleeping chip skips there); false when it cannot go on
     * (it crashed, or it sleeps with interrupts off and would never wake), with the reason
     * in failure().
     */
    bool runUntil(std::uint64_t cycle) { return run(cycle, false); }
    /** As runUntil(), but stops early as soon as the chip is asleep. */
    bool runAwakeUntil(std::uint64_t cycle) { return run(cycle, true); }
    /** Whether the chip sleeps, waiting for an interrupt. */
    bool asleep() const;
    /** The cycle of the chip's next scheduled event (a timer, a byte on the line). */
    std::uint64_t nextEvent() const;
    const QString &failure() const { return m_failure; }

private:
    struct Deleter
    {
        void operator()(avr_t *avr) const;
    };
    struct Periodic
    {
        AvrCore *core;
        std::uint64_t period;
        std::function<void()> callback;
    };
    static std::uint64_t onPeriodic(avr_t *avr, std::uint64_t when, void *param);
    static std::uint64_t onSliceEnd(avr_t *avr, std::uint64_t when, void *param);
    /** Registers the periodic timers again when a reset has cleared them. */
    void keepTimers();
    bool run(std::uint64_t cycle, bool whileAwake);

    std::unique_ptr<avr_t, Deleter> m_avr;
    std::vector<std::unique_ptr<Periodic>> m_periodic;
    QString m_failure;
};

} // namespace semhap
