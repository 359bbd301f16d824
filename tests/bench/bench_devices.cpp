// SPDX-License-Identifier: MIT
// Event-to-bytes latency of the serial transport: frames handed to send() at 1 kHz, read
// back raw from the other side of a pty, matched by value. Prints median and p99 in µs.
#include "framedecoder.h"
#include "linktransport.h"
#include "monotonic.h"
#include "seriallink.h"

#include <QCoreApplication>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <fcntl.h>
#include <poll.h>
#include <thread>
#include <unistd.h>
#include <vector>

using namespace semhap;

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    const double seconds = argc > 1 ? std::max(1.0, std::atof(argv[1])) : 5.0;
    const int frames = int(seconds * 1000.0);

    const int master = ::posix_openpt(O_RDWR | O_NOCTTY);
    if (master < 0 || ::grantpt(master) != 0 || ::unlockpt(master) != 0) {
        std::perror("posix_openpt");
        return 1;
    }
    const QString slave = QString::fromLocal8Bit(::ptsname(master));

    // Frame k carries k + 1 on channel 0, so the reader knows which send it answers.
    std::vector<double> sentAt(size_t(frames) + 1, 0.0);
    std::vector<double> latency(size_t(frames) + 1, -1.0);
    std::atomic<bool> done{false};
    std::thread reader([&] {
        FrameDecoder decoder;
        std::vector<std::uint8_t> buffer(4096);
        while (!done) {
            pollfd fd{master, POLLIN, 0};
            if (::poll(&fd, 1, 20) <= 0)
                continue;
            const ssize_t n = ::read(master, buffer.data(), buffer.size());
            const double now = monotonicSeconds();
            if (n <= 0)
                continue;
            decoder.feed(buffer.data(), size_t(n), [&](const protocol::Message &m) {
                const int k = m.values[0];
                if (m.type == protocol::MessageType::SetValues && k > 0 && k <= frames &&
                    latency[size_t(k)] < 0.0)
                    latency[size_t(k)] = now - sentAt[size_t(k)];
            });
        }
    });

    DeviceModelPtr model = DeviceModelLibrary::builtin(QStringLiteral("lra4"));
    LinkTransport transport(std::make_unique<SerialLink>(slave, 115200), model);
    QString error;
    if (!transport.open(&error)) {
        std::fprintf(stderr, "%s\n", qPrintable(error));
        return 1;
    }
    transport.setArmed(true);
    DeviceFrame frame;
    frame.channelCount = model->channelCount();
    const double start = monotonicSeconds();
    for (int k = 1; k <= frames; ++k) {
        const double due = start + k * 0.001;
        while (monotonicSeconds() < due)
            std::this_thread::sleep_for(std::chrono::microseconds(50));
        frame.values[0] = k / 65535.0;
        sentAt[size_t(k)] = monotonicSeconds();
        transport.send(frame);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    transport.close();
    done = true;
    reader.join();
    ::close(master);

    std::vector<double> us;
    for (int k = 1; k <= frames; ++k) {
        if (latency[size_t(k)] >= 0.0)
            us.push_back(latency[size_t(k)] * 1e6);
    }
    if (us.empty()) {
        std::fprintf(stderr, "no frame arrived\n");
        return 1;
    }
    std::sort(us.begin(), us.end());
    std::printf("bench_devices: %d frames at 1 kHz over a pty (serial transport, termios)\n",
                frames);
    std::printf("  arrived %zu, skipped as stale %zu\n", us.size(), size_t(frames) - us.size());
    std::printf("  event-to-bytes latency: median %.1f us, p99 %.1f us, max %.1f us "
                "(target p99 <= 1000 us)\n",
                us[us.size() / 2], us[std::min(us.size() - 1, us.size() * 99 / 100)], us.back());
    return 0;
}
