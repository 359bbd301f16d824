// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

struct avr_t;
struct avr_irq_t;

namespace semhap {

/**
 * The chip's UART0 wired to the band's side of a pseudo-terminal, as a USB serial bridge
 * wires a board's UART to the host. Bytes from the host wait here until the UART's input
 * FIFO has room: simavr says so with its XON and XOFF IRQs, and the UART then delivers them
 * to the firmware at the line's byte rate, so none is lost. Bytes the firmware sends go to
 * the host as they leave the UART; a full pty (no host reading) drops them, as a line would.
 */
class UartBridge
{
public:
    /**
     * Attaches to `avr`'s UART0 and serves `fd` (non-blocking). `handedOver` is called with
     * each run of bytes as it enters the UART (for observers that time frames).
     */
    UartBridge(avr_t *avr, int fd, std::function<void(const std::uint8_t *, size_t)> handedOver);

    /** Waits up to `seconds` for the host to write (less when it writes). */
    void waitForHost(double seconds);
    /**
     * Takes what the host wrote (as much as is sensible to hold) and hands the UART what its
     * FIFO has room for, now.
     */
    void takeFromHost();
    /** Writes what the firmware sent since the last call. */
    void flushToHost();

private:
    static void onOutput(avr_irq_t *irq, std::uint32_t value, void *param);
    static void onXon(avr_irq_t *irq, std::uint32_t value, void *param);
    static void onXoff(avr_irq_t *irq, std::uint32_t value, void *param);
    /** Hands pending bytes to the UART until its FIFO is full or none are left. */
    void feed();

    avr_irq_t *m_input = nullptr;
    int m_fd = -1;
    std::function<void(const std::uint8_t *, size_t)> m_handedOver;
    bool m_full = true; ///< XOFF: the FIFO has no room (and none before the UART is enabled)
    bool m_feeding = false;
    std::vector<std::uint8_t> m_pending; ///< from the host, not yet in the UART
    size_t m_next = 0;                   ///< the first of m_pending not handed over
    std::vector<std::uint8_t> m_toHost;
};

} // namespace semhap
