// SPDX-License-Identifier: MIT
#include "plotpanel.h"

#include "colors.h"
#include "filedialogs.h"
#include "historycsv.h"
#include "nametable.h"
#include "outputfile.h"
#include "plotcursor.h"
#include "plotlayout.h"
#include "plotseries.h"
#include "routernodetype.h"
#include "spanoverlay.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QMessageBox>
#include <QMouseEvent>
#include <QScrollArea>
#include <QSpinBox>
#include <QTextStream>
#include <QToolButton>
#include <QVBoxLayout>

#include <qcustomplot.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>

namespace semhap {

using namespace plotlayout;

namespace {

// Okabe–Ito: readable for the common colour-vision deficiencies.
using colors::Black;
using colors::Blue;
using colors::Green;
using colors::Orange;
using colors::Purple;
using colors::Sky;
using colors::Vermillion;

constexpr double MinWindow = 2.0;
constexpr double MaxWindow = 120.0;
// Plots need no more than ~33 frames/s, and each frame costs ~10 ms of software drawing.
constexpr qint64 MinReplotMs = 30;

QString number(double value)
{
    return QLocale::c().toString(value, 'g', 10);
}

} // namespace

PlotPanel::PlotPanel(RunHistory &history, QWidget *parent) : QWidget(parent), m_history(history)
{
    m_pauseButton = new QToolButton(this);
    m_pauseButton->setText(tr("Pause"));
    m_pauseButton->setToolTip(tr("Freeze the view; data keep being recorded"));
    m_pauseButton->setCheckable(true);
    m_liveButton = new QToolButton(this);
    m_liveButton->setText(tr("Live"));
    m_liveButton->setToolTip(tr("Follow the newest data again"));
    m_windowSpin = new QSpinBox(this);
    m_windowSpin->setRange(int(MinWindow), int(MaxWindow));
    m_windowSpin->setValue(int(m_windowSeconds));
    m_windowSpin->setSuffix(tr(" s"));
    m_windowSpin->setKeyboardTracking(false);
    m_windowSpin->setToolTip(tr("Width of the live time window"));
    auto *windowLabel = new QLabel(tr("&Window:"), this);
    windowLabel->setBuddy(m_windowSpin);
    auto *csvButton = new QToolButton(this);
    csvButton->setObjectName(QStringLiteral("exportCsv"));
    csvButton->setText(tr("Export CSV…"));
    csvButton->setToolTip(tr("Save the visible time range as CSV"));
    auto *pngButton = new QToolButton(this);
    pngButton->setObjectName(QStringLiteral("exportPng"));
    pngButton->setText(tr("Export PNG…"));
    pngButton->setToolTip(tr("Save the plots as an image"));

    auto *toolbar = new QHBoxLayout;
    toolbar->addWidget(m_pauseButton);
    toolbar->addWidget(m_liveButton);
    toolbar->addSpacing(12);
    toolbar->addWidget(windowLabel);
    toolbar->addWidget(m_windowSpin);
    toolbar->addStretch(1);
    toolbar->addWidget(csvButton);
    toolbar->addWidget(pngButton);

    m_plot = new QCustomPlot(this);
    m_spanOverlay = std::make_unique<SpanOverlay>(m_plot);
    m_plot->setAutoAddPlottableToLegend(false);
    // No "fast polylines": they draw each segment with its own call, slower than one
    // polyline for thin pens (measured with bench_plots).
    m_plot->setPlottingHints(QCP::phCacheLabels);
    m_plot->setNotAntialiasedElements(QCP::aeAll);
    // Nothing draws on the overlay: one paint buffer less to clear and blend per frame.
    m_plot->layer(QStringLiteral("overlay"))->setMode(QCPLayer::lmLogical);
    m_plot->addLayer(QStringLiteral("spans"), m_plot->layer(QStringLiteral("grid")),
                     QCustomPlot::limAbove);
    m_plot->setToolTip(tr("Click to place the cursor; when paused, drag to pan (Shift+drag "
                          "moves the cursor) and use the wheel to zoom"));

    m_cursor = new PlotCursor(m_plot, [this](double t) { return readoutAt(t); });
    connect(m_cursor, &PlotCursor::moved, this, &PlotPanel::requestReplot);

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    layout->addLayout(toolbar);
    // Many devices (both hands, a live rig) want more height than a dock has: rather than
    // squash every rect to a strip, the plot keeps its rects readable and scrolls.
    auto *scroll = new QScrollArea(this);
    scroll->setObjectName(QStringLiteral("plotScroll"));
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidgetResizable(true);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    scroll->setWidget(m_plot);
    layout->addWidget(scroll, 1);

    connect(m_pauseButton, &QToolButton::toggled, this, &PlotPanel::setPaused);
    connect(m_liveButton, &QToolButton::clicked, this, &PlotPanel::goLive);
    connect(m_windowSpin, qOverload<int>(&QSpinBox::valueChanged), this,
            [this](int seconds) { setWindowSeconds(seconds); });
    connect(csvButton, &QToolButton::clicked, this, &PlotPanel::exportCsvDialog);
    connect(pngButton, &QToolButton::clicked, this, &PlotPanel::exportPngDialog);
    // Pixels are known only once the plot is laid out (after a resize, say).
    // The value ranges keep the data under each rect's title and legend, whose pixels a
    // layout sets; the drawing that follows it shows the new ranges.
    connect(m_plot, &QCustomPlot::afterLayout, this, &PlotPanel::fitToLayout);
    connect(m_plot, &QCustomPlot::afterLayout, m_cursor, &PlotCursor::placeReadout);
    connect(m_plot, &QCustomPlot::afterLayout, this, &PlotPanel::layoutSpanLabels);
    connect(m_plot, &QCustomPlot::afterLayout, this, &PlotPanel::keepReadableHeight);
    connect(&m_history, &RunHistory::reset, this, [this] {
        m_cursor->setTime(std::numeric_limits<double>::quiet_NaN());
        rebuild();
        goLive();
    });
    // A router swapped into the running session: other devices and thresholds, same time.
    connect(&m_history, &RunHistory::routerChanged, this, [this] {
        rebuild();
        onUpdated();
    });
    connect(&m_history, &RunHistory::updated, this, &PlotPanel::onUpdated);
    m_replotTimer.setSingleShot(true);
    connect(&m_replotTimer, &QTimer::timeout, this, &PlotPanel::requestReplot);
    m_sinceReplot.start();

    if (m_history.keepSeconds() < m_windowSeconds)
        m_history.setKeepSeconds(m_windowSeconds);
    rebuild();
    onUpdated();
}

PlotPanel::~PlotPanel() = default;

double PlotPanel::cursorTime() const
{
    return m_cursor->time();
}

void PlotPanel::clearPlots()
{
    m_plot->clearItems();
    m_plot->clearGraphs();
    m_plot->plotLayout()->clear();
    delete m_marginGroup;
    m_marginGroup = new QCPMarginGroup(m_plot);
    m_rects.clear();
    m_grippers.clear();
    m_signals.clear();
    m_devices.clear();
    m_spanOverlay->clear();
    m_cursor->clearLines();
    m_levelNames.clear();
    m_titles.clear();
}

/** The grippers worth a plot, right first: with a detector or with contact data. */
static std::vector<Gripper> shownGrippers(const RunHistory &history)
{
    std::vector<Gripper> shown;
    for (Gripper gripper : {Gripper::Right, Gripper::Left}) {
        const GripperThresholds &thresholds = history.thresholds()[size_t(gripper)];
        const auto &frames = history.frames(gripper);
        if (!thresholds.levels.empty() || !thresholds.signalThresholds.empty() ||
            !frames.isEmpty())
            shown.push_back(gripper);
    }
    return shown;
}

bool PlotPanel::needsRebuild() const
{
    const std::vector<Gripper> shown = shownGrippers(m_history);
    if (shown.size() != m_grippers.size())
        return true;
    for (size_t i = 0; i < shown.size(); ++i) {
        if (shown[i] != m_grippers[i]->gripper)
            return true;
    }
    return false;
}

void PlotPanel::rebuild()
{
    clearPlots();
    for (Gripper gripper : shownGrippers(m_history)) {
        addGripper(gripper);
        addSignals(gripper);
    }
    // A device of a hand the scene lacks never plays: its rect would only take room.
    for (int device = 0; device < int(m_history.devices().size()); ++device) {
        if (!m_history.devices()[size_t(device)].idle)
            addDevice(device);
    }
    if (m_rects.empty())
        return;
    QCPAxis *timeAxis = m_rects.back()->axis(QCPAxis::atBottom);
    timeAxis->setTickLabels(true);
    timeAxis->setLabel(tr("pipeline time (s)"));
    for (QCPAxisRect *rect : m_rects)
        m_cursor->addLine(rect);
    updateInteractions();
    // Fewer rects may need less height; keepReadableHeight() sets what they need.
    m_plot->setMinimumHeight(0);
    m_plot->updateGeometry();
}

void PlotPanel::keepReadableHeight()
{
    // What the rects need is known only once a layout has placed their axes and titles,
    // and the scroll area does not ask again by itself: the plot is held at least that
    // high, so rects added while it shows (a hand that comes later) keep their height and
    // the panel scrolls. A new height lays the plot out again, which then asks for the same.
    const QWidget *plot = m_plot; // QCustomPlot hides the hint QWidget makes public
    const int wanted = plot->minimumSizeHint().height();
    if (wanted == m_plot->minimumHeight())
        return;
    m_plot->setMinimumHeight(wanted);
    // The new height comes while the plot is replotting, which drops the replot its resize
    // asks for: the rects stayed laid out for the old height, crushed to a third of their
    // minimum (dish_wiping's seven devices at 1280x800). Lay out again once it is done.
    QMetaObject::invokeMethod(
        this,
        [this] {
            m_plot->setViewport(m_plot->rect());
            m_plot->replot(QCustomPlot::rpQueuedReplot);
        },
        Qt::QueuedConnection);
}

QCPAxisRect *PlotPanel::addRect(const QString &title, int stretch)
{
    auto *rect = new QCPAxisRect(m_plot);
    rect->setMarginGroup(QCP::msLeft | QCP::msRight, m_marginGroup);
    rect->setRangeDrag(Qt::Horizontal);
    rect->setRangeZoom(Qt::Horizontal);
    // Each rect keeps room to read its curves and value labels under its title and legend
    // (stacked, in a narrow dock); past that the panel scrolls. At 40 px a device's rect had
    // room for one value label under its title (dish_wiping's seven devices at 1280x800).
    const int line = QFontMetrics(rect->axis(QCPAxis::atLeft)->tickLabelFont()).height();
    const double lines = stretch >= 5 ? 6.0 : stretch >= 3 ? 5.0 : 4.5;
    rect->setMinimumSize(0, int(std::ceil(lines * line)));
    // Value ticks a step apart that spaceValueTicks() sets from the rect's pixels.
    auto ticker = QSharedPointer<QCPAxisTickerFixed>::create();
    ticker->setScaleStrategy(QCPAxisTickerFixed::ssNone);
    rect->axis(QCPAxis::atLeft)->setTicker(ticker);
    QCPAxis *time = rect->axis(QCPAxis::atBottom);
    time->setTickLabels(false);
    time->setPadding(0);
    connect(time, qOverload<const QCPRange &>(&QCPAxis::rangeChanged), this,
            &PlotPanel::onTimeRangeChanged);
    if (!m_rects.empty())
        time->setRange(m_rects.front()->axis(QCPAxis::atBottom)->range());
    const int row = m_plot->plotLayout()->rowCount();
    m_plot->plotLayout()->addElement(row, 0, rect);
    m_plot->plotLayout()->setRowStretchFactor(row, stretch);
    m_rects.push_back(rect);

    QCPItemText *titleItem = addText(m_plot, rect, title, Qt::AlignLeft | Qt::AlignTop);
    place(titleItem->position, rect, QCPItemPosition::ptAxisRectRatio,
          QCPItemPosition::ptAxisRectRatio, 0.0, 0.0);
    QFont bold = titleItem->font();
    bold.setBold(true);
    titleItem->setFont(bold);
    m_titleHeight =
        QFontMetrics(bold).height() + titleItem->padding().top() + titleItem->padding().bottom();
    titleItem->setBrush(colors::veil(200));
    titleItem->setLayer(QStringLiteral("legend"));
    m_titles[rect] = titleItem;
    return rect;
}

void PlotPanel::addThreshold(QCPAxisRect *rect, const QString &id, const QString &name,
                             double value, const QColor &color, Qt::PenStyle style)
{
    addLevelLine(m_plot, rect, id, value, QPen(color, 1.0, style));
    if (!name.isEmpty()) // a line named in another's label
        m_levelNames.push_back({rect, value, name});
}

/** The gripper's name as shown (the data keep the untranslated one). */
static QString gripperTitle(Gripper gripper)
{
    return gripper == Gripper::Right ? PlotPanel::tr("right gripper")
                                     : PlotPanel::tr("left gripper");
}

void PlotPanel::addGripper(Gripper gripper)
{
    auto plot = std::make_unique<GripperPlot>();
    plot->gripper = gripper;
    const QString id = gripperName(gripper);
    const GripperThresholds &thresholds = m_history.thresholds()[size_t(gripper)];

    plot->forceRect = addRect(tr("%1: force").arg(gripperTitle(gripper)), 5);
    plot->forceRect->axis(QCPAxis::atLeft)->setLabel(tr("F (N)"));
    plot->left = plotlayout::addGraph(m_plot, plot->forceRect, id + QStringLiteral(".left.f"),
                                      tr("left.f (finger)"), Sky, 1.0);
    plot->right = plotlayout::addGraph(m_plot, plot->forceRect, id + QStringLiteral(".right.f"),
                                       tr("right.f (finger)"), Green, 1.0);
    plot->sum = plotlayout::addGraph(m_plot, plot->forceRect, id + QStringLiteral(".F"),
                                     tr("F (sum)"), Black, 1.0);
    addLevels(plot.get(), DetectorLevel::Quantity::Force, thresholds.levels);
    plot->countRect = addRect(tr("%1: contacts").arg(gripperTitle(gripper)), 3);
    plot->countRect->axis(QCPAxis::atLeft)->setLabel(tr("N"));
    plot->count = plotlayout::addGraph(m_plot, plot->countRect, id + QStringLiteral(".N"),
                                       tr("N (contacts)"), Black, 1.0);
    addLevels(plot.get(), DetectorLevel::Quantity::Contacts, thresholds.levels);
    plot->next = m_history.frames(gripper).begin();
    m_grippers.push_back(std::move(plot));
}

void PlotPanel::addLevels(GripperPlot *plot, DetectorLevel::Quantity quantity,
                          const std::vector<DetectorLevel> &levels)
{
    const bool force = quantity == DetectorLevel::Quantity::Force;
    QCPAxisRect *rect = force ? plot->forceRect : plot->countRect;
    double &top = force ? plot->thresholdTop : plot->countTop;
    // Named as the detector's parameters, in every language: the event log and the router
    // files say `grasp` too. The colour says what happens there, the same on every rect.
    const QString format = force ? tr("%1 %2 N") : tr("%1 %2");
    for (const DetectorLevel &level : levels) {
        if (level.quantity != quantity)
            continue;
        const QColor color = level.meaning == DetectorLevel::Meaning::ConfirmationBegins ? Blue
                             : level.meaning == DetectorLevel::Meaning::ExceptionBegins
                                 ? Orange
                                 : Vermillion;
        addThreshold(rect, gripperName(plot->gripper) + QLatin1Char('.') + level.name,
                     format.arg(level.name, number(level.value)), level.value, color);
        top = std::max(top, level.value);
    }
}

void PlotPanel::addSignals(Gripper gripper)
{
    // The built-in quantities are the force and contact rects' already.
    const RouterNodeType *signalType = routerNodeType(QStringLiteral("signal"));
    const ParamSpec *quantitySpec =
        signalType ? signalType->param(QStringLiteral("quantity")) : nullptr;
    const QString hand = gripperName(gripper);
    for (const ThresholdLevels &levels :
         m_history.thresholds()[size_t(gripper)].signalThresholds) {
        if (quantitySpec && quantitySpec->choices.contains(levels.quantity))
            continue;
        auto found = std::find_if(m_signals.begin(), m_signals.end(), [&](const auto &p) {
            return p->gripper == gripper && p->quantity == levels.quantity;
        });
        if (found == m_signals.end()) {
            auto plot = std::make_unique<SignalPlot>();
            plot->gripper = gripper;
            plot->quantity = levels.quantity;
            plot->id = signalNames().find(levels.quantity);
            plot->rect = addRect(tr("%1: %2").arg(gripperTitle(gripper), levels.quantity), 3);
            plot->rect->axis(QCPAxis::atLeft)->setLabel(levels.quantity);
            plot->graph =
                plotlayout::addGraph(m_plot, plot->rect, hand + QLatin1Char('.') + levels.quantity,
                                     levels.quantity, Black, 1.0);
            plot->next = m_history.frames(gripper).begin();
            m_signals.push_back(std::move(plot));
            found = m_signals.end() - 1;
        }
        SignalPlot &plot = **found;
        plot.nodes.append(levels.node);
        // A derivative's levels are in other units than the signal: its spans only.
        if (!levels.levelsInSignalUnits)
            continue;
        const QColor color = levels.category == Category::Confirmation ? Blue : Orange;
        const QString id = plot.graph->objectName() + QLatin1Char('/') + levels.node;
        const auto line = [&](const QString &key, const QString &name, double value,
                              Qt::PenStyle style) {
            addThreshold(plot.rect, id + QLatin1Char('.') + key, name, value, color, style);
            plot.levelLow = plot.hasLevels ? std::min(plot.levelLow, value) : value;
            plot.levelHigh = plot.hasLevels ? std::max(plot.levelHigh, value) : value;
            plot.hasLevels = true;
        };
        // Begin dashed, end (where it differs: hysteresis) dotted; a range as two lines. The
        // end is named in its begin's label: the two lie too close for a label each.
        const auto name = [&](double begin, double end) {
            return begin == end
                       ? tr("%1 %2").arg(levels.node, number(begin))
                       : tr("%1 %2 (end %3)").arg(levels.node, number(begin), number(end));
        };
        line(QStringLiteral("begin"), name(levels.begin, levels.end), levels.begin, Qt::DashLine);
        if (levels.range)
            line(QStringLiteral("beginHigh"), name(levels.beginHigh, levels.endHigh),
                 levels.beginHigh, Qt::DashLine);
        if (levels.end != levels.begin)
            line(QStringLiteral("end"), QString(), levels.end, Qt::DotLine);
        if (levels.range && levels.endHigh != levels.beginHigh)
            line(QStringLiteral("endHigh"), QString(), levels.endHigh, Qt::DotLine);
    }
}

void PlotPanel::addDevice(int device)
{
    const RunDevice &info = m_history.devices()[size_t(device)];
    auto plot = std::make_unique<DevicePlot>();
    plot->device = device;
    const QString title =
        info.model.isEmpty() ? info.name : tr("%1 (%2)").arg(info.name, info.model);
    plot->rect = addRect(title, 2);
    plot->rect->axis(QCPAxis::atLeft)->setLabel(tr("output"));
    for (int channel = 0; channel < int(info.channels.size()); ++channel) {
        const QString &name = info.channels[channel];
        const QColor color = colors::series(channel);
        // Past the palette, dashes keep channels apart.
        QCPGraph *graph = plotlayout::addGraph(
            m_plot, plot->rect, info.name + QLatin1Char('.') + name, name, color, 1.0);
        if (channel >= colors::SeriesCount) {
            QPen pen = graph->pen();
            pen.setStyle(Qt::DashLine);
            graph->setPen(pen);
        }
        plot->graphs.push_back(graph);
    }
    plot->next = m_history.deviceFrames(device).begin();
    plot->rewinds = m_history.deviceFrames(device).rewinds();
    m_devices.push_back(std::move(plot));
}

void PlotPanel::onUpdated()
{
    if (needsRebuild())
        rebuild();
    appendNew();
    syncSpans();
    if (m_paused && !m_rects.empty()) {
        const QCPRange range = m_rects.front()->axis(QCPAxis::atBottom)->range();
        setTimeRange(range.lower, range.upper);
    } else {
        const double now = m_history.now();
        setTimeRange(now - m_windowSeconds, now);
    }
    requestReplot();
}

void PlotPanel::requestReplot()
{
    if (m_replotTimer.isActive())
        return;
    const qint64 wait = MinReplotMs - m_sinceReplot.elapsed();
    if (wait > 0) {
        m_replotTimer.start(int(wait));
        return;
    }
    m_sinceReplot.restart();
    m_plot->replot(QCustomPlot::rpQueuedReplot);
}

void PlotPanel::appendNew()
{
    for (auto &plot : m_grippers)
        plot->appendNew(m_history);
    for (auto &plot : m_signals)
        plot->appendNew(m_history);
    for (auto &plot : m_devices)
        plot->appendNew(m_history);
    // The history forgot what is older; so do the graphs.
    const double oldest = m_history.now() - m_history.keepSeconds();
    for (int i = 0; i < m_plot->graphCount(); ++i)
        m_plot->graph(i)->data()->removeBefore(oldest);
}

void PlotPanel::syncSpans()
{
    m_spanOverlay->sync(m_history.spans(), [this](const MessageSpan &span, bool *labelled) {
        // On its gripper's force and contact rects, and on the plots of the signals its
        // threshold node reads.
        std::vector<QCPAxisRect *> rects;
        const auto plot = std::find_if(m_grippers.begin(), m_grippers.end(),
                                       [&](const auto &p) { return p->gripper == span.gripper; });
        if (plot != m_grippers.end())
            rects = {(*plot)->forceRect, (*plot)->countRect};
        for (const auto &signal : m_signals) {
            if (span.detector == DetectorKind::Threshold && signal->nodes.contains(span.node))
                rects.push_back(signal->rect);
        }
        // Only a force rect's labels are laid out.
        *labelled = plot != m_grippers.end();
        return rects;
    });
}

void PlotPanel::layoutSpanLabels()
{
    for (const auto &plot : m_grippers)
        m_spanOverlay->layoutLabels(plot->gripper, plot->forceRect);
}

void PlotPanel::fitToLayout()
{
    for (QCPAxisRect *rect : m_rects) {
        if (placeLegend(rect, m_titles[rect], m_titleHeight))
            requestReplot(); // the inset is laid out at the next replot
    }
    // The layout has set up the axes' ticks for the old ranges: they are set up again for
    // the drawing that follows (the margins follow at the next replot).
    if (!fitValueAxes())
        return;
    for (QCPAxisRect *rect : m_rects)
        rect->update(QCPLayoutElement::upPreparation);
}

bool PlotPanel::fitValueAxes()
{
    if (m_rects.empty())
        return false;
    bool changed = false;
    const QCPRange visible = m_rects.front()->axis(QCPAxis::atBottom)->range();
    const auto visibleTop = [&visible](QCPGraph *graph, double floor) {
        bool found = false;
        const QCPRange range = graph->getValueRange(found, QCP::sdBoth, visible);
        return found ? std::max(floor, range.upper) : floor;
    };
    for (auto &plot : m_grippers) {
        const double force = visibleTop(plot->sum, std::max(1.0, plot->thresholdTop));
        // Headroom above the data for the span labels too.
        changed |=
            setValueRange(plot->forceRect, 0.0,
                          upperUnderHeader(plot->forceRect, m_titleHeight, 0.0, force, 0.3));
        const double count = visibleTop(plot->count, std::max(4.0, plot->countTop));
        changed |= setValueRange(
            plot->countRect, 0.0,
            std::ceil(upperUnderHeader(plot->countRect, m_titleHeight, 0.0, count, 0.1)));
    }
    for (auto &plot : m_signals) {
        // The data in view and the levels, whatever their sign and scale.
        bool found = false;
        const QCPRange range = plot->graph->getValueRange(found, QCP::sdBoth, visible);
        double low = found ? range.lower : plot->levelLow;
        double high = found ? range.upper : plot->levelHigh;
        if (plot->hasLevels) {
            low = std::min(low, plot->levelLow);
            high = std::max(high, plot->levelHigh);
        }
        if (!(high > low)) {
            // A flat signal: around its value, at its scale (a millimetre, a newton).
            const double pad = low == 0.0 ? 1.0 : std::abs(low) / 2;
            low -= pad;
            high += pad;
        }
        const double lower = low - 0.08 * (high - low);
        changed |= setValueRange(plot->rect, lower,
                                 upperUnderHeader(plot->rect, m_titleHeight, lower, high, 0.1));
    }
    for (auto &plot : m_devices) {
        // Normalised outputs keep a fixed 0..1 scale so devices compare at a glance; a
        // model with a wider range widens it (tracked as data come, not searched per frame:
        // sixteen channels at 1 kHz would cost more than drawing them).
        const double lower = plot->low - 0.06 * (plot->high - plot->low);
        changed |=
            setValueRange(plot->rect, lower,
                          upperUnderHeader(plot->rect, m_titleHeight, lower, plot->high, 0.06));
    }
    for (QCPAxisRect *rect : m_rects) {
        changed |= spaceValueTicks(rect);
        changed |= nameLevels(rect, m_levelNames);
    }
    return changed;
}

void PlotPanel::setTimeRange(double lower, double upper)
{
    m_syncingRange = true;
    for (QCPAxisRect *rect : m_rects)
        rect->axis(QCPAxis::atBottom)->setRange(lower, upper);
    m_syncingRange = false;
    fitValueAxes();
    m_cursor->refresh();
}

void PlotPanel::onTimeRangeChanged(const QCPRange &range)
{
    if (m_syncingRange)
        return;
    setTimeRange(range.lower, range.upper);
}

QString PlotPanel::readoutAt(double t) const
{
    QStringList lines;
    lines << tr("t = %1 s").arg(QLocale().toString(t, 'f', 3));
    for (const auto &plot : m_grippers) {
        const ContactFrame *frame = m_history.frames(plot->gripper).latestAt(t);
        if (!frame)
            continue;
        lines << tr("%1: F %2 N (left %3, right %4), N %5")
                     .arg(gripperTitle(plot->gripper))
                     .arg(QLocale().toString(frame->totalForce(), 'f', 2))
                     .arg(QLocale().toString(frame->left.f, 'f', 2))
                     .arg(QLocale().toString(frame->right.f, 'f', 2))
                     .arg(frame->totalContacts());
    }
    for (const auto &plot : m_signals) {
        const ContactFrame *frame = m_history.frames(plot->gripper).latestAt(t);
        const double *value = frame ? frame->signalValues.find(plot->id) : nullptr;
        if (value)
            lines << tr("%1: %2 %3")
                         .arg(gripperTitle(plot->gripper), plot->quantity,
                              QLocale().toString(*value, 'g', 4));
    }
    for (const auto &plot : m_devices) {
        const DeviceFrame *frame = m_history.deviceFrames(plot->device).latestAt(t);
        if (!frame)
            continue;
        const RunDevice &info = m_history.devices()[size_t(plot->device)];
        QStringList values;
        const int n = std::min(frame->channelCount, int(info.channels.size()));
        for (int c = 0; c < n; ++c)
            values << tr("%1 %2").arg(info.channels[c],
                                      QLocale().toString(frame->values[size_t(c)], 'f', 2));
        lines << tr("%1: %2").arg(info.name, values.join(QStringLiteral(", ")));
    }
    return lines.join(QLatin1Char('\n'));
}

void PlotPanel::updateInteractions()
{
    m_cursor->setPaused(m_paused);
    m_plot->setInteractions(m_paused ? QCP::iRangeDrag | QCP::iRangeZoom : QCP::Interactions());
}

void PlotPanel::setWindowSeconds(double seconds)
{
    m_windowSeconds = std::clamp(seconds, MinWindow, MaxWindow);
    {
        const QSignalBlocker blocker(m_windowSpin);
        m_windowSpin->setValue(int(std::lround(m_windowSeconds)));
    }
    if (m_history.keepSeconds() < m_windowSeconds)
        m_history.setKeepSeconds(m_windowSeconds);
    double upper = m_history.now();
    if (m_paused && !m_rects.empty())
        upper = m_rects.front()->axis(QCPAxis::atBottom)->range().upper;
    setTimeRange(upper - m_windowSeconds, upper);
    requestReplot();
}

void PlotPanel::setPaused(bool paused)
{
    m_paused = paused;
    {
        const QSignalBlocker blocker(m_pauseButton);
        m_pauseButton->setChecked(paused);
    }
    updateInteractions();
    if (!paused) {
        const double now = m_history.now();
        setTimeRange(now - m_windowSeconds, now);
    }
    requestReplot();
}

void PlotPanel::goLive()
{
    setPaused(false);
}

void PlotPanel::setCursorTime(double t)
{
    setPaused(true);
    if (!m_rects.empty()) {
        const QCPRange range = m_rects.front()->axis(QCPAxis::atBottom)->range();
        if (!range.contains(t))
            setTimeRange(t - range.size() / 2, t + range.size() / 2);
    }
    m_cursor->setTime(t);
    requestReplot();
}

bool PlotPanel::exportCsv(const QString &path, QString *error) const
{
    const QCPRange visible = m_rects.empty()
                                 ? QCPRange(m_history.now() - m_windowSeconds, m_history.now())
                                 : m_rects.front()->axis(QCPAxis::atBottom)->range();
    // What the plots show, as the history's CSV holds it.
    HistoryCsv::Columns columns;
    for (const auto &plot : m_grippers)
        columns.grippers.push_back(plot->gripper);
    for (const auto &plot : m_signals)
        columns.frameSignals.push_back({plot->gripper, plot->id, plot->graph->objectName()});
    for (const auto &plot : m_devices)
        columns.devices.push_back(plot->device);
    LoadError failure;
    if (!OutputFile::write(
            path, HistoryCsv::write(m_history, columns, visible.lower, visible.upper), &failure)) {
        if (error)
            *error = failure.toString();
        return false;
    }
    return true;
}

bool PlotPanel::exportPng(const QString &path, QString *error)
{
    if (m_plot->savePng(path))
        return true;
    if (error)
        *error = tr("Cannot write %1").arg(path);
    return false;
}

void PlotPanel::exportCsvDialog()
{
    const QString path = FileDialogs::saveFile(
        this, FileKind::PlotExport, tr("Export Plots as CSV"), QString(), tr("CSV files (*.csv)"));
    QString error;
    if (!path.isEmpty() && !exportCsv(path, &error))
        QMessageBox::warning(this, tr("Export CSV"), error);
}

void PlotPanel::exportPngDialog()
{
    const QString path =
        FileDialogs::saveFile(this, FileKind::PlotExport, tr("Export Plots as PNG"), QString(),
                              tr("PNG images (*.png)"));
    QString error;
    if (!path.isEmpty() && !exportPng(path, &error))
        QMessageBox::warning(this, tr("Export PNG"), error);
}

PanelDock PlotPanel::dock()
{
    return {QStringLiteral("plotsDock"), tr("Plots"), PanelDock::Side::Right, QString()};
}

} // namespace semhap
