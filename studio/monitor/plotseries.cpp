// SPDX-License-Identifier: MIT
#include "plotseries.h"

#include <qcustomplot.h>

#include <algorithm>
#include <limits>

namespace semhap {

void GripperPlot::appendNew(const RunHistory &history)
{
    QVector<QCPGraphData> leftForce, rightForce, totalForce, contacts;
    const RunSeries<ContactFrame> &frames = history.frames(gripper);
    for (qint64 i = std::max(next, frames.begin()); i < frames.end(); ++i) {
        const ContactFrame &frame = frames.at(i);
        leftForce.append(QCPGraphData(frame.t, frame.left.f));
        rightForce.append(QCPGraphData(frame.t, frame.right.f));
        totalForce.append(QCPGraphData(frame.t, frame.totalForce()));
        contacts.append(QCPGraphData(frame.t, frame.totalContacts()));
    }
    next = frames.end();
    left->data()->add(leftForce, true);
    right->data()->add(rightForce, true);
    sum->data()->add(totalForce, true);
    count->data()->add(contacts, true);
}

void SignalPlot::appendNew(const RunHistory &history)
{
    QVector<QCPGraphData> values;
    const RunSeries<ContactFrame> &frames = history.frames(gripper);
    for (qint64 i = std::max(next, frames.begin()); i < frames.end(); ++i) {
        const ContactFrame &frame = frames.at(i);
        const double *value = frame.signalValues.find(id);
        // A frame without the signal breaks the curve (a NaN is a gap).
        if (value || !gap)
            values.append(
                QCPGraphData(frame.t, value ? *value : std::numeric_limits<double>::quiet_NaN()));
        gap = !value;
    }
    next = frames.end();
    graph->data()->add(values, true);
}

void DevicePlot::appendNew(const RunHistory &history)
{
    const RunSeries<DeviceFrame> &frames = history.deviceFrames(device);
    if (frames.rewinds() != rewinds) {
        // The run went on where an audition had drawn ahead of it: draw it again.
        rewinds = frames.rewinds();
        next = frames.begin();
        for (QCPGraph *graph : graphs)
            graph->data()->clear();
    }
    std::vector<QVector<QCPGraphData>> channels(graphs.size());
    for (qint64 i = std::max(next, frames.begin()); i < frames.end(); ++i) {
        const DeviceFrame &frame = frames.at(i);
        const size_t n = std::min(channels.size(), size_t(frame.channelCount));
        for (size_t c = 0; c < n; ++c) {
            channels[c].append(QCPGraphData(frame.t, frame.values[c]));
            low = std::min(low, frame.values[c]);
            high = std::max(high, frame.values[c]);
        }
    }
    next = frames.end();
    for (size_t c = 0; c < channels.size(); ++c)
        graphs[c]->data()->add(channels[c], true);
}

} // namespace semhap
