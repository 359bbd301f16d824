// SPDX-License-Identifier: MIT
#pragma once

#include <qcustomplot.h>

#include <QString>

#include <vector>

/**
 * How the plot panel lays its rects out: the items it puts on them (time lines, texts), and
 * what keeps a rect readable at any size — its value range under its title and legend, value
 * ticks that stand apart, the legend beside or under the title, the levels' names apart.
 */
namespace semhap::plotlayout {

/** Places `position` on `rect`'s axes in the given coordinate types. */
void place(QCPItemPosition *position, QCPAxisRect *rect, QCPItemPosition::PositionType typeX,
           QCPItemPosition::PositionType typeY, double x, double y);
/** A vertical line at time `t` across `rect`. */
QCPItemStraightLine *addTimeLine(QCustomPlot *plot, QCPAxisRect *rect, double t, const QPen &pen);
/** Moves a line addTimeLine() made to time `t`. */
void moveTimeLine(QCPItemStraightLine *line, double t);
/** A text clipped to `rect`, padded, not selectable (placed by the caller). */
QCPItemText *addText(QCustomPlot *plot, QCPAxisRect *rect, const QString &text,
                     Qt::Alignment alignment);
/** The legend in the rect's top right corner, if it has one yet. */
QCPLegend *legendOf(QCPAxisRect *rect);

/** A graph on `rect` in its legend (made at its top right the first time), not antialiased. */
QCPGraph *addGraph(QCustomPlot *plot, QCPAxisRect *rect, const QString &id, const QString &name,
                   const QColor &color, double width);
/**
 * A horizontal line at `value` across `rect` (a detector's level), its right axis made ready
 * to name it (nameLevels()).
 */
void addLevelLine(QCustomPlot *plot, QCPAxisRect *rect, const QString &id, double value,
                  const QPen &pen);

/** Sets the rect's value range on both sides, so the level names stay at their lines. */
bool setValueRange(QCPAxisRect *rect, double lower, double upper);
/**
 * The upper end of a value range from `lower` that shows `top` below the rect's title (of
 * `titleHeight` pixels) and legend, with at least `headroom` (a part of the data's span)
 * above it.
 */
double upperUnderHeader(QCPAxisRect *rect, int titleHeight, double lower, double top,
                        double headroom);
/** As many value ticks on the rect as its height lets stand apart (true: changed). */
bool spaceValueTicks(QCPAxisRect *rect);
/**
 * Moves the legend under the rect's `title` where the two do not fit side by side (true:
 * moved; the inset is laid out at the next replot).
 */
bool placeLegend(QCPAxisRect *rect, const QCPItemText *title, int titleHeight);

/** A level's name beside its rect. */
struct LevelName
{
    QCPAxisRect *rect;
    double value;
    QString name;
};
/**
 * Names the levels of `all` that are `rect`'s beside it, on its right axis: levels closer
 * than a label's height share one label, a line each, so no name is drawn over another
 * (true: changed).
 */
bool nameLevels(QCPAxisRect *rect, const std::vector<LevelName> &all);

} // namespace semhap::plotlayout
