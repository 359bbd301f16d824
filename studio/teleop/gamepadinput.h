// SPDX-License-Identifier: MIT
#pragma once

#include "gamepadmapping.h"

#include <QObject>
#include <QStringList>
#include <QTimer>

#include <memory>

namespace semhap {

class HandDrive;

/**
 * Gamepads through SDL2's game-controller API: every controller SDL knows (Xbox,
 * PlayStation, Switch Pro, most others, and SDL's virtual joysticks) drives the HandDrive
 * at rates, with an analogue grip on a trigger, through a GamepadMapping. Polled at 125 Hz
 * on the GUI thread; controllers come and go while it runs (hot-plug). The one that moved
 * last drives; when it is unplugged its rates go to zero at once, so the wrist stops.
 */
class GamepadInput : public QObject
{
    Q_OBJECT

public:
    static constexpr int PollIntervalMs = 8;

    explicit GamepadInput(QObject *parent = nullptr);
    ~GamepadInput() override;

    /** Where rates and actions go (null: nowhere). Not owned. */
    void setDrive(HandDrive *drive);
    void setMapping(const GamepadMapping &mapping);
    const GamepadMapping &mapping() const { return m_mapping; }

    /** Starts SDL's game-controller subsystem and the polling; false with errorString(). */
    bool start();
    /** Closes every controller, zeroes the drive's gamepad rates and stops SDL. */
    void stop();
    bool isStarted() const { return m_started; }
    QString errorString() const { return m_error; }

    /** The connected controllers' names, in the order they came. */
    QStringList controllers() const;
    /** The controller that drives now (empty: none). */
    QString activeController() const;

    /** Reads SDL's events and the controllers now (the timer does this every tick). */
    void poll();

signals:
    /** A controller came or went. */
    void controllersChanged();
    /**
     * A button of an action the drive cannot do itself was pressed (HandBack, NextCamera):
     * the window does it. The drive's own actions (grip, hand) are applied directly.
     */
    void triggered(semhap::GamepadMapping::Action action);

private:
    struct Private;
    std::unique_ptr<Private> d;
    HandDrive *m_drive = nullptr;
    GamepadMapping m_mapping = GamepadMapping::defaults();
    QTimer m_timer;
    bool m_started = false;
    QString m_error;
};

} // namespace semhap
