// SPDX-License-Identifier: MIT
#pragma once

#include <QByteArray>
#include <QElapsedTimer>
#include <QFile>
#include <QString>

#include <atomic>
#include <csignal>
#include <cstring>
#include <ctime>
#include <fcntl.h>
#include <mutex>
#include <poll.h>
#include <sys/stat.h>
#include <thread>
#include <unistd.h>
#include <vector>

/**
 * A sound card for tests, without one: PortAudio's ALSA host API sees only the PCMs of
 * a configuration written here (ALSA_CONFIG_PATH). `semhaptest`'s `file` plugin writes the
 * raw float samples into a FIFO that a FifoCard reads at the card's rate (the `null` PCM
 * behind the plugin takes samples as fast as they come: the reader paces the stream);
 * `semhapother` is a second output whose name shares a part with it.
 */
class FifoCard
{
public:
    /** The rate the outputs run at: the null PCM's default. */
    static constexpr double Rate = 44100.0;

    /**
     * Writes the configuration and the FIFO into `dir` and points ALSA at them, before
     * anything starts PortAudio. Returns the FIFO's path; empty when that failed.
     */
    static QString install(const QString &dir)
    {
        const QString fifo = dir + QStringLiteral("/card.fifo");
        if (::mkfifo(QFile::encodeName(fifo).constData(), 0600) != 0)
            return {};
        QByteArray config = R"(
pcm.semhaptest {
    type file
    slave.pcm "null"
    file "@FIFO@"
    format "raw"
}
pcm.semhapother {
    type null
}
pcm.null {
    type null
}
# PortAudio 19.6 needs a default PCM to list the others.
pcm.default {
    type null
}
)";
        config.replace("@FIFO@", QFile::encodeName(fifo));
        QFile file(dir + QStringLiteral("/asound.conf"));
        if (!file.open(QIODevice::WriteOnly) || file.write(config) != config.size())
            return {};
        file.close();
        qputenv("ALSA_CONFIG_PATH", QFile::encodeName(file.fileName()));
        // The plugin writes into the FIFO: a reader that went away must not end the test.
        std::signal(SIGPIPE, SIG_IGN);
        return fifo;
    }

    /** Reads the FIFO at `path`: frames of `channels` interleaved floats. */
    FifoCard(const QString &path, int channels) : m_channels(channels)
    {
        // Opening for reading first lets the plugin's open for writing go through.
        m_fd = ::open(QFile::encodeName(path).constData(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
        // A small pipe: the stream runs close to what has been read.
        ::fcntl(m_fd, F_SETPIPE_SZ, 4096);
        m_thread = std::thread([this] { run(); });
    }
    ~FifoCard() { stop(); }

    /** Stops reading and closes the FIFO: to the writer, the card is gone. */
    void stop()
    {
        m_quit = true;
        if (m_thread.joinable())
            m_thread.join();
        if (m_fd >= 0)
            ::close(m_fd);
        m_fd = -1;
    }
    bool ended() const { return m_ended; }
    /** CPU time the reading thread has used (s). */
    double cpuSeconds() const { return m_cpu; }
    size_t frames() const
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        return m_samples.size() / size_t(m_channels);
    }
    /** Output `channel` (from 0) from frame `from` on. */
    std::vector<float> channel(int channel, size_t from = 0) const
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        std::vector<float> out;
        for (size_t i = from * size_t(m_channels) + size_t(channel); i < m_samples.size();
             i += size_t(m_channels))
            out.push_back(m_samples[i]);
        return out;
    }

private:
    void run()
    {
        QElapsedTimer clock;
        clock.start();
        std::vector<char> buffer(8192);
        size_t bytes = 0;
        while (!m_quit) {
            timespec cpu{};
            clock_gettime(CLOCK_THREAD_CPUTIME_ID, &cpu);
            m_cpu = double(cpu.tv_sec) + double(cpu.tv_nsec) * 1e-9;
            const double allowed = double(clock.nsecsElapsed()) * 1e-9 * Rate;
            if (double(bytes) / (4.0 * m_channels) >= allowed) {
                std::this_thread::sleep_for(std::chrono::milliseconds(1));
                continue;
            }
            pollfd fd{m_fd, POLLIN, 0};
            if (::poll(&fd, 1, 10) <= 0)
                continue;
            const ssize_t n = ::read(m_fd, buffer.data(), buffer.size());
            if (n == 0 && m_writerSeen) {
                m_ended = true;
                return;
            }
            if (n <= 0) {
                std::this_thread::sleep_for(std::chrono::milliseconds(1)); // no writer yet
                continue;
            }
            m_writerSeen = true;
            bytes += size_t(n);
            m_pending.insert(m_pending.end(), buffer.begin(), buffer.begin() + n);
            const size_t whole = m_pending.size() / 4 * 4;
            std::lock_guard<std::mutex> lock(m_mutex);
            const size_t first = m_samples.size();
            m_samples.resize(first + whole / 4);
            std::memcpy(m_samples.data() + first, m_pending.data(), whole);
            m_pending.erase(m_pending.begin(), m_pending.begin() + long(whole));
        }
    }

    int m_channels;
    int m_fd = -1;
    std::thread m_thread;
    std::atomic<bool> m_quit{false};
    std::atomic<bool> m_ended{false};
    std::atomic<double> m_cpu{0.0};
    bool m_writerSeen = false;
    std::vector<char> m_pending;
    mutable std::mutex m_mutex;
    std::vector<float> m_samples;
};
