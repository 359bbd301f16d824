// SPDX-License-Identifier: MIT
#pragma once

#include "deviceuri.h"
#include "transport.h"
#include "transportscheme.h"

#include <array>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <thread>

namespace semhap {

class AudioRenderer;
class AudioSystem;

/**
 * A vibrotactile band on a sound card (`audio:`): each channel a carrier times its envelope
 * on one output of the card, through PortAudio (AudioRenderer makes the sound in the
 * stream's callback). send() applies safety under a tiny mutex and queues the values
 * lock-free; a worker thread logs what the callback rendered into sent(), re-sends held
 * values every 100 ms (so disarming or a gain acts on them), notices a stream that ended
 * by itself (a card unplugged) and reopens it every second.
 */
class AudioTransport : public Transport
{
public:
    static constexpr double HeartbeatPeriod = 0.1;
    static constexpr double ReconnectPeriod = 1.0;

    AudioTransport(const DeviceUri &uri, DeviceModelPtr model);
    ~AudioTransport() override;

    QString uri() const override;
    /**
     * Opens the output and starts the stream, returning whether that worked; the worker
     * keeps trying either way (a card plugged in later is found).
     */
    bool open(QString *error) override;
    /** Fades to silence, waits for it to be played, and closes the stream. */
    void close() override;
    void send(const DeviceFrame &frame) override;
    void stopAll() override;
    TransportStatus status() const override;

    /**
     * Whether `uri` fits `model`: no more output channels or carriers than the model has
     * channels. False with a reason.
     */
    static bool fits(const DeviceUri &uri, const DeviceModel &model, QString *error);
    /**
     * `DEVICE[?channels=1,2,…&carrier=HZ,…]`, what follows `audio:`, into the output's name,
     * its channels and carriers; false with a reason.
     */
    static bool parseAddress(const QString &address, DeviceUri *uri, QString *error);
    /** The same, spelled: the options only when they are not the defaults. */
    static QString formatAddress(const DeviceUri &uri);
    /** Appends the sound card outputs (scanned at most every 5 s: probing cards is slow). */
    static void present(std::vector<PortInfo> *out);
    /**
     * Seconds from send() to the first sample that carried sent() frame number `index`
     * (its running count) at the card's DAC, by PortAudio's output time; < 0 when that
     * frame is no longer kept.
     */
    double latencyOf(std::uint64_t index) const;

private:
    bool connect(QString *error);
    void disconnect(const QString &reason);
    /** Stops and closes the stream, keeping what it rendered in sent(). */
    void closeStream(bool drainFirst);
    void run();
    void drain();
    /** Hands the commanded values, made safe, to the renderer (m_sendMutex held). */
    void pushSafe(double now, bool fresh);

    DeviceUri m_uri;
    std::thread m_thread;
    std::mutex m_wakeMutex; ///< guards m_quit, for the worker's wait
    std::condition_variable m_wake;
    bool m_quit = false;

    // The stream: the thread that opens and closes (open(), the worker, close()) only.
    std::unique_ptr<AudioSystem> m_system;
    void *m_stream = nullptr; ///< PaStream
    std::uint64_t m_lastSamples = 0;
    double m_lastProgress = -1.0;

    mutable std::mutex m_sendMutex; ///< never held by the callback
    SafetyFilter m_safety;
    std::unique_ptr<AudioRenderer> m_renderer;
    DeviceFrame m_commanded; ///< the latest values given to send(), before safety
    bool m_holding = false;  ///< m_commanded is to be played (no stop-all since)
    DeviceFrame m_lastSafe;
    double m_lastPush = -1.0;

    mutable std::mutex m_statusMutex;
    TransportStatus m_status;
    bool m_responding = false;
    std::uint64_t m_skippedBefore = 0; ///< by the renderers of earlier streams
    std::uint64_t m_underflowsBefore = 0;
    std::uint32_t m_disconnects = 0;
    std::array<double, SentLog::Capacity> m_latency{}; ///< by sent() running count
};

} // namespace semhap
