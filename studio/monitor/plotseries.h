// SPDX-License-Identifier: MIT
#pragma once

#include "runhistory.h"

#include <QString>
#include <QStringList>

#include <vector>

class QCPAxisRect;
class QCPGraph;

namespace semhap {

// The series the plot panel draws, a struct per kind: each holds its rects and graphs and
// appends what is new of its own history series, by running index.

/** A gripper's two rects: its fingertips' forces and their sum, and its contact count. */
struct GripperPlot
{
    Gripper gripper = Gripper::Right;
    QCPAxisRect *forceRect = nullptr;
    QCPAxisRect *countRect = nullptr;
    QCPGraph *left = nullptr;
    QCPGraph *right = nullptr;
    QCPGraph *sum = nullptr;
    QCPGraph *count = nullptr;
    double thresholdTop = 0.0; ///< the highest force threshold, kept in view
    double countTop = 0.0;     ///< the highest count threshold, kept in view
    qint64 next = 0;           ///< the history index not yet plotted

    /** Appends what the history got since the last call to the graphs. */
    void appendNew(const RunHistory &history);
};

/** A frame signal that threshold nodes read, with their levels. */
struct SignalPlot
{
    Gripper gripper = Gripper::Right;
    QString quantity; ///< the signal's name (`plug.angle`)
    int id = -1;      ///< its signalNames() id
    QCPAxisRect *rect = nullptr;
    QCPGraph *graph = nullptr;
    QStringList nodes; ///< the threshold nodes reading it: their spans are shaded here
    bool hasLevels = false;
    double levelLow = 0.0; ///< the levels drawn, kept in view
    double levelHigh = 0.0;
    bool gap = true; ///< the last point plotted was a frame without the signal (or none)
    qint64 next = 0;

    /** Appends what the history got since the last call to the graphs. */
    void appendNew(const RunHistory &history);
};

/** A device's rect: a curve per channel of what was sent to it. */
struct DevicePlot
{
    int device = 0;
    QCPAxisRect *rect = nullptr;
    std::vector<QCPGraph *> graphs;
    qint64 next = 0;
    int rewinds = 0;  ///< the series' rewinds() when it was read
    double low = 0.0; ///< the value range seen since the run started, at least 0..1
    double high = 1.0;

    /** Appends what the history got since the last call to the graphs. */
    void appendNew(const RunHistory &history);
};

} // namespace semhap
