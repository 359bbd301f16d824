// SPDX-License-Identifier: MIT
#include "historycsv.h"

#include "runhistory.h"

#include <QLocale>
#include <QStringList>
#include <QTextStream>

#include <algorithm>

namespace semhap {

namespace {

QString number(double value)
{
    return QLocale::c().toString(value, 'g', 10);
}

} // namespace

QByteArray HistoryCsv::write(const RunHistory &history, const Columns &columns, double from,
                             double to)
{
    QStringList header{QStringLiteral("t")};
    for (const Gripper gripper : columns.grippers) {
        const QString id = gripperName(gripper);
        for (const char *column : {".F", ".left.f", ".right.f", ".N"})
            header << id + QLatin1String(column);
    }
    for (const FrameSignal &signal : columns.frameSignals)
        header << signal.name;
    for (const int device : columns.devices) {
        const RunDevice &info = history.devices()[size_t(device)];
        for (const QString &channel : info.channels)
            header << info.name + QLatin1Char('.') + channel;
    }

    std::vector<double> times;
    const auto collect = [&](const auto &series) {
        for (qint64 i = series.begin(); i < series.end(); ++i) {
            const double t = series.at(i).t;
            if (t >= from && t <= to)
                times.push_back(t);
        }
    };
    for (const Gripper gripper : columns.grippers)
        collect(history.frames(gripper));
    if (times.empty()) {
        for (const int device : columns.devices)
            collect(history.deviceFrames(device));
    }
    std::sort(times.begin(), times.end());
    times.erase(std::unique(times.begin(), times.end()), times.end());

    QString text;
    QTextStream out(&text);
    out << header.join(QLatin1Char(',')) << '\n';
    QStringList cells;
    for (const double t : times) {
        cells.clear();
        cells << number(t);
        for (const Gripper gripper : columns.grippers) {
            if (const ContactFrame *frame = history.frames(gripper).latestAt(t))
                cells << number(frame->totalForce()) << number(frame->left.f)
                      << number(frame->right.f) << QString::number(frame->totalContacts());
            else
                cells << QString() << QString() << QString() << QString();
        }
        for (const FrameSignal &signal : columns.frameSignals) {
            const ContactFrame *frame = history.frames(signal.gripper).latestAt(t);
            const double *value = frame ? frame->signalValues.find(signal.id) : nullptr;
            cells << (value ? number(*value) : QString());
        }
        for (const int device : columns.devices) {
            const DeviceFrame *frame = history.deviceFrames(device).latestAt(t);
            const int n = int(history.devices()[size_t(device)].channels.size());
            for (int c = 0; c < n; ++c)
                cells << (frame && c < frame->channelCount ? number(frame->values[size_t(c)])
                                                           : QString());
        }
        out << cells.join(QLatin1Char(',')) << '\n';
    }
    out.flush();
    return text.toUtf8();
}

} // namespace semhap
