// SPDX-License-Identifier: MIT
#include "spanoverlay.h"

#include "colors.h"
#include "plotlayout.h"

#include <qcustomplot.h>

#include <algorithm>

namespace semhap {

using namespace plotlayout;

/** The items showing one MessageSpan on the rects it belongs to. */
struct SpanOverlay::View
{
    Gripper gripper = Gripper::Right;
    QString node;
    Message message = Message::Grasp;
    double begin = 0.0;
    double end = 0.0;
    bool active = true;
    int row = 0; ///< the label's own row under the rect's title (a kind of message each)
    std::vector<QCPItemRect *> shades; ///< one per rect it is shaded on
    std::vector<QCPItemStraightLine *> beginLines;
    std::vector<QCPItemStraightLine *> endLines;
    QCPItemText *label = nullptr;
    bool seen = false;

    bool shows(const MessageSpan &span) const
    {
        return span.gripper == gripper && span.node == node && span.message == message &&
               span.begin == begin;
    }
};

SpanOverlay::SpanOverlay(QCustomPlot *plot) : m_plot(plot) {}

SpanOverlay::~SpanOverlay() = default;

void SpanOverlay::clear()
{
    m_views.clear();
}

SpanOverlay::View SpanOverlay::makeView(const MessageSpan &span,
                                        const std::vector<QCPAxisRect *> &rects)
{
    QCPAxisRect *labelRect = rects.front();
    View view;
    view.gripper = span.gripper;
    view.node = span.node;
    view.message = span.message;
    view.begin = span.begin;
    // Confirmations blue, exceptions orange; slip hatched vermillion so it never reads as
    // a break even without colour.
    QColor color = colors::Blue;
    QBrush brush;
    if (span.category == Category::Exception)
        color = span.message == Message::Slip ? colors::Vermillion : colors::Orange;
    if (span.message == Message::Slip) {
        QColor hatch = color;
        hatch.setAlpha(140);
        brush = QBrush(hatch, Qt::BDiagPattern);
    } else {
        QColor fill = color;
        fill.setAlpha(span.category == Category::Exception ? 70 : 32);
        brush = QBrush(fill);
    }
    // A threshold node's message is named after its node, in rows under the detectors'
    // labels: a predicted break begins while the force detector's is still ahead.
    const bool threshold = span.detector == DetectorKind::Threshold;
    QString id =
        QStringLiteral("span.%1.%2").arg(gripperName(span.gripper), messageName(span.message));
    if (threshold)
        id += QLatin1Char('/') + span.node;
    for (size_t i = 0; i < rects.size(); ++i) {
        auto *shade = new QCPItemRect(m_plot);
        shade->setObjectName(id);
        shade->setClipAxisRect(rects[i]);
        shade->setLayer(QStringLiteral("spans"));
        shade->setPen(Qt::NoPen);
        shade->setBrush(brush);
        shade->setSelectable(false);
        place(shade->topLeft, rects[i], QCPItemPosition::ptPlotCoords,
              QCPItemPosition::ptAxisRectRatio, span.begin, 0.0);
        place(shade->bottomRight, rects[i], QCPItemPosition::ptPlotCoords,
              QCPItemPosition::ptAxisRectRatio, span.end, 1.0);
        view.shades.push_back(shade);
        view.beginLines.push_back(addTimeLine(m_plot, rects[i], span.begin, QPen(color, 1.0)));
        view.endLines.push_back(addTimeLine(m_plot, rects[i], span.end, QPen(color, 1.0)));
        view.beginLines.back()->setLayer(QStringLiteral("spans"));
        view.endLines.back()->setLayer(QStringLiteral("spans"));
    }
    view.label = addText(m_plot, labelRect, threshold ? span.node : messageName(span.message),
                         Qt::AlignLeft | Qt::AlignTop);
    view.label->setObjectName(id);
    view.label->setColor(color.darker(150));
    QFont font = view.label->font();
    font.setBold(true);
    view.label->setFont(font);
    view.label->setBrush(colors::veil(170));
    // A row per kind of message below the rect's title, so overlapping spans stay readable
    // (layoutLabels() places it).
    view.row = int(span.message) + (threshold ? 3 : 0);
    place(view.label->position, labelRect, QCPItemPosition::ptPlotCoords,
          QCPItemPosition::ptAxisRectRatio, span.begin, 0.0);
    return view;
}

void SpanOverlay::stretch(const View &view, const MessageSpan &span)
{
    for (size_t i = 0; i < view.shades.size(); ++i) {
        view.shades[i]->bottomRight->setCoords(span.end, 1.0);
        moveTimeLine(view.endLines[i], span.end);
        view.endLines[i]->setVisible(!span.active);
    }
}

void SpanOverlay::sync(const std::vector<MessageSpan> &spans, const Placement &where)
{
    for (View &view : m_views)
        view.seen = false;
    for (const MessageSpan &span : spans) {
        auto view = std::find_if(m_views.begin(), m_views.end(),
                                 [&](const View &v) { return v.shows(span); });
        if (view == m_views.end()) {
            bool labelled = false;
            const std::vector<QCPAxisRect *> rects = where(span, &labelled);
            if (rects.empty())
                continue;
            m_views.push_back(makeView(span, rects));
            view = m_views.end() - 1;
            view->label->setVisible(labelled);
        }
        view->seen = true;
        view->end = span.end;
        view->active = span.active;
        stretch(*view, span);
    }
    // Spans the history forgot.
    const auto gone =
        std::partition(m_views.begin(), m_views.end(), [](const View &v) { return v.seen; });
    for (auto it = gone; it != m_views.end(); ++it) {
        for (size_t i = 0; i < it->shades.size(); ++i) {
            m_plot->removeItem(it->shades[i]);
            m_plot->removeItem(it->beginLines[i]);
            m_plot->removeItem(it->endLines[i]);
        }
        m_plot->removeItem(it->label);
    }
    m_views.erase(gone, m_views.end());
}

void SpanOverlay::layoutLabels(Gripper gripper, QCPAxisRect *forceRect)
{
    const QRect area = forceRect->rect();
    const QCPAxis *time = forceRect->axis(QCPAxis::atBottom);
    const QCPRange range = time->range();
    // A span's label shows while the span does: from its begin, or from the view's left
    // edge while it goes on; an ended span out of view takes it along.
    std::vector<View *> shown;
    for (View &view : m_views) {
        if (view.gripper != gripper)
            continue;
        view.label->setVisible(false);
        const bool inView = view.begin <= range.upper && (view.active || view.end >= range.lower);
        if (inView && area.height() > 0)
            shown.push_back(&view);
    }
    std::stable_sort(shown.begin(), shown.end(),
                     [](const View *a, const View *b) { return a->begin < b->begin; });
    // In rows as tall as a label under the rect's title, in the upper part where the
    // force curves leave room: each kind of message on its own row, so the labels read
    // as lanes; a label that would cover another waits until it would not (its span is
    // shaded anyway). A rect too short for a kind's row lends it the first free row. The
    // legend's box is taken (under the title in a narrow rect).
    std::vector<QRectF> taken;
    if (const QCPLegend *legend = legendOf(forceRect))
        taken.push_back(QRectF(legend->outerRect()));
    for (View *view : shown) {
        double x = std::max(view->begin, range.lower);
        view->label->position->setCoords(x, 0.0);
        QRectF box(view->label->topLeft->pixelPosition(),
                   view->label->bottomRight->pixelPosition());
        // A span begun near the right edge has its label end there, not cut off by it.
        if (box.right() > area.right()) {
            x = time->pixelToCoord(area.right() - box.width());
            view->label->position->setCoords(x, 0.0);
            box = QRectF(view->label->topLeft->pixelPosition(),
                         view->label->bottomRight->pixelPosition());
        }
        const double rowHeight = box.height() + 1.0;
        // Less the title's row; a squeezed rect still has the one under its title.
        int rows = int(area.height() * 0.75 / rowHeight) - 1;
        if (rows < 1 && area.height() >= 2 * rowHeight)
            rows = 1;
        std::vector<int> tries{view->row};
        if (view->row >= rows) {
            tries.clear();
            for (int row = 0; row < rows; ++row)
                tries.push_back(row);
        }
        for (int row : tries) {
            const QRectF at = box.translated(0.0, (row + 1) * rowHeight);
            const auto overlaps = [&at](const QRectF &other) {
                return other.adjusted(-2.0, 0.0, 2.0, 0.0).intersects(at);
            };
            if (std::any_of(taken.begin(), taken.end(), overlaps))
                continue;
            taken.push_back(at);
            view->label->position->setCoords(x, (at.top() - area.top()) / area.height());
            view->label->setVisible(true);
            break;
        }
    }
}

} // namespace semhap
