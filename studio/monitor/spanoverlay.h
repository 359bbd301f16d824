// SPDX-License-Identifier: MIT
#pragma once

#include "runhistory.h"

#include <functional>
#include <vector>

class QCPAxisRect;
class QCustomPlot;

namespace semhap {

/**
 * The message spans over the plot panel's curves: each span shaded with its begin and end
 * lines on the rects it belongs to, and its label in a lane under its gripper's force rect's
 * title, none over another. The panel says where each span goes; the overlay keeps its items
 * in step with the history's spans.
 */
class SpanOverlay
{
public:
    /**
     * Where a span shows: the rects it is shaded on (its label goes on the first; none: not
     * shown), and whether its label is laid out (layoutLabels()) or hidden.
     */
    using Placement =
        std::function<std::vector<QCPAxisRect *>(const MessageSpan &span, bool *labelled)>;

    explicit SpanOverlay(QCustomPlot *plot);
    ~SpanOverlay();
    SpanOverlay(const SpanOverlay &) = delete;
    SpanOverlay &operator=(const SpanOverlay &) = delete;

    /** Draws the new spans, stretches the growing ones and removes those the history forgot. */
    void sync(const std::vector<MessageSpan> &spans, const Placement &where);
    /**
     * Shows the labels of `gripper`'s spans in view on `forceRect`, none over another, in a
     * lane per kind of message (the rect's pixels must be laid out).
     */
    void layoutLabels(Gripper gripper, QCPAxisRect *forceRect);
    /** Forgets every span (after the plot's items were cleared). */
    void clear();

private:
    struct View;

    /** Shades `span` on `rects`; its label goes on the first. */
    View makeView(const MessageSpan &span, const std::vector<QCPAxisRect *> &rects);
    /** Moves its end to where the span has got to (an active span shows no end line). */
    void stretch(const View &view, const MessageSpan &span);

    QCustomPlot *m_plot;
    std::vector<View> m_views;
};

} // namespace semhap
