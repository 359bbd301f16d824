// SPDX-License-Identifier: MIT
#pragma once

#include "devicemodel.h"
#include "patternrender.h"

#include <QStringList>
#include <QWidget>

#include <vector>

class QCPMarginGroup;
class QCustomPlot;
class QLabel;

namespace semhap {

/**
 * How a pattern will feel: per channel, the commanded signal (the frames the device gets,
 * at its rate) and the delivered output the device model predicts (dead time and lag), from
 * a begin at 0 to an end at a chosen time. Channels that get the same signal share a plot.
 */
class PatternPreview : public QWidget
{
    Q_OBJECT

public:
    explicit PatternPreview(QWidget *parent = nullptr);

    /**
     * Renders `pattern` on `model` at the model's rate (`options.rate` is ignored) and plots
     * it; a pattern the model cannot play shows why instead.
     */
    void showPattern(const PatternPtr &pattern, const DeviceModelPtr &model,
                     const RenderOptions &options);
    /** Shows a message (a load error) instead of plots. */
    void showMessage(const QString &message);

    QCustomPlot *plot() const { return m_plot; }
    /** Plots shown: groups of channels with the same commanded signal. */
    int groupCount() const { return int(m_groups.size()); }
    const QStringList &groupChannels(int group) const { return m_groups[size_t(group)].channels; }
    const std::vector<double> &commanded(int group) const
    {
        return m_groups[size_t(group)].commanded;
    }
    const std::vector<double> &predicted(int group) const
    {
        return m_groups[size_t(group)].predicted;
    }
    const std::vector<double> &times() const { return m_times; }
    QString message() const;

private:
    struct Group
    {
        QStringList channels;
        std::vector<double> commanded;
        std::vector<double> predicted;
    };

    void replot(const DeviceModel &model, double releaseAt);

    QCustomPlot *m_plot = nullptr;
    QCPMarginGroup *m_margins = nullptr;
    QLabel *m_message = nullptr;
    std::vector<Group> m_groups;
    std::vector<double> m_times;
};

} // namespace semhap
