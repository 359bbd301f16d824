// SPDX-License-Identifier: MIT
#pragma once

#include <QObject>
#include <QTimer>

class QLabel;

namespace semhap {

class Engine;
class StatusBar;

/**
 * The run's readouts, kept up to date in the status bar's permanent corner: the recording
 * and what it dropped, who drives (or the live rig's address), the devices by link state,
 * the time, the pace (or a live rig's frame rate, jitter and held frames), and the Foxglove
 * viewers. A live rig's newest rejection shows as a message once, its reason in the rate's
 * tooltip after.
 */
class RunReadouts : public QObject
{
    Q_OBJECT

public:
    RunReadouts(StatusBar *bar, const Engine &engine, QObject *parent = nullptr);

    /** Reads the engine again now (the readouts also do so four times a second). */
    void update();
    /** Another source runs: its rejections are told from its first. */
    void sourceChanged() { m_shownRejections = 0; }

private:
    void updateLive();
    void updateDevices();

    StatusBar *m_bar;
    const Engine &m_engine;
    QLabel *m_recordLabel = nullptr;
    QLabel *m_operatorLabel = nullptr;
    QLabel *m_devicesLabel = nullptr;
    QLabel *m_timeLabel = nullptr;
    QLabel *m_rateLabel = nullptr;
    QLabel *m_foxgloveLabel = nullptr;
    QTimer m_timer;
    quint64 m_shownRejections = 0; ///< the live rig's rejections already told
};

} // namespace semhap
