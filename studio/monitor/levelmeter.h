// SPDX-License-Identifier: MIT
#pragma once

#include <QStringList>
#include <QWidget>

#include <vector>

namespace semhap {

/** A device's channels as labelled horizontal bars, so the output can be seen at a glance. */
class LevelMeter : public QWidget
{
    Q_OBJECT

public:
    /** One channel: its name and the range the bar spans. */
    struct Channel
    {
        QString name;
        double min = 0.0;
        double max = 1.0;
    };

    explicit LevelMeter(QWidget *parent = nullptr);

    /** Sets the channels to show; the values go back to the channels' minimum. */
    void setChannels(const std::vector<Channel> &channels);
    /** Shows the latest values, one per channel (missing ones count as the minimum). */
    void setValues(const std::vector<double> &values);
    const std::vector<double> &values() const { return m_values; }
    const std::vector<Channel> &channels() const { return m_channels; }

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

protected:
    void paintEvent(QPaintEvent *event) override;

private:
    int rowHeight() const;

    std::vector<Channel> m_channels;
    std::vector<double> m_values;
};

} // namespace semhap
