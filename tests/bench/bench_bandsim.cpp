// SPDX-License-Identifier: MIT
// Host to firmware-in-simavr latency: lra4's real image in a BandSimulator on its own
// thread, a LinkTransport (the serial transport, as `semhap play` drives a band) sending
// set-values at the model's 500 Hz, each frame a new amplitude. From send() to the
// firmware's RTP_INPUT write at the first and at the last DRV2605L, in simulated time (from
// the frame's first byte entering the chip's UART) and in wall time; then the simulated
// chip's real-time factor and CPU share, busy and idle.
#include "bandsimulator.h"
#include "devicemodel.h"
#include "drv2605lbus.h"
#include "framedecoder.h"
#include "linktransport.h"
#include "monotonic.h"
#include "seriallink.h"

#include <QCoreApplication>

#include <algorithm>
#include <array>
#include <atomic>
#include <cstdio>
#include <ctime>
#include <mutex>
#include <pthread.h>
#include <thread>
#include <vector>

using namespace semhap;

namespace {

/** RTP bytes 1…254 in turn: each frame a new amplitude, so the firmware writes each. */
std::uint8_t rtpOf(int frame)
{
    return std::uint8_t(1 + frame % 254);
}

/**
 * Frame k's wire value: its RTP byte on top (what the drivers get), k's low byte below
 * (what tells the frames apart in the bytes the chip receives, with the RTP byte for 65 s).
 */
std::uint16_t wireOf(int frame)
{
    return std::uint16_t(rtpOf(frame) << 8 | (frame & 0xFF));
}

/** The frame below `frames` whose wire value is `wire`, or -1. */
int frameOf(std::uint16_t wire, int frames)
{
    for (int k = wire & 0xFF; k < frames; k += 256) {
        if (wireOf(k) == wire)
            return k;
    }
    return -1;
}

/** What the chip saw of each frame: when its first byte entered the UART, when each
 * driver got its amplitude (simulated and wall seconds). */
struct Arrival
{
    double uart = -1.0;
    std::array<double, 4> driverSim{{-1.0, -1.0, -1.0, -1.0}};
    std::array<double, 4> driverWall{{-1.0, -1.0, -1.0, -1.0}};
};

/** Matches the chip's events to the frames sent; called on the simulator's thread. */
class Recorder : public BandSimObserver
{
public:
    explicit Recorder(int frames) : m_arrivals(size_t(frames)), m_latestOf(256, -1) {}

    void hostBytes(double t, const std::uint8_t *bytes, size_t size) override
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        for (size_t i = 0; i < size; ++i) {
            if (m_frameStart < 0.0 && bytes[i] != 0)
                m_frameStart = t;
            m_decoder.feed(bytes + i, 1, [this](const protocol::Message &m) {
                if (m.type != protocol::MessageType::SetValues)
                    return;
                const int frame = frameOf(m.values[0], int(m_arrivals.size()));
                if (frame >= 0 && m_arrivals[size_t(frame)].uart < 0.0) {
                    m_arrivals[size_t(frame)].uart = m_frameStart;
                    m_latestOf[rtpOf(frame)] = frame;
                }
            });
            if (bytes[i] == 0)
                m_frameStart = -1.0;
        }
    }

    void driverWrite(double t, int channel, std::uint8_t reg, std::uint8_t value) override
    {
        if (reg != Drv2605lBus::RtpInput || channel > 3)
            return;
        const double wall = monotonicSeconds();
        std::lock_guard<std::mutex> lock(m_mutex);
        const int frame = m_latestOf[value];
        if (frame >= 0 && m_arrivals[size_t(frame)].driverSim[size_t(channel)] < 0.0) {
            m_arrivals[size_t(frame)].driverSim[size_t(channel)] = t;
            m_arrivals[size_t(frame)].driverWall[size_t(channel)] = wall;
        }
    }

    std::vector<Arrival> arrivals() const
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        return m_arrivals;
    }

private:
    mutable std::mutex m_mutex;
    FrameDecoder m_decoder;
    double m_frameStart = -1.0;
    std::vector<Arrival> m_arrivals;
    std::vector<int> m_latestOf; ///< RTP byte → the latest frame that carried it
};

double threadCpuSeconds(std::thread &thread)
{
    clockid_t clock{};
    timespec ts{};
    if (pthread_getcpuclockid(thread.native_handle(), &clock) != 0 ||
        clock_gettime(clock, &ts) != 0)
        return 0.0;
    return double(ts.tv_sec) + double(ts.tv_nsec) * 1e-9;
}

void printPercentiles(const char *what, std::vector<double> us)
{
    if (us.empty()) {
        std::printf("    %s: none\n", what);
        return;
    }
    std::sort(us.begin(), us.end());
    std::printf("    %s: median %.0f us, p99 %.0f us, max %.0f us\n", what, us[us.size() / 2],
                us[std::min(us.size() - 1, us.size() * 99 / 100)], us.back());
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    const double seconds = argc > 1 ? std::max(1.0, std::atof(argv[1])) : 10.0;
    const DeviceModelPtr model = DeviceModelLibrary::builtin(QStringLiteral("lra4"));
    const int frames = int(seconds * model->rate());

    BandSimOptions options;
    options.model = model;
    BandSimulator band(options);
    QString error;
    if (!band.open(&error)) {
        std::fprintf(stderr, "%s\n", qPrintable(error));
        return 1;
    }
    Recorder recorder(frames);
    band.setObserver(&recorder);
    std::atomic<bool> quit{false};
    bool ran = true;
    std::thread simulator([&] { ran = band.run([&] { return quit.load(); }); });

    // Idle first: the chip sleeps between its millisecond timer interrupts.
    const double idleWall = 3.0;
    const double idleStart = monotonicSeconds();
    const double idleCpu0 = threadCpuSeconds(simulator);
    const double idleSim0 = band.reached();
    std::this_thread::sleep_for(std::chrono::duration<double>(idleWall));
    const double idleElapsed = monotonicSeconds() - idleStart;
    const double idleCpu = threadCpuSeconds(simulator) - idleCpu0;
    const double idleSim = band.reached() - idleSim0;

    LinkTransport transport(std::make_unique<SerialLink>(band.address(), 250000), model);
    if (!transport.open(&error)) {
        std::fprintf(stderr, "%s\n", qPrintable(error));
        return 1;
    }
    transport.setArmed(true);
    std::this_thread::sleep_for(std::chrono::milliseconds(300)); // identify, heartbeats
    std::vector<double> sentAt(size_t(frames), 0.0);
    DeviceFrame frame;
    frame.channelCount = model->channelCount();
    const double busyCpu0 = threadCpuSeconds(simulator);
    const double busySim0 = band.reached();
    const double start = monotonicSeconds();
    for (int k = 0; k < frames; ++k) {
        const double due = start + k / model->rate();
        while (monotonicSeconds() < due)
            std::this_thread::sleep_for(std::chrono::microseconds(100));
        for (int c = 0; c < frame.channelCount; ++c)
            frame.values[size_t(c)] = wireOf(k) / 65535.0;
        sentAt[size_t(k)] = monotonicSeconds();
        transport.send(frame);
    }
    const double busyWall = monotonicSeconds() - start;
    const double busyCpu = threadCpuSeconds(simulator) - busyCpu0;
    const double busySim = band.reached() - busySim0;
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    transport.close();
    quit = true;
    simulator.join();
    if (!ran) {
        std::fprintf(stderr, "%s\n", qPrintable(band.error()));
        return 1;
    }

    std::vector<double> simFirst, simAll, wallFirst, wallAll;
    const std::vector<Arrival> arrivals = recorder.arrivals();
    int arrived = 0;
    for (int k = 0; k < frames; ++k) {
        const Arrival &a = arrivals[size_t(k)];
        if (a.uart < 0.0)
            continue;
        ++arrived;
        if (a.driverSim[0] >= 0.0) {
            simFirst.push_back((a.driverSim[0] - a.uart) * 1e6);
            wallFirst.push_back((a.driverWall[0] - sentAt[size_t(k)]) * 1e6);
        }
        if (a.driverSim[3] >= 0.0) {
            simAll.push_back((a.driverSim[3] - a.uart) * 1e6);
            wallAll.push_back((a.driverWall[3] - sentAt[size_t(k)]) * 1e6);
        }
    }
    std::printf("bench_bandsim: lra4's image in simavr, %d set-values frames at %.0f Hz over "
                "its pty (serial transport)\n",
                frames, model->rate());
    std::printf("  reached the chip %d, skipped by the transport as stale %d; RTP writes "
                "matched: first driver %zu, all four %zu\n",
                arrived, frames - arrived, simFirst.size(), simAll.size());
    std::printf("  simulated time, frame's first byte into the UART -> RTP_INPUT written:\n");
    printPercentiles("first driver (m1)", simFirst);
    printPercentiles("last driver (m4)", simAll);
    std::printf("  wall time, send() -> RTP_INPUT written:\n");
    printPercentiles("first driver (m1)", wallFirst);
    printPercentiles("last driver (m4)", wallAll);
    std::printf("  busy: %.2f s simulated in %.2f s (real-time factor %.3f); simulator thread "
                "%.1f %% of a core, so it could run %.1fx real time\n",
                busySim, busyWall, busySim / busyWall, 100.0 * busyCpu / busyWall,
                busyCpu > 0 ? busySim / busyCpu : 0.0);
    std::printf("  idle (no host): %.2f s simulated in %.2f s; simulator thread %.1f %% of a "
                "core\n",
                idleSim, idleElapsed, 100.0 * idleCpu / idleElapsed);
    return 0;
}
