// SPDX-License-Identifier: MIT
#include "plotlayout.h"

#include "colors.h"

#include <qcustomplot.h>

#include <QFontMetrics>

#include <algorithm>
#include <cmath>
#include <limits>

namespace semhap::plotlayout {

void place(QCPItemPosition *position, QCPAxisRect *rect, QCPItemPosition::PositionType typeX,
           QCPItemPosition::PositionType typeY, double x, double y)
{
    position->setAxes(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
    position->setAxisRect(rect);
    position->setTypeX(typeX);
    position->setTypeY(typeY);
    position->setCoords(x, y);
}

/** A vertical line at time `t` across `rect`. */
QCPItemStraightLine *addTimeLine(QCustomPlot *plot, QCPAxisRect *rect, double t, const QPen &pen)
{
    auto *line = new QCPItemStraightLine(plot);
    line->setClipAxisRect(rect);
    line->setPen(pen);
    line->setSelectable(false);
    place(line->point1, rect, QCPItemPosition::ptPlotCoords, QCPItemPosition::ptAxisRectRatio, t,
          0.0);
    place(line->point2, rect, QCPItemPosition::ptPlotCoords, QCPItemPosition::ptAxisRectRatio, t,
          1.0);
    return line;
}

void moveTimeLine(QCPItemStraightLine *line, double t)
{
    line->point1->setCoords(t, 0.0);
    line->point2->setCoords(t, 1.0);
}

QCPItemText *addText(QCustomPlot *plot, QCPAxisRect *rect, const QString &text,
                     Qt::Alignment alignment)
{
    auto *item = new QCPItemText(plot);
    item->setClipAxisRect(rect);
    item->setSelectable(false);
    item->setText(text);
    item->setPositionAlignment(alignment);
    item->setPadding(QMargins(3, 1, 3, 1));
    return item;
}

/** The legend in the rect's top right corner, if it has one yet. */
QCPLegend *legendOf(QCPAxisRect *rect)
{
    if (rect->insetLayout()->elementCount() == 0)
        return nullptr;
    return qobject_cast<QCPLegend *>(rect->insetLayout()->elementAt(0));
}

QCPGraph *addGraph(QCustomPlot *plot, QCPAxisRect *rect, const QString &id, const QString &name,
                   const QColor &color, double width)
{
    QCPGraph *graph = plot->addGraph(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
    graph->setObjectName(id);
    graph->setName(name);
    QPen pen(color);
    pen.setWidthF(width);
    graph->setPen(pen);
    graph->setAntialiased(false);
    graph->setAdaptiveSampling(true);
    QCPLegend *legend = legendOf(rect);
    if (!legend) {
        legend = new QCPLegend;
        rect->insetLayout()->addElement(legend, Qt::AlignTop | Qt::AlignRight);
        legend->setLayer(QStringLiteral("legend"));
        legend->setFillOrder(QCPLayoutGrid::foColumnsFirst);
        legend->setBrush(colors::veil(200));
        legend->setBorderPen(QPen(colors::Border));
        legend->setRowSpacing(0);
        legend->setColumnSpacing(6);
        legend->setIconSize(16, 8);
        legend->setMargins(QMargins(4, 1, 4, 1));
    }
    graph->addToLegend(legend);
    return graph;
}

void addLevelLine(QCustomPlot *plot, QCPAxisRect *rect, const QString &id, double value,
                  const QPen &pen)
{
    auto *line = new QCPItemStraightLine(plot);
    line->setObjectName(id);
    line->setClipAxisRect(rect);
    line->setLayer(QStringLiteral("spans"));
    line->setPen(pen);
    line->setSelectable(false);
    place(line->point1, rect, QCPItemPosition::ptAxisRectRatio, QCPItemPosition::ptPlotCoords, 0.0,
          value);
    place(line->point2, rect, QCPItemPosition::ptAxisRectRatio, QCPItemPosition::ptPlotCoords, 1.0,
          value);
    // Named on the right axis, beside the plot, where no data, legend or span can hide it.
    QCPAxis *names = rect->axis(QCPAxis::atRight);
    auto ticker = names->ticker().dynamicCast<QCPAxisTickerText>();
    if (!ticker) {
        ticker.reset(new QCPAxisTickerText);
        ticker->setSubTickCount(0);
        names->setTicker(ticker);
        names->setVisible(true);
        names->setTickLabels(true);
        names->setBasePen(Qt::NoPen);
    }
}

bool setValueRange(QCPAxisRect *rect, double lower, double upper)
{
    if (rect->axis(QCPAxis::atLeft)->range() == QCPRange(lower, upper))
        return false;
    rect->axis(QCPAxis::atLeft)->setRange(lower, upper);
    rect->axis(QCPAxis::atRight)->setRange(lower, upper);
    return true;
}

double upperUnderHeader(QCPAxisRect *rect, int titleHeight, double lower, double top,
                        double headroom)
{
    // The title and the legend sit over the top of the rect: the range reaches so far above
    // the data that its top runs under them, never behind (a band's 1.0 went behind both).
    QCPLegend *legend = legendOf(rect);
    const int legendHeight = legend ? legend->outerRect().height() : 0;
    const bool stacked =
        legend && rect->insetLayout()->insetPlacement(0) == QCPLayoutInset::ipFree;
    const int header =
        (stacked ? titleHeight + legendHeight : std::max(titleHeight, legendHeight)) + 2;
    const int height = rect->rect().height();
    const double span = top - lower;
    double upper = top + span * headroom;
    if (height > header) // laid out
        upper = std::max(upper, lower + span * height / (height - header));
    return upper;
}

bool spaceValueTicks(QCPAxisRect *rect)
{
    // Labels a fifth of their height apart at least, on a step of 1, 2 or 5 times a
    // power of ten: the ticker's default of about five overlapped in the rects of both
    // hands' seven devices at 1920×1080.
    QCPAxis *axis = rect->axis(QCPAxis::atLeft);
    const double pixels = rect->rect().height();
    if (pixels <= 0)
        return false;
    const double least =
        axis->range().size() * 1.2 * QFontMetrics(axis->tickLabelFont()).height() / pixels;
    const double power = std::pow(10.0, std::floor(std::log10(least)));
    double step = 10 * power;
    for (double mantissa : {1.0, 2.0, 5.0}) {
        if (mantissa * power >= least) {
            step = mantissa * power;
            break;
        }
    }
    auto ticker = axis->ticker().staticCast<QCPAxisTickerFixed>();
    if (ticker->tickStep() == step)
        return false;
    ticker->setTickStep(step);
    return true;
}

bool placeLegend(QCPAxisRect *rect, const QCPItemText *title, int titleHeight)
{
    QCPLegend *legend = legendOf(rect);
    const int width = rect->rect().width();
    if (!legend || !title || width <= 0)
        return false;
    // Beside the title while both fit the rect's width; else under it, at the right (in a
    // narrow dock the legend of a signal's rect hid its title, "rechter Greifer: Kraft").
    const QCPItemText *text = title;
    const int titleWidth = QFontMetrics(text->font()).horizontalAdvance(text->text()) +
                           text->padding().left() + text->padding().right();
    const QSize size = legend->minimumOuterSizeHint();
    QCPLayoutInset *inset = rect->insetLayout();
    const bool beside = titleWidth + 8 + size.width() <= width;
    const auto placement = beside ? QCPLayoutInset::ipBorderAligned : QCPLayoutInset::ipFree;
    const QRectF under(std::max(0.0, 1.0 - double(size.width()) / width),
                       double(titleHeight) / std::max(1, rect->rect().height()), 0.0, 0.0);
    if (inset->insetPlacement(0) == placement && (beside || inset->insetRect(0) == under))
        return false;
    inset->setInsetPlacement(0, placement);
    if (!beside)
        inset->setInsetRect(0, under);
    return true;
}

bool nameLevels(QCPAxisRect *rect, const std::vector<LevelName> &all)
{
    QCPAxis *names = rect->axis(QCPAxis::atRight);
    auto ticker = names->ticker().dynamicCast<QCPAxisTickerText>();
    if (!ticker)
        return false;
    std::vector<const LevelName *> levels;
    for (const LevelName &level : all) {
        if (level.rect == rect)
            levels.push_back(&level);
    }
    std::stable_sort(levels.begin(), levels.end(),
                     [](const LevelName *a, const LevelName *b) { return a->value > b->value; });
    // Each level's name a label; two labels that would overlap become one, a line per name,
    // at their levels' mean, until none overlaps (two signal nodes' levels a thousandth apart
    // on a metre scale were drawn over each other).
    const double height = rect->rect().height();
    const double pixelsPerUnit = height > 0 && names->range().size() > 0
                                     ? height / names->range().size()
                                     : std::numeric_limits<double>::infinity(); // not laid out
    const double lineHeight = QFontMetrics(names->tickLabelFont()).height();
    struct Label
    {
        QStringList lines;
        double sum = 0.0; // of the levels' values
        double value() const { return sum / double(lines.size()); }
    };
    std::vector<Label> labels;
    for (const LevelName *level : levels)
        labels.push_back({{level->name}, level->value});
    for (size_t i = 0; i + 1 < labels.size();) {
        const Label &above = labels[i];
        const Label &below = labels[i + 1];
        const double apart = (above.value() - below.value()) * pixelsPerUnit;
        if (apart >= double(above.lines.size() + below.lines.size()) * lineHeight / 2) {
            ++i;
            continue;
        }
        labels[i].lines += below.lines;
        labels[i].sum += below.sum;
        labels.erase(labels.begin() + std::ptrdiff_t(i) + 1);
        i = i > 0 ? i - 1 : 0; // the grown label may now reach the one above
    }
    QMap<double, QString> ticks;
    for (const Label &label : labels)
        ticks.insert(label.value(), label.lines.join(QLatin1Char('\n')));
    if (ticker->ticks() == ticks)
        return false;
    ticker->setTicks(ticks);
    return true;
}

} // namespace semhap::plotlayout
