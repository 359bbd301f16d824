// SPDX-License-Identifier: MIT
// The sound card transport (`audio:`) without a card: PortAudio's ALSA host API into a
// FIFO read at the card's rate (tests/common/fifocard.h). Prints the latency from send()
// to the first sample that carries a frame, and the CPU that rendering 8 channels takes.
#include "audiorenderer.h"
#include "audiotransport.h"
#include "fifocard.h"
#include "monotonic.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonObject>
#include <QTemporaryDir>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <sys/resource.h>
#include <thread>
#include <vector>

using namespace semhap;

namespace {

/** An 8-channel vibrotactile band at 1 kHz: the most a multichannel card is asked for. */
DeviceModelPtr eightChannels()
{
    QJsonArray channels;
    for (int c = 1; c <= 8; ++c)
        channels.append(QJsonObject{{QStringLiteral("name"), QStringLiteral("m%1").arg(c)},
                                    {QStringLiteral("unit"), QStringLiteral("amplitude")},
                                    {QStringLiteral("min"), 0},
                                    {QStringLiteral("max"), 1}});
    const QJsonObject json{{QStringLiteral("format"), QString::fromLatin1(DeviceModel::Format)},
                           {QStringLiteral("name"), QStringLiteral("lra8")},
                           {QStringLiteral("rate"), 1000},
                           {QStringLiteral("channels"), channels}};
    LoadError error;
    return DeviceModel::fromJson(json, QStringLiteral("lra8"), &error);
}

double threadCpu()
{
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + double(ts.tv_nsec) * 1e-9;
}

double processCpu()
{
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
           double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec) * 1e-6;
}

/** `audio:semhaptest`, the FIFO card. */
DeviceUri fifoCard()
{
    DeviceUri uri;
    uri.scheme = QStringLiteral("audio");
    uri.name = QStringLiteral("semhaptest");
    return uri;
}

/** A frame of `count` channels whose envelopes move with `k`. */
DeviceFrame frameAt(int k, int count, double t)
{
    DeviceFrame frame;
    frame.t = t;
    frame.channelCount = count;
    for (int c = 0; c < count; ++c)
        frame.values[size_t(c)] = 0.5 + 0.4 * std::sin(0.01 * k + c);
    return frame;
}

void printLatencies(const char *what, std::vector<double> latency)
{
    std::sort(latency.begin(), latency.end());
    if (latency.empty()) {
        std::printf("%s: no frames\n", what);
        return;
    }
    const auto at = [&](double q) { return latency[size_t(q * double(latency.size() - 1))]; };
    std::printf("%s: %zu frames, latency median %.2f ms, p99 %.2f ms, max %.2f ms\n", what,
                latency.size(), at(0.5) * 1e3, at(0.99) * 1e3, latency.back() * 1e3);
}

/** Sends at `rate` Hz for `seconds` and returns each played frame's latency. */
std::vector<double> latencies(const QString &fifo, double rate, double seconds,
                              std::uint32_t *skipped)
{
    FifoCard card(fifo, 4);
    AudioTransport transport(fifoCard(), DeviceModelLibrary::builtin(QStringLiteral("lra4")));
    QString error;
    if (!transport.open(&error)) {
        std::fprintf(stderr, "%s\n", qPrintable(error));
        return {};
    }
    transport.setArmed(true);
    const std::uint64_t first = transport.sent().count();
    const double start = monotonicSeconds();
    const int count = int(seconds * rate);
    for (int k = 0; k < count; ++k) {
        const double due = start + k / rate;
        std::this_thread::sleep_for(std::chrono::duration<double>(due - monotonicSeconds()));
        transport.send(frameAt(k, 4, k / rate));
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    std::vector<double> out;
    for (std::uint64_t i = first; i < transport.sent().count(); ++i) {
        const double latency = transport.latencyOf(i);
        if (latency >= 0.0)
            out.push_back(latency);
    }
    *skipped = transport.status().framesSkipped;
    transport.close();
    return out;
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    const double seconds = argc > 1 ? std::max(1.0, std::atof(argv[1])) : 5.0;
    QTemporaryDir dir;
    const QString fifo = FifoCard::install(dir.path());
    if (fifo.isEmpty()) {
        std::fprintf(stderr, "cannot set up the FIFO sound card\n");
        return 1;
    }

    // Latency: lra4 at its own rate (500 Hz), and at the pipeline's 1 kHz, twice as fast
    // as the renderer takes frames (one per update period), so the backlog is skipped.
    for (const double rate : {500.0, 1000.0}) {
        std::uint32_t skipped = 0;
        const std::vector<double> measured = latencies(fifo, rate, seconds, &skipped);
        char what[96];
        std::snprintf(what, sizeof what, "lra4, sent at %.0f Hz (%u skipped)", rate, skipped);
        printLatencies(what, measured);
    }

    // CPU: the renderer alone, 8 channels at 48 kHz in 256-sample buffers, a frame per ms.
    const DeviceModelPtr model = eightChannels();
    std::vector<AudioRenderer::Channel> channels;
    for (int c = 0; c < 8; ++c)
        channels.push_back({c, 170.0 + 10.0 * c});
    {
        AudioRenderer renderer(model, 48000.0, 8, channels);
        std::vector<float> buffer(256 * 8);
        const int buffers = int(seconds * 48000.0 / 256.0);
        const double cpu = threadCpu();
        int k = 0;
        for (int b = 0; b < buffers; ++b) {
            for (; k < (b + 1) * 256 / 48; ++k)
                renderer.push(frameAt(k, 8, k * 0.001), monotonicSeconds());
            renderer.render(buffer.data(), 256, 0.0, monotonicSeconds());
            RenderedFrame rendered;
            while (renderer.takeRendered(&rendered)) {
            }
        }
        const double audio = buffers * 256.0 / 48000.0;
        std::printf("renderer, 8 channels at 48 kHz: %.3f%% of a core (%.1f µs per 256-sample "
                    "buffer)\n",
                    100.0 * (threadCpu() - cpu) / audio, 1e6 * (threadCpu() - cpu) / buffers);
    }

    // CPU: the whole transport in real time, 8 channels on the FIFO card at 44.1 kHz, fed
    // at 1 kHz: the process's CPU less the feeding thread's and the card reader's (both
    // timed on their own threads), so what is left is PortAudio's callback thread (the
    // renderer and ALSA's file plugin) and the transport's worker.
    {
        FifoCard card(fifo, 8);
        AudioTransport transport(fifoCard(), model);
        QString error;
        if (!transport.open(&error)) {
            std::fprintf(stderr, "%s\n", qPrintable(error));
            return 1;
        }
        transport.setArmed(true);
        std::this_thread::sleep_for(std::chrono::milliseconds(200));
        const double wallStart = monotonicSeconds();
        const double processStart = processCpu();
        const double feederStart = threadCpu();
        const double readerStart = card.cpuSeconds();
        const int count = int(seconds * 1000.0);
        for (int k = 0; k < count; ++k) {
            std::this_thread::sleep_for(
                std::chrono::duration<double>(wallStart + k * 0.001 - monotonicSeconds()));
            transport.send(frameAt(k, 8, k * 0.001));
        }
        const double feeder = threadCpu() - feederStart;
        const double process = processCpu() - processStart;
        const double wall = monotonicSeconds() - wallStart;
        const double reader = card.cpuSeconds() - readerStart;
        std::printf("transport, 8 channels at 44.1 kHz in real time: %.2f%% of a core "
                    "(process %.2f%%, feeding thread %.2f%%, card reader %.2f%%)\n",
                    100.0 * (process - feeder - reader) / wall, 100.0 * process / wall,
                    100.0 * feeder / wall, 100.0 * reader / wall);
        transport.close();
    }
    return 0;
}
