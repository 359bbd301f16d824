// SPDX-License-Identifier: MIT
#pragma once

#include "contactframe.h"

#include <QByteArray>
#include <QString>

#include <vector>

namespace semhap {

class RunHistory;

/**
 * A stretch of a run's history as CSV, the series the plots show: what Plots → Export CSV
 * writes. The header is `t`, then per gripper `G.F,G.left.f,G.right.f,G.N`, each frame
 * signal by its name, each device channel as `device.channel`. A row is written at each
 * contact frame's time (both grippers' merged: the pipeline's tick), or at each device
 * frame's when no gripper has data; every cell is its series' latest sample at or before
 * the row's time (as a sample-and-hold reading of the plot), empty before its first.
 */
class HistoryCsv
{
public:
    struct FrameSignal
    {
        Gripper gripper = Gripper::Right;
        int id = -1;  ///< its signalNames() id
        QString name; ///< its column's header
    };
    /** Which series the CSV holds. */
    struct Columns
    {
        std::vector<Gripper> grippers;
        std::vector<FrameSignal> frameSignals;
        std::vector<int> devices; ///< every channel of each
    };

    /** The rows with a time in [from, to], as UTF-8. */
    static QByteArray write(const RunHistory &history, const Columns &columns, double from,
                            double to);
};

} // namespace semhap
