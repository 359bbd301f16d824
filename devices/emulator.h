// SPDX-License-Identifier: MIT
#pragma once

#include "bandstatelog.h"
#include "devicemodel.h"
#include "protocol.h"
#include "pseudoterminal.h"

#include <QString>

#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

struct semhap_band;
struct semhap_band_channel;
struct semhap_band_hw;
struct semhap_band_model;

namespace semhap {

/** Where and how an emulated band listens. */
struct EmulatorOptions
{
    DeviceModelPtr model;
    bool udp = false;                           ///< a UDP port instead of a pseudo-terminal
    QString host = QStringLiteral("127.0.0.1"); ///< UDP: the address to bind
    int port = 0;                               ///< UDP: 0 picks a free port
    QString link;           ///< pty: a symlink kept pointing at the pty (replaced if stale)
    QString logPath;        ///< JSON Lines state log; empty: none
    double watchdog = 0.25; ///< s without a valid frame before every setpoint goes to 0
};

/**
 * A wristband in software, for tests and for working without hardware: the band firmware's
 * core (firmware/core, the same C library the reference boards run) compiled for the host,
 * listening on a pseudo-terminal or a UDP port, plus the device model's response applied at
 * the model's rate. It logs its state as JSON Lines (`{"t", "setpoint", "values"}`) at
 * every change.
 */
class Emulator
{
public:
    /** What the band is doing, for in-process tests. */
    struct State
    {
        std::vector<double> setpoints;
        std::vector<double> values;
        protocol::DeviceStatus status;
        int watchdogTrips = 0;
    };

    explicit Emulator(const EmulatorOptions &options);
    ~Emulator();
    Emulator(const Emulator &) = delete;
    Emulator &operator=(const Emulator &) = delete;

    /** Creates the pty (and link) or binds the port, opens the log; false with `error`. */
    bool open(QString *error);
    /** The pty's path, or HOST:PORT. */
    QString address() const;
    /** The URI a host uses: `serial:LINK-or-PTY` or `udp:HOST:PORT`. */
    QString uri() const;
    /**
     * Serves until `quit()` returns true (checked at least every tick), or until the log
     * cannot be written: false then, with `LOG: cannot write: reason` in logError().
     */
    bool run(const std::function<bool()> &quit);
    /** Why the log could not be written; empty while it can. */
    const QString &logError() const { return m_logError; }
    State state() const;

private:
    bool openUdp(QString *error);
    void receive();
    /** The band's counters into m_state; with m_mutex held. */
    void readStatus();
    void tick(double now);
    void log(double now);

    // The firmware's hardware interface.
    static void write(void *context, const std::uint8_t *bytes, size_t size);
    static std::uint32_t millis(void *context);
    static void setOutput(void *context, std::uint8_t channel, std::uint16_t value);

    EmulatorOptions m_options;
    PseudoTerminal m_pty;
    int m_fd = -1; ///< the pty's band side, or the UDP socket
    int m_boundPort = 0;
    std::vector<unsigned char> m_peer; ///< UDP: the last sender's address
    std::vector<std::string> m_names;  ///< the model's and its channels' names, for the band
    std::unique_ptr<semhap_band_channel[]> m_channels;
    std::unique_ptr<semhap_band_model> m_bandModel;
    std::unique_ptr<semhap_band_hw> m_hw;
    std::unique_ptr<semhap_band> m_band; ///< driven by run()'s thread only
    std::vector<ResponseFilter> m_filters;
    BandStateLog m_log;
    State m_logged; ///< the state the log last saw, copied out of m_state under m_mutex
    QString m_logError;
    double m_start = 0.0;

    mutable std::mutex m_mutex; ///< guards m_state against state() from other threads
    State m_state;
};

} // namespace semhap
