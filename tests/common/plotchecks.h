// SPDX-License-Identifier: MIT
#pragma once

#include <qcustomplot.h>

/** How many of the rect's value labels (its left axis' ticks) lie inside its range. */
inline int valueLabelsInView(QCPAxisRect *rect)
{
    const QCPAxis *values = rect->axis(QCPAxis::atLeft);
    int labels = 0;
    for (double tick : values->tickVector())
        labels += values->range().contains(tick) ? 1 : 0;
    return labels;
}
