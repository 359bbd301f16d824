// SPDX-License-Identifier: MIT
#include "replaybar.h"

#include "elidinglabel.h"
#include "sessionreplay.h"

#include <QComboBox>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QProxyStyle>
#include <QSignalBlocker>
#include <QSlider>
#include <QStyle>
#include <QToolButton>

#include <cmath>

namespace semhap {

namespace {

/** The scrubber's resolution: one step per millisecond of session time. */
constexpr double StepsPerSecond = 1000.0;
constexpr double Speeds[] = {0.25, 0.5, 1.0, 2.0, 4.0};

/** A click on the scrubber's groove jumps there, as in a media player, instead of paging. */
class JumpingSliderStyle : public QProxyStyle
{
public:
    using QProxyStyle::QProxyStyle;
    int styleHint(StyleHint hint, const QStyleOption *option, const QWidget *widget,
                  QStyleHintReturn *returned) const override
    {
        if (hint == SH_Slider_AbsoluteSetButtons)
            return int(Qt::LeftButton | Qt::MiddleButton);
        return QProxyStyle::styleHint(hint, option, widget, returned);
    }
};

} // namespace

ReplayBar::ReplayBar(SessionReplay &replay, QWidget *parent) : QWidget(parent), m_replay(replay)
{
    setObjectName(QStringLiteral("replayBar"));
    auto *layout = new QHBoxLayout(this);
    layout->setContentsMargins(6, 2, 6, 2);

    m_play = new QToolButton(this);
    m_play->setObjectName(QStringLiteral("replayPlay"));
    m_play->setToolTip(tr("Play or pause the replay"));
    connect(m_play, &QToolButton::clicked, this, [this] { setPlaying(!isPlaying()); });
    layout->addWidget(m_play);

    m_slider = new QSlider(Qt::Horizontal, this);
    m_slider->setObjectName(QStringLiteral("replaySlider"));
    m_slider->setToolTip(tr("Session time: click or drag to scrub"));
    // Owned by the slider; with no base given it follows the application's style.
    auto *jumping = new JumpingSliderStyle;
    jumping->setParent(m_slider);
    m_slider->setStyle(jumping);
    connect(m_slider, &QSlider::valueChanged, this, [this](int value) {
        m_replay.seek(m_replay.startTime() + double(value) / StepsPerSecond);
    });
    m_slider->setMinimumWidth(160);
    layout->addWidget(m_slider, 1);

    m_time = new QLabel(this);
    m_time->setObjectName(QStringLiteral("replayTime"));
    m_time->setMinimumWidth(
        m_time->fontMetrics().horizontalAdvance(QStringLiteral("0000.00 / 0000.00 s")));
    layout->addWidget(m_time);

    m_speed = new QComboBox(this);
    m_speed->setObjectName(QStringLiteral("replaySpeed"));
    m_speed->setToolTip(tr("Session seconds per real second"));
    for (double speed : Speeds)
        m_speed->addItem(tr("%1×").arg(QLocale().toString(speed)), speed);
    m_speed->setCurrentIndex(2);
    layout->addWidget(m_speed);

    m_about = new QLabel(this);
    m_about->setObjectName(QStringLiteral("replayAbout"));
    layout->addWidget(m_about);
    // Short of room, the words before the router's name go first; the tooltip keeps them.
    m_source = new ElidingLabel(this);
    m_source->setObjectName(QStringLiteral("replaySource"));
    layout->addWidget(m_source);
    m_reroute = new QToolButton(this);
    m_reroute->setObjectName(QStringLiteral("replayReroute"));
    m_reroute->setText(tr("Re-route")); // the tooltip says through what: the bar is short
    m_reroute->setToolTip(tr("Run the recorded contact frames through the router in the "
                             "router editor"));
    connect(m_reroute, &QToolButton::clicked, this, &ReplayBar::rerouteRequested);
    layout->addWidget(m_reroute);
    m_recorded = new QToolButton(this);
    m_recorded->setObjectName(QStringLiteral("replayRecorded"));
    m_recorded->setText(tr("Recorded router"));
    m_recorded->setToolTip(tr("Show the events and device frames the session recorded"));
    connect(m_recorded, &QToolButton::clicked, &m_replay, &SessionReplay::showRecorded);
    layout->addWidget(m_recorded);
    m_close = new QToolButton(this);
    m_close->setObjectName(QStringLiteral("replayClose"));
    m_close->setText(tr("Close replay"));
    connect(m_close, &QToolButton::clicked, this, &ReplayBar::closeRequested);
    layout->addWidget(m_close);

    m_timer.setInterval(33);
    connect(&m_timer, &QTimer::timeout, this, &ReplayBar::advance);
    connect(&m_replay, &SessionReplay::opened, this, &ReplayBar::sessionOpened);
    connect(&m_replay, &SessionReplay::timeChanged, this, &ReplayBar::showTime);
    const auto showSource = [this] {
        m_source->setFullText(m_replay.isRerouted()
                                  ? tr("Showing: re-routed through %1").arg(m_replay.routerName())
                                  : tr("Showing: recorded with %1").arg(m_replay.routerName()));
        m_recorded->setEnabled(m_replay.isRerouted());
    };
    connect(&m_replay, &SessionReplay::streamsChanged, this, showSource);
    connect(&m_replay, &SessionReplay::opened, this, showSource);
    connect(&m_replay, &SessionReplay::closed, this, [this] { setPlaying(false); });
    setPlaying(false);
}

void ReplayBar::setPlaying(bool playing)
{
    if (playing && m_replay.time() >= m_replay.endTime())
        m_slider->setValue(0); // from the start again
    if (playing) {
        m_clock.start();
        m_timer.start();
    } else {
        m_timer.stop();
    }
    m_play->setIcon(style()->standardIcon(playing ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
    m_play->setText(playing ? tr("Pause") : tr("Play"));
}

void ReplayBar::sessionOpened()
{
    // What the session was, in a word (the scrubber keeps the room); the rest on hover.
    const SessionInfo &info = m_replay.info();
    const QLocale locale;
    const QString started = info.started.isValid()
                                ? locale.toString(info.started.toLocalTime(), QLocale::ShortFormat)
                                : tr("unknown date");
    // A robot's recording is named by its file (`semhap import`, File → Open).
    const QString recording = info.extra.value(QStringLiteral("recording"));
    const QString what = !info.scene.isEmpty() ? QFileInfo(info.scene).completeBaseName()
                         : info.source == QLatin1String("import") ? QFileInfo(recording).fileName()
                                                                  : tr("live rig");
    m_about->setText(what);
    QStringList details;
    if (!info.notes.isEmpty())
        details << tr("Notes: %1").arg(info.notes);
    details << tr("Recorded by: %1").arg(info.source);
    if (!info.operatorName.isEmpty())
        details << tr("Operator: %1, seed %2").arg(info.operatorName, info.seed);
    details << (m_replay.isRecordedRouterEdited()
                    ? tr("Router: %1, edited (it routes differently from %1)")
                    : tr("Router: %1"))
                   .arg(info.routerSource);
    details << tr("Started: %1").arg(started);
    details << (info.ended.isValid()
                    ? tr("Ended: %1")
                          .arg(locale.toString(info.ended.toLocalTime(), QLocale::ShortFormat))
                    : tr("Ended: never closed (the recording was cut off)"));
    m_about->setToolTip(details.join(QLatin1Char('\n')));
    const QSignalBlocker block(m_slider);
    m_slider->setRange(
        0, int(std::lround((m_replay.endTime() - m_replay.startTime()) * StepsPerSecond)));
    m_slider->setValue(0);
    m_slider->setPageStep(int(StepsPerSecond));
    m_slider->setSingleStep(int(StepsPerSecond / 10));
    showTime(m_replay.time());
}

void ReplayBar::showTime(double t)
{
    m_time->setText(
        tr("%1 / %2 s")
            .arg(QLocale().toString(t, 'f', 2), QLocale().toString(m_replay.endTime(), 'f', 2)));
    const QSignalBlocker block(m_slider);
    m_slider->setValue(int(std::lround((t - m_replay.startTime()) * StepsPerSecond)));
}

void ReplayBar::advance()
{
    const double wall = double(m_clock.restart()) / 1000.0;
    const double t = m_replay.time() + wall * m_speed->currentData().toDouble();
    m_replay.seek(t);
    if (t >= m_replay.endTime())
        setPlaying(false);
}

} // namespace semhap
