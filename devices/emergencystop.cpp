// SPDX-License-Identifier: MIT
#include "emergencystop.h"

#include "protocol.h"
#include "quitsignal.h"

#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <sys/socket.h>
#include <unistd.h>

namespace semhap {

namespace {

constexpr int MaxFds = 32;
constexpr int StopRepeats = 3;

/** Registered descriptors plus one, so that the zero-initialised table is empty. */
std::array<std::atomic<int>, MaxFds> g_fds{};

/** The stop-all frame, encoded before any signal can arrive. */
struct StopFrame
{
    std::array<char, 16> bytes{};
    int size = 0;
};

const StopFrame &stopFrame()
{
    static const StopFrame frame = [] {
        QByteArray encoded;
        protocol::Message stop;
        stop.type = protocol::MessageType::StopAll;
        stop.sequence = 0xFFFF;
        encoded.append('\0'); // flush whatever half-frame the device holds
        protocol::encode(stop, &encoded);
        StopFrame f;
        f.size = int(encoded.size());
        std::copy(encoded.begin(), encoded.end(), f.bytes.begin());
        return f;
    }();
    return frame;
}

extern "C" void onTerminatingSignal(int signal)
{
    EmergencyStop::stopAllNow();
    std::signal(signal, SIG_DFL);
    std::raise(signal);
}

extern "C" void onGracefulSignal(int signal)
{
    EmergencyStop::stopAllNow();
    QuitSignal::request();
    std::signal(signal, onTerminatingSignal);
}

} // namespace

void EmergencyStop::installGraceful()
{
    stopFrame();
    QuitSignal::install(); // clears the flag
    std::signal(SIGINT, onGracefulSignal);
    std::signal(SIGTERM, onGracefulSignal);
}

void EmergencyStop::install()
{
    static std::atomic<bool> installed{false};
    stopFrame();
    if (installed.exchange(true))
        return;
    std::signal(SIGINT, onTerminatingSignal);
    std::signal(SIGTERM, onTerminatingSignal);
}

bool EmergencyStop::add(int fd)
{
    stopFrame();
    if (fd < 0)
        return false;
    for (auto &slot : g_fds) {
        int expected = 0;
        if (slot.compare_exchange_strong(expected, fd + 1))
            return true;
    }
    return false;
}

void EmergencyStop::remove(int fd)
{
    for (auto &slot : g_fds) {
        int expected = fd + 1;
        slot.compare_exchange_strong(expected, 0);
    }
}

void EmergencyStop::stopAllNow()
{
    const StopFrame &frame = stopFrame();
    const int interruptedErrno = errno; // a signal handler leaves errno as it found it
    for (auto &slot : g_fds) {
        const int fd = slot.load() - 1;
        if (fd < 0)
            continue;
        for (int i = 0; i < StopRepeats; ++i) {
            // send() first: a socket whose peer has gone would raise SIGPIPE on write() and
            // end the process before the other bands got their stop. Both are
            // async-signal-safe; a tty or pty is no socket and takes write().
            ssize_t n = ::send(fd, frame.bytes.data(), size_t(frame.size), MSG_NOSIGNAL);
            if (n < 0 && errno == ENOTSOCK)
                n = ::write(fd, frame.bytes.data(), size_t(frame.size));
            if (n < 0)
                break;
        }
    }
    errno = interruptedErrno;
}

} // namespace semhap
