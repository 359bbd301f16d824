// SPDX-License-Identifier: MIT
#pragma once

#include <QElapsedTimer>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

/** One line of a band's state log (`semhap emulate --log`, `semhap bandsim --log`). */
struct BandLogLine
{
    double t = 0.0;
    std::vector<double> setpoint;
    std::vector<double> values;
};

/** The log's complete lines so far (the band may be writing the next one). */
inline std::vector<BandLogLine> readBandLog(const QString &path)
{
    std::vector<BandLogLine> out;
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return out;
    for (const QByteArray &line : file.readAll().split('\n')) {
        const QJsonObject o = QJsonDocument::fromJson(line).object();
        if (o.isEmpty())
            continue; // a line still being written
        BandLogLine l;
        l.t = o.value("t").toDouble();
        for (const QJsonValue &v : o.value("setpoint").toArray())
            l.setpoint.push_back(v.toDouble());
        for (const QJsonValue &v : o.value("values").toArray())
            l.values.push_back(v.toDouble());
        out.push_back(l);
    }
    return out;
}

/** Polls the log until `done` holds for its last line; the elapsed ms, or -1 on timeout. */
inline qint64 waitForBandLog(const QString &path,
                             const std::function<bool(const BandLogLine &)> &done, int timeoutMs)
{
    QElapsedTimer timer;
    timer.start();
    while (timer.elapsed() < timeoutMs) {
        const std::vector<BandLogLine> log = readBandLog(path);
        if (!log.empty() && done(log.back()))
            return timer.elapsed();
        QTest::qSleep(5);
    }
    return -1;
}

/** Whether every setpoint of `line` is `value`. */
inline bool allAt(const BandLogLine &line, double value)
{
    return !line.setpoint.empty() &&
           std::all_of(line.setpoint.begin(), line.setpoint.end(),
                       [value](double v) { return std::abs(v - value) < 1e-3; });
}

/** When channel `channel`'s setpoint rose above 0.5: the log's pulses. */
inline std::vector<double> pulseStarts(const std::vector<BandLogLine> &lines, size_t channel)
{
    std::vector<double> starts;
    double previous = 0.0;
    for (const BandLogLine &l : lines) {
        if (l.setpoint[channel] > 0.5 && previous <= 0.5)
            starts.push_back(l.t);
        previous = l.setpoint[channel];
    }
    return starts;
}
