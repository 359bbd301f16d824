// SPDX-License-Identifier: MIT
#pragma once

#include "devicemodel.h"
#include "emulator.h"

#include <atomic>
#include <thread>

/** An emulated band of a built-in model serving UDP loopback on its own thread. */
class EmulatedBand
{
public:
    explicit EmulatedBand(const QString &model) : m_emulator(options(model)) {}
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
    semhap::Emulator::State state() const { return m_emulator.state(); }

private:
    static semhap::EmulatorOptions options(const QString &model)
    {
        semhap::EmulatorOptions options;
        options.model = semhap::DeviceModelLibrary::builtin(model);
        options.udp = true;
        return options;
    }

    semhap::Emulator m_emulator;
    std::atomic<bool> m_quit{false};
    std::thread m_thread;
};
