// SPDX-License-Identifier: MIT
#include "avrcore.h"

#include "firmwareimage.h"

#include <avr_uart.h>
#include <sim_avr.h>

#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>

#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SEMHAP_LEAK_CHECKED
#endif
#elif defined(__SANITIZE_ADDRESS__)
#define SEMHAP_LEAK_CHECKED
#endif

#ifdef SEMHAP_LEAK_CHECKED
/**
 * simavr 1.6's avr_terminate() frees its I/O modules but not the IRQs they made
 * (avr_init_irq: the pool, the names) nor their notify hooks: the library's leak, which
 * LeakSanitizer would otherwise blame on every `semhap bandsim` in the sanitizer build.
 */
extern "C" const char *__lsan_default_suppressions()
{
    return "leak:libsimavr.so\n";
}

/** Without the list of suppressions used on standard error, which tests read as the CLI's. */
extern "C" const char *__lsan_default_options()
{
    return "print_suppressions=0";
}
#endif

namespace semhap {

namespace {

/**
 * simavr's errors on standard error (a UART overrun, a crash); its warnings (modes it does
 * not simulate, such as a timer's passing through one while the firmware sets it up) and
 * traces (every TWI step) nowhere.
 */
void logger(avr_t *, const int level, const char *format, va_list arguments)
{
    if (level > LOG_ERROR)
        return;
    std::fputs("simavr: ", stderr);
    std::vfprintf(stderr, format, arguments);
}

/** The host paces the chip: simavr must not sleep on its own while the chip sleeps. */
void noSleep(avr_t *, avr_cycle_count_t) {}

} // namespace

void AvrCore::Deleter::operator()(avr_t *avr) const
{
    avr_terminate(avr);
    std::free(avr);
}

AvrCore::AvrCore() = default;

AvrCore::~AvrCore() = default;

bool AvrCore::load(const FirmwareImage &image, QString *error)
{
    avr_global_logger_set(logger);
    m_avr.reset(avr_make_mcu_by_name("atmega328p"));
    if (!m_avr || avr_init(m_avr.get()) != 0) {
        *error = QStringLiteral("simavr cannot make an ATmega328P");
        m_avr.reset();
        return false;
    }
    avr_t *avr = m_avr.get();
    if (image.flash().size() > avr->flashend + 1u) {
        *error = QStringLiteral("%1: %2 bytes, more than the ATmega328P's %3 bytes of flash")
                     .arg(image.name())
                     .arg(image.flash().size())
                     .arg(avr->flashend + 1u);
        return false;
    }
    avr->frequency = Frequency;
    avr->vcc = avr->avcc = avr->aref = 5000; // mV: the boards run at 5 V, the ADC on AVcc
    avr->sleep = noSleep;
    avr->log = LOG_ERROR;
    std::vector<std::uint8_t> flash = image.flash();
    avr_loadcode(avr, flash.data(), std::uint32_t(flash.size()), 0);
    // No console echo of the UART and no usleep when firmware polls it: the bridge paces.
    std::uint32_t flags = 0;
    avr_ioctl(avr, AVR_IOCTL_UART_GET_FLAGS('0'), &flags);
    flags &= ~std::uint32_t(AVR_UART_FLAG_POLL_SLEEP | AVR_UART_FLAG_STDIO);
    avr_ioctl(avr, AVR_IOCTL_UART_SET_FLAGS('0'), &flags);
    return true;
}

std::uint64_t AvrCore::cycle() const
{
    return m_avr ? m_avr->cycle : 0;
}

std::uint64_t AvrCore::cycleAt(double seconds)
{
    return std::uint64_t(std::llround(std::max(0.0, seconds) * Frequency));
}

void AvrCore::every(std::uint64_t period, std::function<void()> callback)
{
    m_periodic.push_back(std::make_unique<Periodic>(Periodic{this, period, std::move(callback)}));
    avr_cycle_timer_register(m_avr.get(), period, &AvrCore::onPeriodic, m_periodic.back().get());
}

std::uint64_t AvrCore::onPeriodic(avr_t *, std::uint64_t when, void *param)
{
    auto *periodic = static_cast<Periodic *>(param);
    periodic->callback();
    return when + periodic->period;
}

std::uint64_t AvrCore::onSliceEnd(avr_t *, std::uint64_t, void *)
{
    return 0; // only there so that a sleeping chip wakes up at the end of the slice
}

void AvrCore::keepTimers()
{
    for (const std::unique_ptr<Periodic> &periodic : m_periodic) {
        if (avr_cycle_timer_status(m_avr.get(), &AvrCore::onPeriodic, periodic.get()) == 0)
            avr_cycle_timer_register(m_avr.get(), periodic->period, &AvrCore::onPeriodic,
                                     periodic.get());
    }
}

bool AvrCore::asleep() const
{
    return m_avr->state == cpu_Sleeping;
}

std::uint64_t AvrCore::nextEvent() const
{
    const avr_cycle_timer_slot_t *next = m_avr->cycle_timers.timer;
    return next ? next->when : m_avr->cycle;
}

bool AvrCore::run(std::uint64_t cycle, bool whileAwake)
{
    avr_t *avr = m_avr.get();
    if (cycle <= avr->cycle)
        return true;
    keepTimers();
    avr_cycle_timer_register(avr, cycle - avr->cycle, &AvrCore::onSliceEnd, this);
    while (avr->cycle < cycle) {
        if (whileAwake && avr->state == cpu_Sleeping) {
            // Not needed any more: left in place, it would look like the chip's next event.
            avr_cycle_timer_cancel(avr, &AvrCore::onSliceEnd, this);
            break;
        }
        const int state = avr_run(avr);
        if (state == cpu_Crashed || state == cpu_Stopped) {
            m_failure = QStringLiteral("the simulated chip crashed at PC 0x%1 after %2 s")
                            .arg(avr->pc, 4, 16, QLatin1Char('0'))
                            .arg(seconds(), 0, 'f', 3);
            return false;
        }
        if (state == cpu_Done) {
            m_failure = QStringLiteral("the simulated chip went to sleep with interrupts off "
                                       "at PC 0x%1 after %2 s: it would never wake again")
                            .arg(avr->pc, 4, 16, QLatin1Char('0'))
                            .arg(seconds(), 0, 'f', 3);
            return false;
        }
    }
    return true;
}

} // namespace semhap
