// SPDX-License-Identifier: MIT
#pragma once

#include "pattern.h"
#include "patternrender.h"

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

#include <atomic>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>

namespace semhap {

class Transport;
class Voice;

/**
 * Plays a pattern on a device in real time, for the designer's audition: a voice rendered
 * at the device model's rate on a thread of its own (so a busy window does not thin out a
 * Geiger pattern's clicks), each frame handed to the transport, which clamps to the
 * device's limits. Begin and end follow the user's buttons; when the voice falls idle after
 * an end, on stop(), or when the device is rebound, every channel is sent to zero.
 */
class PatternAuditioner : public QObject
{
    Q_OBJECT

public:
    /**
     * Finds the transport to play on. Asked at the begin and again on the GUI thread while
     * playing: when it answers another transport (a rebinding), the audition stops. Shared,
     * so the transport outlives a rebinding until the render thread has let go of it.
     */
    using TransportSource = std::function<std::shared_ptr<Transport>()>;

    explicit PatternAuditioner(QObject *parent = nullptr);
    ~PatternAuditioner() override;

    /**
     * Begins `pattern` now on the transport `source` gives (the pattern must be for its
     * model); restarts it if already playing. It ends by itself `endAt` seconds after the
     * begin, as the preview draws it; a negative `endAt` holds until end() or stop(). Its
     * frames are stamped `startTime` plus the seconds since the begin: where the readouts
     * draw them. False with `reason` when it cannot play.
     */
    bool begin(const PatternPtr &pattern, const TransportSource &source, double intensity,
               double endAt, double startTime, QString *reason);
    /** Starts the release; the audition stops by itself once the voice is idle. */
    void end();
    /** Sends every channel to zero at once and stops. */
    void stop();
    void setIntensity(double intensity);

    bool isPlaying() const { return m_thread.joinable(); }
    /** True between begin and end. */
    bool isActive() const;
    /** Frames handed to the transport since the last begin. */
    int framesSent() const { return m_frames.load(); }

signals:
    void playingChanged(bool playing);

private:
    /** The render thread: a frame every period of the device's rate, until quit. */
    void render(double period);
    /** GUI thread, a few times a second: stops once idle long enough or rebound. */
    void watch();
    /** Ends the render thread; the transport is let go. */
    void join();
    double now() const;

    std::shared_ptr<Transport> m_transport;
    TransportSource m_source;
    std::vector<PlayerInput::Route> m_routes;
    QElapsedTimer m_clock;
    QTimer m_watch;
    std::thread m_thread;
    std::atomic<bool> m_quit{false};
    std::atomic<int> m_frames{0};
    /** The voice and what the render thread reads with it; held briefly by both threads. */
    mutable std::mutex m_voiceMutex;
    std::unique_ptr<Voice> m_voice;
    int m_channels = 0;
    double m_idleSince = -1.0; ///< when the voice fell idle (s since the begin); < 0: not
    double m_endAt = -1.0;     ///< when the voice ends by itself; negative: held
    double m_startTime = 0.0;  ///< the frames' time at the begin
};

} // namespace semhap
