// SPDX-License-Identifier: MIT
#include "plotcursor.h"

#include "colors.h"
#include "plotlayout.h"

#include <qcustomplot.h>

#include <QLabel>
#include <QMouseEvent>

#include <algorithm>
#include <cmath>
#include <limits>

namespace semhap {

PlotCursor::PlotCursor(QCustomPlot *plot, Readout readout)
    : QObject(plot), m_plot(plot), m_readoutText(std::move(readout)), m_readout(new QLabel(plot)),
      m_time(std::numeric_limits<double>::quiet_NaN())
{
    m_readout->setObjectName(QStringLiteral("cursorReadout"));
    m_readout->setStyleSheet(
        QStringLiteral("QLabel { background: rgba(255, 255, 255, 225); border: 1px solid #888;"
                       " padding: 3px; color: black; }"));
    m_readout->setAttribute(Qt::WA_TransparentForMouseEvents);
    m_readout->hide();
    connect(plot, &QCustomPlot::mousePress, this, &PlotCursor::onMousePress);
    connect(plot, &QCustomPlot::mouseMove, this, &PlotCursor::onMouseMove);
    connect(plot, &QCustomPlot::mouseRelease, this, &PlotCursor::onMouseRelease);
}

void PlotCursor::addLine(QCPAxisRect *rect)
{
    QPen pen(colors::Text);
    pen.setWidthF(1.5);
    QCPItemStraightLine *line = plotlayout::addTimeLine(m_plot, rect, 0.0, pen);
    line->setObjectName(QStringLiteral("cursor"));
    line->setVisible(false);
    m_lines.push_back(line);
}

void PlotCursor::clearLines()
{
    m_lines.clear();
}

void PlotCursor::setTime(double t)
{
    m_time = t;
    refresh();
}

QCPAxisRect *PlotCursor::firstRect() const
{
    return m_plot->axisRectCount() > 0 ? m_plot->axisRect(0) : nullptr;
}

void PlotCursor::refresh()
{
    const bool placed = !std::isnan(m_time);
    for (QCPItemStraightLine *line : m_lines) {
        line->setVisible(placed);
        if (placed)
            plotlayout::moveTimeLine(line, m_time);
    }
    if (!placed || !firstRect()) {
        m_readout->hide();
        return;
    }
    m_readout->setText(m_readoutText(m_time));
    m_readout->adjustSize();
    placeReadout();
}

void PlotCursor::placeReadout()
{
    QCPAxisRect *rect = firstRect();
    if (std::isnan(m_time) || !rect)
        return;
    QCPAxis *time = rect->axis(QCPAxis::atBottom);
    const int x = int(time->coordToPixel(m_time));
    // Right of the cursor, or left of it where it would cover the threshold names.
    int left = x + 10;
    if (left + m_readout->width() > rect->right())
        left = x - 10 - m_readout->width();
    m_readout->move(std::max(0, left), rect->top() + 2);
    m_readout->setVisible(time->range().contains(m_time));
}

void PlotCursor::onMousePress(QMouseEvent *event)
{
    if (event->button() != Qt::LeftButton || !firstRect())
        return;
    const QList<QCPAxisRect *> rects = m_plot->axisRects();
    const bool inside = std::any_of(rects.begin(), rects.end(), [event](QCPAxisRect *r) {
        return r->rect().contains(event->pos());
    });
    if (!inside)
        return;
    // Live, a drag can only mean the cursor; paused, a plain drag pans and Shift picks the
    // cursor. The plot sees the press after this signal, so switching drag off works now.
    if (!m_paused || event->modifiers().testFlag(Qt::ShiftModifier)) {
        m_dragging = true;
        m_plot->setInteraction(QCP::iRangeDrag, false);
    }
    placeAt(event->pos().x());
}

void PlotCursor::onMouseMove(QMouseEvent *event)
{
    if (m_dragging && event->buttons().testFlag(Qt::LeftButton))
        placeAt(event->pos().x());
}

void PlotCursor::onMouseRelease(QMouseEvent *)
{
    if (!m_dragging)
        return;
    m_dragging = false;
    m_plot->setInteraction(QCP::iRangeDrag, m_paused);
}

void PlotCursor::placeAt(int pixelX)
{
    setTime(firstRect()->axis(QCPAxis::atBottom)->pixelToCoord(pixelX));
    emit moved();
}

} // namespace semhap
