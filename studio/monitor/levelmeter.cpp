// SPDX-License-Identifier: MIT
#include "levelmeter.h"

#include "colors.h"

#include <QLocale>
#include <QPainter>

#include <algorithm>
#include <cmath>

namespace semhap {

LevelMeter::LevelMeter(QWidget *parent) : QWidget(parent)
{
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
}

void LevelMeter::setChannels(const std::vector<Channel> &channels)
{
    m_channels = channels;
    m_values.assign(channels.size(), 0.0);
    for (size_t i = 0; i < channels.size(); ++i)
        m_values[i] = channels[i].min;
    updateGeometry();
    update();
}

void LevelMeter::setValues(const std::vector<double> &values)
{
    for (size_t i = 0; i < m_channels.size(); ++i)
        m_values[i] = i < values.size() ? values[i] : m_channels[i].min;
    update();
}

int LevelMeter::rowHeight() const
{
    return fontMetrics().height() + 4;
}

QSize LevelMeter::sizeHint() const
{
    return {240, rowHeight() * int(std::max<size_t>(m_channels.size(), 1))};
}

QSize LevelMeter::minimumSizeHint() const
{
    return {120, sizeHint().height()};
}

void LevelMeter::paintEvent(QPaintEvent *)
{
    QPainter painter(this);
    const QFontMetrics metrics = fontMetrics();
    int nameWidth = 0;
    for (const Channel &channel : m_channels)
        nameWidth = std::max(nameWidth, metrics.horizontalAdvance(channel.name));
    const int valueWidth = metrics.horizontalAdvance(QStringLiteral("-000.00"));
    const int barLeft = nameWidth + 8;
    const int barWidth = std::max(10, width() - barLeft - valueWidth - 8);
    const int h = rowHeight();
    for (size_t i = 0; i < m_channels.size(); ++i) {
        const Channel &channel = m_channels[i];
        const int y = int(i) * h;
        const double span = channel.max - channel.min;
        const double value = std::isfinite(m_values[i]) ? m_values[i] : channel.min;
        const double fraction =
            span > 0.0 ? std::clamp((value - channel.min) / span, 0.0, 1.0) : 0.0;
        painter.setPen(palette().color(QPalette::WindowText));
        painter.drawText(QRect(0, y, nameWidth, h), Qt::AlignLeft | Qt::AlignVCenter,
                         channel.name);
        const QRect track(barLeft, y + 3, barWidth, h - 6);
        painter.fillRect(track, palette().color(QPalette::Base));
        painter.fillRect(QRect(track.left(), track.top(), int(std::lround(fraction * barWidth)),
                               track.height()),
                         colors::Level);
        painter.setPen(palette().color(QPalette::Mid));
        painter.drawRect(track.adjusted(0, 0, -1, -1));
        painter.setPen(palette().color(QPalette::WindowText));
        painter.drawText(QRect(track.right() + 6, y, valueWidth, h),
                         Qt::AlignRight | Qt::AlignVCenter, QLocale().toString(value, 'f', 2));
    }
}

} // namespace semhap
