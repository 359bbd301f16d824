// SPDX-License-Identifier: MIT
#pragma once

#include "devicemodel.h"
#include "emulator.h"

#include <atomic>
#include <thread>

/**
 * An emulated band of a built-in model serving UDP loopback (or, with `udp` false, a
 * pseudo-terminal) on its own thread.
 */
class EmulatedBand
{
public:
    explicit EmulatedBand(const QString &model, bool udp = true) : m_emulator(options(model, udp))
    {}
    ~EmulatedBand()
    {
        m_quit = true;
        if (m_thread.joinable())
            m_thread.join();
    }
    bool start(QString *error)
    {
        if (!m_emulator.open(error))
            return false;
        m_thread = std::thread([this] { m_emulator.run([this] { return m_quit.load(); }); });
        return true;
    }
    QString uri() const { return m_emulator.uri(); }
    /** The pty's path, or HOST:PORT. */
    QString address() const { return m_emulator.address(); }
    semhap::Emulator::State state() const { return m_emulator.state(); }

private:
    static semhap::EmulatorOptions options(const QString &model, bool udp)
    {
        semhap::EmulatorOptions options;
        options.model = semhap::DeviceModelLibrary::builtin(model);
        options.udp = udp;
        return options;
    }

    semhap::Emulator m_emulator;
    std::atomic<bool> m_quit{false};
    std::thread m_thread;
};
