// SPDX-License-Identifier: MIT
#pragma once

#include "bandstatelog.h"
#include "devicemodel.h"
#include "pseudoterminal.h"

#include <QString>
#include <QStringList>

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace semhap {

class AvrCore;
class Drv2605lBus;
class PressureSensor;
class PwmOutputs;
class TwiCorrections;
class UartBridge;

/** Which reference band to simulate, with which image, and where it serves and logs. */
struct BandSimOptions
{
    DeviceModelPtr model; ///< lra4 or pneumatic6 (BandSimulator::models())
    QString firmware;     ///< an Intel HEX image to run; empty: the model's built-in image
    QString link;         ///< a symlink kept pointing at the pty (replaced if stale)
    QString logPath;      ///< JSON Lines state log, as `semhap emulate --log`; empty: none
};

/**
 * What an in-process observer (the command's report, a test, the benchmark) may watch;
 * called on run()'s thread.
 */
class BandSimObserver
{
public:
    virtual ~BandSimObserver();
    /** Bytes from the host entered the chip's UART at simulated time `t` (s). */
    virtual void hostBytes(double t, const std::uint8_t *bytes, size_t size);
    /** The firmware wrote `value` to register `reg` of channel `channel`'s DRV2605L. */
    virtual void driverWrite(double t, int channel, std::uint8_t reg, std::uint8_t value);
    /**
     * At simulated time `t` the chip was `behind` seconds behind the wall clock (its process
     * did not run) and gave up catching up on `skipped` of them: that much wall time is
     * missing from the simulated time line there, so host bytes around it arrive closer
     * together in `t` than they were sent.
     */
    virtual void fellBehind(double t, double behind, double skipped);
};

/**
 * A reference band with its real firmware image on a simulated ATmega328P (simavr), paced
 * to the wall clock: the chip's UART on a pseudo-terminal (a host talks to it with
 * `serial:PTY` as to the board), and the chip's outputs as the hardware would
 * see them — lra4's DRV2605L drivers behind their TCA9548A on I2C, pneumatic6's six PWM
 * valve outputs and its pressure sensor on ADC0. It logs what the chip drives and the
 * device model's response to it, in the format of `semhap emulate --log`, with `t` in
 * simulated seconds since power-on.
 */
class BandSimulator
{
public:
    /** The models with a reference board: lra4 and pneumatic6. */
    static QStringList models();

    explicit BandSimulator(const BandSimOptions &options);
    ~BandSimulator();
    BandSimulator(const BandSimulator &) = delete;
    BandSimulator &operator=(const BandSimulator &) = delete;

    /** Loads the image onto the chip, creates the pty (and link), opens the log; false with
     * `error`. */
    bool open(QString *error);
    /** The pty's path. */
    QString address() const { return m_pty.path(); }
    /** The URI a host uses: `serial:LINK-or-PTY`. */
    QString uri() const;
    /** Watches the chip from run()'s thread; set before run(), null for none. */
    void setObserver(BandSimObserver *observer) { m_observer = observer; }
    /**
     * Runs the chip in step with the wall clock until `quit()` returns true (asked at least
     * once per step of the device model's response, 2 or 10 ms, and at once after a
     * signal), the log cannot be written or the chip stops (a crash): false then, the
     * reason in error().
     */
    bool run(const std::function<bool()> &quit);
    /** `LOG: cannot write: reason`, or `IMAGE: the simulated chip …`; empty while running. */
    const QString &error() const { return m_error; }
    /** Simulated seconds since power-on; from run()'s thread, or after run() returned. */
    double seconds() const;
    /** Simulated seconds reached, from any thread: as of run()'s latest step. */
    double reached() const { return m_reached.load(std::memory_order_relaxed); }

private:
    void outputChanged(int channel, double output);
    void tick();
    void log();

    BandSimOptions m_options;
    QString m_imageName;
    PseudoTerminal m_pty;
    BandStateLog m_log;
    std::unique_ptr<AvrCore> m_core;
    std::unique_ptr<UartBridge> m_uart;
    std::unique_ptr<TwiCorrections> m_twi;
    std::unique_ptr<Drv2605lBus> m_drivers;
    std::unique_ptr<PwmOutputs> m_valves;
    std::unique_ptr<PressureSensor> m_pressure;
    std::vector<double> m_setpoints; ///< what the chip drives, in the model's units
    std::vector<double> m_values;    ///< the device model's response to it
    std::vector<ResponseFilter> m_filters;
    BandSimObserver *m_observer = nullptr;
    QString m_error;
    std::atomic<double> m_reached{0.0};
};

} // namespace semhap
