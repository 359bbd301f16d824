// SPDX-License-Identifier: MIT
#include "runreadouts.h"

#include "colors.h"
#include "devicemanager.h"
#include "engine.h"
#include "statusbar.h"

#include <QFileInfo>
#include <QLabel>
#include <QLocale>

#include <climits>
#include <map>

namespace semhap {

RunReadouts::RunReadouts(StatusBar *bar, const Engine &engine, QObject *parent)
    : QObject(parent), m_bar(bar), m_engine(engine)
{
    const auto label = [bar](const QString &name) {
        auto *l = new QLabel(bar);
        l->setObjectName(name);
        bar->addPermanentWidget(l);
        return l;
    };
    m_recordLabel = label(QStringLiteral("recordLabel"));
    m_recordLabel->setStyleSheet(
        QStringLiteral("color: %1; font-weight: bold;").arg(colors::css(colors::Error)));
    m_operatorLabel = label(QStringLiteral("operatorLabel"));
    m_devicesLabel = label(QStringLiteral("devicesLabel"));
    m_timeLabel = label(QStringLiteral("timeLabel"));
    m_rateLabel = label(QStringLiteral("rateLabel"));
    m_foxgloveLabel = label(QStringLiteral("foxgloveLabel"));
    m_timer.setInterval(250);
    connect(&m_timer, &QTimer::timeout, this, &RunReadouts::update);
    m_timer.start();
}

void RunReadouts::update()
{
    const QLocale locale;
    m_recordLabel->setVisible(m_engine.isRecording());
    if (m_engine.isRecording())
        m_recordLabel->setText(tr("Recording to %1 (%2 dropped)")
                                   .arg(QFileInfo(m_engine.recordingPath()).fileName())
                                   .arg(m_engine.recordingDropped()));
    m_timeLabel->setText(tr("t = %1 s").arg(locale.toString(m_engine.simTime(), 'f', 2)));
    m_foxgloveLabel->setVisible(m_engine.isPublishing());
    if (m_engine.isPublishing()) {
        const FoxgloveServer::Stats served = m_engine.publishingStats();
        m_foxgloveLabel->setText(tr("Foxglove: %n viewer(s)", nullptr, served.clients));
        m_foxgloveLabel->setToolTip(
            tr("Published at %1: %2 message(s) sent, %3 dropped for slow viewers")
                .arg(m_engine.publishingUrl())
                .arg(served.sent)
                .arg(served.dropped));
    }
    m_rateLabel->setToolTip(QString()); // a live rig's says why its datagrams were refused
    if (m_engine.isReplaying()) {
        m_operatorLabel->setText(tr("Replay: nobody drives"));
        m_rateLabel->setText(tr("replay"));
        return;
    }
    if (m_engine.isLive()) {
        updateLive();
        updateDevices();
        return;
    }
    m_rateLabel->setText(
        m_engine.isRunning()
            ? tr("%1× real time").arg(locale.toString(m_engine.realtimeFactor(), 'f', 2))
            : tr("paused"));
    m_operatorLabel->setText(m_engine.isDriving()
                                 ? tr("You are driving")
                                 : tr("Operator: %1").arg(m_engine.options().operatorName));
    updateDevices();
}

void RunReadouts::updateLive()
{
    const QLocale locale;
    const RunSource::LinkStats stats = m_engine.liveStats();
    m_operatorLabel->setText(tr("Live rig on %1").arg(m_engine.liveUri()));
    QString rate = m_engine.isRunning() ? tr("%1 frames/s, jitter %2 ms")
                                              .arg(locale.toString(stats.framesPerSecond, 'f', 0),
                                                   locale.toString(stats.jitter * 1000.0, 'f', 1))
                                        : tr("paused: %n frame(s) held", nullptr,
                                             int(std::min<quint64>(stats.held, INT_MAX)));
    if (stats.rejected > 0)
        rate += tr(" · %n malformed", nullptr, int(std::min<quint64>(stats.rejected, INT_MAX)));
    m_rateLabel->setText(rate);
    // The latest rejection says what was wrong with it, as it comes.
    if (stats.reasons != m_shownRejections) {
        m_shownRejections = stats.reasons;
        m_bar->showMessage(tr("Malformed datagram: %1").arg(stats.lastRejection), 5000);
    }
    // The message goes after 5 s and a narrow window cuts it: the count's tooltip keeps the
    // reason.
    m_rateLabel->setToolTip(stats.reasons > 0
                                ? tr("Latest malformed datagram: %1").arg(stats.lastRejection)
                                : QString());
}

void RunReadouts::updateDevices()
{
    // Counted by the state the Devices panel shows each band in (TransportStatus::state).
    int virtualCount = 0;
    std::map<LinkState, int> count;
    for (const BoundDevice &device : m_engine.devices().status()) {
        if (device.uri.startsWith(QLatin1String("virtual:")))
            ++virtualCount;
        else
            ++count[device.status.state()];
    }
    QString devices =
        tr("Devices: %1 virtual, %2 connected").arg(virtualCount).arg(count[LinkState::Connected]);
    if (count[LinkState::Connecting] > 0)
        devices += tr(", %1 connecting").arg(count[LinkState::Connecting]);
    if (count[LinkState::Disconnected] > 0)
        devices += tr(", %1 disconnected").arg(count[LinkState::Disconnected]);
    m_devicesLabel->setText(devices);
}

} // namespace semhap
