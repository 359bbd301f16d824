// SPDX-License-Identifier: MIT
#include "patternpreview.h"

#include "colors.h"

#include <QLabel>
#include <QVBoxLayout>

#include <qcustomplot.h>

#include <algorithm>
#include <cmath>

namespace semhap {

namespace {

const QColor &Commanded = colors::Confirmation;
const QColor &Predicted = colors::Error;
const QColor &Marker = colors::MutedText;

} // namespace

PatternPreview::PatternPreview(QWidget *parent) : QWidget(parent)
{
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    m_message = new QLabel(this);
    m_message->setObjectName(QStringLiteral("previewMessage"));
    m_message->setWordWrap(true);
    m_message->setStyleSheet(
        QStringLiteral("QLabel { background: %1; border: 1px solid %2; padding: 6px; }")
            .arg(colors::css(colors::ExceptionWash), colors::css(colors::Exception)));
    m_message->hide();
    m_plot = new QCustomPlot(this);
    m_plot->setObjectName(QStringLiteral("previewPlot"));
    m_plot->setMinimumHeight(160);
    layout->addWidget(m_message);
    layout->addWidget(m_plot, 1);
}

QString PatternPreview::message() const
{
    return m_message->isVisible() ? m_message->text() : QString();
}

void PatternPreview::showMessage(const QString &message)
{
    m_message->setText(message);
    m_message->show();
}

void PatternPreview::showPattern(const PatternPtr &pattern, const DeviceModelPtr &model,
                                 const RenderOptions &options)
{
    m_groups.clear();
    m_times.clear();
    RenderOptions atRate = options;
    atRate.rate = model->rate();
    RenderedPattern rendered;
    QString reason;
    if (!renderPattern(pattern, *model, atRate, &rendered, &reason)) {
        showMessage(reason);
        replot(*model, options.releaseAt);
        return;
    }
    m_message->hide();
    m_times = rendered.t;
    for (int c = 0; c < int(rendered.channels.size()); ++c) {
        const std::vector<double> &column = rendered.values[size_t(c)];
        auto same = std::find_if(m_groups.begin(), m_groups.end(),
                                 [&](const Group &g) { return g.commanded == column; });
        if (same != m_groups.end()) {
            same->channels.append(rendered.channels[c]);
            continue;
        }
        m_groups.push_back({{rendered.channels[c]}, column, model->predict(column, atRate.rate)});
    }
    replot(*model, options.releaseAt);
}

void PatternPreview::replot(const DeviceModel &model, double releaseAt)
{
    m_plot->clearItems();
    m_plot->clearGraphs();
    m_plot->plotLayout()->clear();
    delete m_margins;
    m_margins = new QCPMarginGroup(m_plot);
    const double end = m_times.empty() ? 1.0 : m_times.back() + 1.0 / model.rate();
    const double low = model.channels().empty() ? 0.0 : model.channels().front().min;
    const double high = model.channels().empty() ? 1.0 : model.channels().front().max;
    for (size_t g = 0; g < m_groups.size(); ++g) {
        const Group &group = m_groups[g];
        auto *rect = new QCPAxisRect(m_plot);
        rect->setMarginGroup(QCP::msLeft | QCP::msRight, m_margins);
        rect->setMinimumSize(0, 50);
        m_plot->plotLayout()->addElement(int(g), 0, rect);
        QCPAxis *time = rect->axis(QCPAxis::atBottom);
        QCPAxis *value = rect->axis(QCPAxis::atLeft);
        time->setRange(0, end);
        value->setRange(low - 0.05 * (high - low), high + 0.1 * (high - low));
        value->setLabel(group.channels.size() == model.channelCount() && g == 0
                            ? tr("all channels")
                            : group.channels.join(QStringLiteral(", ")));
        const bool last = g + 1 == m_groups.size();
        time->setTickLabels(last);
        if (last)
            time->setLabel(tr("time since begin (s)"));

        const QVector<double> t(m_times.begin(), m_times.end());
        QCPGraph *commanded = m_plot->addGraph(time, value);
        commanded->setObjectName(QStringLiteral("commanded:%1").arg(g));
        commanded->setName(tr("commanded"));
        commanded->setLineStyle(QCPGraph::lsStepLeft);
        commanded->setPen(QPen(Commanded, 1.2));
        commanded->setData(t, QVector<double>(group.commanded.begin(), group.commanded.end()),
                           true);
        QCPGraph *predicted = m_plot->addGraph(time, value);
        predicted->setObjectName(QStringLiteral("predicted:%1").arg(g));
        predicted->setName(tr("predicted output"));
        predicted->setPen(QPen(Predicted, 2.0));
        predicted->setData(t, QVector<double>(group.predicted.begin(), group.predicted.end()),
                           true);

        if (std::isfinite(releaseAt) && releaseAt < end) {
            auto *line = new QCPItemStraightLine(m_plot);
            line->setClipAxisRect(rect);
            for (QCPItemPosition *p : {line->point1, line->point2}) {
                p->setAxes(time, value);
                p->setAxisRect(rect);
            }
            line->point1->setCoords(releaseAt, 0);
            line->point2->setCoords(releaseAt, 1);
            line->setPen(QPen(Marker, 1, Qt::DashLine));
            if (g == 0) {
                auto *label = new QCPItemText(m_plot);
                label->setClipToAxisRect(false);
                label->position->setAxes(time, value);
                label->position->setCoords(releaseAt, value->range().lower);
                label->setPositionAlignment(Qt::AlignLeft | Qt::AlignBottom);
                label->setText(tr(" end"));
                label->setColor(Marker);
            }
        }
        if (g == 0) {
            auto *legend = new QCPLegend;
            rect->insetLayout()->addElement(legend, Qt::AlignTop | Qt::AlignRight);
            legend->setBrush(colors::veil(210));
            legend->setBorderPen(QPen(colors::Border));
            legend->setFillOrder(QCPLayoutGrid::foColumnsFirst);
            legend->setIconSize(16, 8);
            legend->setMargins(QMargins(4, 1, 4, 1));
            commanded->addToLegend(legend);
            predicted->addToLegend(legend);
        }
    }
    m_plot->replot();
}

} // namespace semhap
