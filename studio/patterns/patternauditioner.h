// SPDX-License-Identifier: MIT
#pragma once

#include "pattern.h"
#include "patternrender.h"

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

#include <functional>
#include <memory>

namespace semhap {

class Transport;
class Voice;

/**
 * Plays a pattern on a device in real time, for the designer's audition: a voice rendered
 * at the device model's rate on a GUI-thread timer, each frame handed to the transport
 * (which clamps to the device's limits). Begin and end follow the user's buttons; when the
 * voice falls idle after an end, or on stop(), every channel is sent to zero.
 */
class PatternAuditioner : public QObject
{
    Q_OBJECT

public:
    /** Finds the transport to play on each tick, so a rebinding never leaves it dangling. */
    using TransportSource = std::function<Transport *()>;

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

    bool isPlaying() const { return m_timer.isActive(); }
    /** True between begin and end. */
    bool isActive() const;
    /** Frames handed to the transport since the last begin. */
    int framesSent() const { return m_frames; }

signals:
    void playingChanged(bool playing);

private:
    void tick();
    double now() const;

    std::unique_ptr<Voice> m_voice;
    std::vector<PlayerInput::Route> m_routes;
    TransportSource m_source;
    QTimer m_timer;
    QElapsedTimer m_clock;
    int m_channels = 0;
    int m_frames = 0;
    double m_idleSince = -1.0;
    double m_endAt = -1.0;    ///< when the voice ends by itself; negative: held
    double m_startTime = 0.0; ///< the frames' time at the begin
};

} // namespace semhap
