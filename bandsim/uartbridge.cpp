// SPDX-License-Identifier: MIT
#include "uartbridge.h"

#include <avr_uart.h>
#include <sim_avr.h>

#include <cmath>
#include <ctime>
#include <poll.h>
#include <unistd.h>

namespace semhap {

namespace {

/**
 * Host bytes held back at most: ~10 ms of the line. More waits in the pty, so a host that
 * floods the band is held back by the pty as a real line holds it back.
 */
constexpr size_t MaxPending = 256;

} // namespace

UartBridge::UartBridge(avr_t *avr, int fd,
                       std::function<void(const std::uint8_t *, size_t)> handedOver)
    : m_fd(fd), m_handedOver(std::move(handedOver))
{
    const std::uint32_t uart = AVR_IOCTL_UART_GETIRQ('0');
    m_input = avr_io_getirq(avr, uart, UART_IRQ_INPUT);
    avr_irq_register_notify(avr_io_getirq(avr, uart, UART_IRQ_OUTPUT), &UartBridge::onOutput,
                            this);
    avr_irq_register_notify(avr_io_getirq(avr, uart, UART_IRQ_OUT_XON), &UartBridge::onXon, this);
    avr_irq_register_notify(avr_io_getirq(avr, uart, UART_IRQ_OUT_XOFF), &UartBridge::onXoff,
                            this);
    m_pending.reserve(MaxPending);
    m_toHost.reserve(1024);
}

void UartBridge::onOutput(avr_irq_t *, std::uint32_t value, void *param)
{
    static_cast<UartBridge *>(param)->m_toHost.push_back(std::uint8_t(value));
}

void UartBridge::onXon(avr_irq_t *, std::uint32_t, void *param)
{
    auto *self = static_cast<UartBridge *>(param);
    self->m_full = false;
    self->feed();
}

void UartBridge::onXoff(avr_irq_t *, std::uint32_t value, void *param)
{
    static_cast<UartBridge *>(param)->m_full = value != 0;
}

void UartBridge::feed()
{
    // Raising the input IRQ may raise XOFF, or (through the firmware) XON again: one loop.
    if (m_feeding)
        return;
    m_feeding = true;
    const size_t first = m_next;
    while (!m_full && m_next < m_pending.size())
        avr_raise_irq(m_input, m_pending[m_next++]);
    if (m_next > first && m_handedOver)
        m_handedOver(m_pending.data() + first, m_next - first);
    if (m_next == m_pending.size()) {
        m_pending.clear();
        m_next = 0;
    }
    m_feeding = false;
}

void UartBridge::waitForHost(double seconds)
{
    // With no room to take bytes, only the wait: the host's bytes stay in the pty.
    pollfd fd{m_fd, POLLIN, 0};
    const double wait = std::max(0.0, seconds);
    timespec timeout{};
    timeout.tv_sec = time_t(wait);
    timeout.tv_nsec = long((wait - double(timeout.tv_sec)) * 1e9);
    ::ppoll(&fd, m_pending.size() < MaxPending ? 1 : 0, &timeout, nullptr);
}

void UartBridge::takeFromHost()
{
    m_pending.erase(m_pending.begin(), m_pending.begin() + std::ptrdiff_t(m_next));
    m_next = 0;
    const size_t held = m_pending.size();
    if (held < MaxPending) {
        m_pending.resize(MaxPending);
        const ssize_t n = ::read(m_fd, m_pending.data() + held, MaxPending - held);
        m_pending.resize(held + size_t(std::max<ssize_t>(n, 0)));
    }
    feed();
}

void UartBridge::flushToHost()
{
    if (m_toHost.empty())
        return;
    // A full pty (no host reading) drops the bytes, as a UART line would.
    [[maybe_unused]] const ssize_t n = ::write(m_fd, m_toHost.data(), m_toHost.size());
    m_toHost.clear();
}

} // namespace semhap
