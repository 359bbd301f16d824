// SPDX-License-Identifier: MIT
#include "bandsimulator.h"

#include "avrcore.h"
#include "drv2605lbus.h"
#include "firmwareimage.h"
#include "monotonic.h"
#include "pressuresensor.h"
#include "pwmoutputs.h"
#include "twicorrections.h"
#include "uartbridge.h"

#include <cmath>

namespace semhap {

namespace {

const QString Lra4 = QStringLiteral("lra4");
const QString Pneumatic6 = QStringLiteral("pneumatic6");

/**
 * How far a busy chip runs ahead of the wall clock before the host's bytes are read again:
 * the most a byte's arrival is delayed in simulated time (a sleeping chip takes them when
 * they arrive).
 */
constexpr double Slice = 250e-6;
/**
 * How far the chip may fall behind (a stopped debugger, an overloaded machine) before it
 * gives up catching up: past this it runs on from where it is, without racing.
 */
constexpr double MaxLag = 0.05;

} // namespace

BandSimObserver::~BandSimObserver() = default;

void BandSimObserver::hostBytes(double, const std::uint8_t *, size_t) {}

void BandSimObserver::driverWrite(double, int, std::uint8_t, std::uint8_t) {}

void BandSimObserver::fellBehind(double, double, double) {}

QStringList BandSimulator::models()
{
    return {Lra4, Pneumatic6};
}

BandSimulator::BandSimulator(const BandSimOptions &options)
    : m_options(options), m_core(std::make_unique<AvrCore>())
{
    const DeviceModel &model = *options.model;
    m_setpoints.assign(size_t(model.channelCount()), 0.0);
    m_values.assign(size_t(model.channelCount()), 0.0);
    m_filters.assign(size_t(model.channelCount()), ResponseFilter(model, model.rate()));
}

BandSimulator::~BandSimulator() = default;

bool BandSimulator::open(QString *error)
{
    const QString model = m_options.model->name();
    if (!models().contains(model)) {
        *error = QStringLiteral("%1: no reference board (boards: %2)")
                     .arg(model, models().join(QStringLiteral(", ")));
        return false;
    }
    FirmwareImage image;
    if (!(m_options.firmware.isEmpty() ? FirmwareImage::builtin(model, &image, error)
                                       : FirmwareImage::load(m_options.firmware, &image, error)))
        return false;
    m_imageName = image.name();
    if (!m_core->load(image, error) || !m_pty.open(m_options.link, error))
        return false;
    if (!m_options.logPath.isEmpty() && !m_log.open(m_options.logPath, error))
        return false;

    avr_t *avr = m_core->avr();
    m_uart = std::make_unique<UartBridge>(avr, m_pty.fd(),
                                          [this](const std::uint8_t *bytes, size_t size) {
                                              if (m_observer)
                                                  m_observer->hostBytes(seconds(), bytes, size);
                                          });
    const auto changed = [this](int channel, double output) { outputChanged(channel, output); };
    if (model == Lra4) {
        m_twi = std::make_unique<TwiCorrections>(avr);
        m_drivers = std::make_unique<Drv2605lBus>(
            avr, m_options.model->channelCount(),
            [this](int channel, std::uint8_t reg, std::uint8_t value) {
                if (m_observer)
                    m_observer->driverWrite(seconds(), channel, reg, value);
            },
            changed);
    } else {
        m_valves = std::make_unique<PwmOutputs>(avr, changed);
        m_pressure = std::make_unique<PressureSensor>(avr);
    }
    // The device model's response runs at the model's rate, in simulated time.
    m_core->every(std::uint64_t(std::llround(AvrCore::Frequency / m_options.model->rate())),
                  [this] { tick(); });
    return true;
}

QString BandSimulator::uri() const
{
    // The boards' 250000 baud is the serial default (on a pty it is moot anyway).
    return QStringLiteral("serial:") + (m_options.link.isEmpty() ? m_pty.path() : m_options.link);
}

double BandSimulator::seconds() const
{
    return m_core->seconds();
}

void BandSimulator::outputChanged(int channel, double output)
{
    const ChannelSpec &spec = m_options.model->channels()[size_t(channel)];
    m_setpoints[size_t(channel)] = spec.min + (spec.max - spec.min) * output;
    log();
}

void BandSimulator::tick()
{
    if (m_drivers)
        m_drivers->followEnable(); // a reset lets EN fall without a word on the bus
    for (size_t c = 0; c < m_filters.size(); ++c)
        m_values[c] = m_filters[c].step(m_setpoints[c]);
    if (m_pressure)
        m_pressure->update(m_values);
    log();
}

void BandSimulator::log()
{
    if (m_error.isEmpty() && !m_log.write(seconds(), m_setpoints, m_values))
        m_error = m_log.error();
}

bool BandSimulator::run(const std::function<bool()> &quit)
{
    log();
    // Simulated time t is wall time `start + t`, until the chip falls too far behind.
    double start = monotonicSeconds() - seconds();
    const auto wall = [&start] { return monotonicSeconds() - start; };
    while (!quit() && m_error.isEmpty()) {
        const double behind = wall() - seconds();
        if (behind > MaxLag) {
            start += behind - MaxLag;
            if (m_observer)
                m_observer->fellBehind(seconds(), behind, behind - MaxLag);
        }
        // Up to now (a sleeping chip skips there), so that the host's bytes enter the UART
        // when they arrived; then a busy chip runs ahead by a slice at most, until it sleeps.
        const double now = wall();
        bool running = m_core->runUntil(AvrCore::cycleAt(now));
        if (running) {
            m_uart->takeFromHost();
            running = m_core->runAwakeUntil(AvrCore::cycleAt(now + Slice));
        }
        if (!running) {
            m_error = QStringLiteral("%1: %2").arg(m_imageName, m_core->failure());
            break;
        }
        m_uart->flushToHost();
        m_reached.store(seconds(), std::memory_order_relaxed);
        // A sleeping chip needs the wall clock again only at its next event (a timer, a byte
        // on the line): until then only the host can wake it.
        const double next =
            m_core->asleep() ? double(m_core->nextEvent()) / AvrCore::Frequency : seconds();
        m_uart->waitForHost(next - wall());
    }
    m_uart->flushToHost();
    return m_error.isEmpty();
}

} // namespace semhap
