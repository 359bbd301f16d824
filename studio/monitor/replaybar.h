// SPDX-License-Identifier: MIT
#pragma once

#include <QElapsedTimer>
#include <QTimer>
#include <QWidget>

class QComboBox;
class QLabel;
class QSlider;
class QToolButton;

namespace semhap {

class ElidingLabel;
class SessionReplay;

/**
 * The timeline of an opened session: a scrubber, the time, play/pause at a chosen speed,
 * and the re-route buttons. Moving the scrubber moves the replay, which fills the history
 * every view reads.
 */
class ReplayBar : public QWidget
{
    Q_OBJECT

public:
    explicit ReplayBar(SessionReplay &replay, QWidget *parent = nullptr);

    QSlider *slider() const { return m_slider; }
    QToolButton *playButton() const { return m_play; }
    QToolButton *rerouteButton() const { return m_reroute; }
    QToolButton *recordedButton() const { return m_recorded; }
    QToolButton *closeButton() const { return m_close; }

    void setPlaying(bool playing);
    bool isPlaying() const { return m_timer.isActive(); }

signals:
    /** The user asked to run the session through the router editor's router. */
    void rerouteRequested();
    /** The user closed the replay: back to the simulation. */
    void closeRequested();

private:
    void sessionOpened();
    void showTime(double t);
    void advance();

    SessionReplay &m_replay;
    QToolButton *m_play = nullptr;
    QSlider *m_slider = nullptr;
    QLabel *m_time = nullptr;
    QComboBox *m_speed = nullptr;
    QToolButton *m_reroute = nullptr;
    QToolButton *m_recorded = nullptr;
    QLabel *m_about = nullptr; ///< the scene and the date; its tooltip, the rest
    ElidingLabel *m_source = nullptr;
    QToolButton *m_close = nullptr;
    QTimer m_timer;
    QElapsedTimer m_clock;
};

} // namespace semhap
