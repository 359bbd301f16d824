// SPDX-License-Identifier: MIT
#pragma once

#include <QObject>
#include <QString>

#include <functional>
#include <vector>

class QCPAxisRect;
class QCPItemStraightLine;
class QCustomPlot;
class QLabel;
class QMouseEvent;

namespace semhap {

/**
 * The plot panel's cursor: a line at one time across every rect, and beside it a readout of
 * what the plots hold there, as the panel words it. A click places it; a drag moves it while
 * live, Shift+drag while paused (a plain drag pans then).
 */
class PlotCursor : public QObject
{
    Q_OBJECT

public:
    /** The readout's text at time `t`, from the panel that knows what it plots. */
    using Readout = std::function<QString(double t)>;

    PlotCursor(QCustomPlot *plot, Readout readout);

    /** Puts a cursor line on a new rect (hidden until the cursor is placed). */
    void addLine(QCPAxisRect *rect);
    /** Forgets the lines (after the plot's items were cleared). */
    void clearLines();
    /** The cursor's time; NaN when it is not placed. */
    double time() const { return m_time; }
    /** Places the cursor at `t` (NaN: takes it away) and reads the plots there. */
    void setTime(double t);
    /** Reads the plots again at the same time (new data, another view). */
    void refresh();
    /** Keeps the readout beside the cursor, on the view's side of it (after a layout). */
    void placeReadout();
    /** Paused, a plain drag pans the view and Shift+drag moves the cursor. */
    void setPaused(bool paused) { m_paused = paused; }

signals:
    /** The cursor moved under the mouse: the plot wants drawing. */
    void moved();

private:
    void onMousePress(QMouseEvent *event);
    void onMouseMove(QMouseEvent *event);
    void onMouseRelease(QMouseEvent *event);
    void placeAt(int pixelX);
    /** The first rect, whose time axis the cursor is placed on; null before there is one. */
    QCPAxisRect *firstRect() const;

    QCustomPlot *m_plot;
    Readout m_readoutText;
    QLabel *m_readout;
    std::vector<QCPItemStraightLine *> m_lines;
    double m_time;
    bool m_paused = false;
    bool m_dragging = false;
};

} // namespace semhap
