// SPDX-License-Identifier: MIT
#include "plotpanel.h"

#include "colors.h"
#include "filedialogs.h"
#include "historycsv.h"
#include "nametable.h"
#include "outputfile.h"
#include "routernodetype.h"

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

QString number(double value)
{
    return QLocale::c().toString(value, 'g', 10);
}

} // namespace

struct PlotPanel::GripperPlot
{
    Gripper gripper = Gripper::Right;
    QCPAxisRect *forceRect = nullptr;
    QCPAxisRect *countRect = nullptr;
    QCPGraph *left = nullptr;
    QCPGraph *right = nullptr;
    QCPGraph *sum = nullptr;
    QCPGraph *count = nullptr;
    double thresholdTop = 0.0; ///< the highest force threshold, kept in view
    double countTop = 0.0;     ///< the highest count threshold, kept in view
    qint64 next = 0;           ///< the history index not yet plotted
};

/** A frame signal that threshold nodes read, with their levels. */
struct PlotPanel::SignalPlot
{
    Gripper gripper = Gripper::Right;
    QString quantity; ///< the signal's name (`plug.angle`)
    int id = -1;      ///< its signalNames() id
    QCPAxisRect *rect = nullptr;
    QCPGraph *graph = nullptr;
    QStringList nodes; ///< the threshold nodes reading it: their spans are shaded here
    bool hasLevels = false;
    double levelLow = 0.0; ///< the levels drawn, kept in view
    double levelHigh = 0.0;
    bool gap = true; ///< the last point plotted was a frame without the signal (or none)
    qint64 next = 0;
};

struct PlotPanel::DevicePlot
{
    int device = 0;
    QCPAxisRect *rect = nullptr;
    std::vector<QCPGraph *> graphs;
    qint64 next = 0;
    int rewinds = 0;  ///< the series' rewinds() when it was read
    double low = 0.0; ///< the value range seen since the run started, at least 0..1
    double high = 1.0;
};

/** The items showing one MessageSpan on its gripper's two rects. */
struct PlotPanel::SpanView
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

PlotPanel::PlotPanel(RunHistory &history, QWidget *parent)
    : QWidget(parent), m_history(history), m_cursorTime(std::numeric_limits<double>::quiet_NaN())
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

    m_readout = new QLabel(m_plot);
    m_readout->setObjectName(QStringLiteral("cursorReadout"));
    m_readout->setStyleSheet(
        QStringLiteral("QLabel { background: rgba(255, 255, 255, 225); border: 1px solid #888;"
                       " padding: 3px; color: black; }"));
    m_readout->setAttribute(Qt::WA_TransparentForMouseEvents);
    m_readout->hide();

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
    connect(m_plot, &QCustomPlot::mousePress, this, &PlotPanel::onMousePress);
    connect(m_plot, &QCustomPlot::mouseMove, this, &PlotPanel::onMouseMove);
    connect(m_plot, &QCustomPlot::mouseRelease, this, &PlotPanel::onMouseRelease);
    // Pixels are known only once the plot is laid out (after a resize, say).
    // The value ranges keep the data under each rect's title and legend, whose pixels a
    // layout sets; the drawing that follows it shows the new ranges.
    connect(m_plot, &QCustomPlot::afterLayout, this, &PlotPanel::fitToLayout);
    connect(m_plot, &QCustomPlot::afterLayout, this, &PlotPanel::placeReadout);
    connect(m_plot, &QCustomPlot::afterLayout, this, &PlotPanel::layoutSpanLabels);
    connect(m_plot, &QCustomPlot::afterLayout, this, &PlotPanel::keepReadableHeight);
    connect(&m_history, &RunHistory::reset, this, [this] {
        m_cursorTime = std::numeric_limits<double>::quiet_NaN();
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
    m_spans.clear();
    m_cursorLines.clear();
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
    QPen cursorPen(colors::Text);
    cursorPen.setWidthF(1.5);
    for (QCPAxisRect *rect : m_rects) {
        QCPItemStraightLine *line = addTimeLine(m_plot, rect, 0.0, cursorPen);
        line->setObjectName(QStringLiteral("cursor"));
        line->setVisible(false);
        m_cursorLines.push_back(line);
    }
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

QCPGraph *PlotPanel::addGraph(QCPAxisRect *rect, const QString &id, const QString &name,
                              const QColor &color, double width)
{
    QCPGraph *graph = m_plot->addGraph(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
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

void PlotPanel::addThreshold(QCPAxisRect *rect, const QString &id, const QString &name,
                             double value, const QColor &color, Qt::PenStyle style)
{
    QPen pen(color, 1.0, style);
    auto *line = new QCPItemStraightLine(m_plot);
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
    if (!name.isEmpty()) // a line named in another's label
        m_levelNames.push_back({rect, value, name});
}

bool PlotPanel::nameLevels(QCPAxisRect *rect)
{
    QCPAxis *names = rect->axis(QCPAxis::atRight);
    auto ticker = names->ticker().dynamicCast<QCPAxisTickerText>();
    if (!ticker)
        return false;
    std::vector<const LevelName *> levels;
    for (const LevelName &level : m_levelNames) {
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
    plot->left =
        addGraph(plot->forceRect, id + QStringLiteral(".left.f"), tr("left.f (finger)"), Sky, 1.0);
    plot->right = addGraph(plot->forceRect, id + QStringLiteral(".right.f"),
                           tr("right.f (finger)"), Green, 1.0);
    plot->sum = addGraph(plot->forceRect, id + QStringLiteral(".F"), tr("F (sum)"), Black, 1.0);
    addLevels(plot.get(), DetectorLevel::Quantity::Force, thresholds.levels);
    plot->countRect = addRect(tr("%1: contacts").arg(gripperTitle(gripper)), 3);
    plot->countRect->axis(QCPAxis::atLeft)->setLabel(tr("N"));
    plot->count =
        addGraph(plot->countRect, id + QStringLiteral(".N"), tr("N (contacts)"), Black, 1.0);
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
            plot->graph = addGraph(plot->rect, hand + QLatin1Char('.') + levels.quantity,
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
        QCPGraph *graph =
            addGraph(plot->rect, info.name + QLatin1Char('.') + name, name, color, 1.0);
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
    QVector<QCPGraphData> left, right, sum, count;
    for (auto &plot : m_grippers) {
        const RunSeries<ContactFrame> &frames = m_history.frames(plot->gripper);
        left.clear();
        right.clear();
        sum.clear();
        count.clear();
        for (qint64 i = std::max(plot->next, frames.begin()); i < frames.end(); ++i) {
            const ContactFrame &frame = frames.at(i);
            left.append(QCPGraphData(frame.t, frame.left.f));
            right.append(QCPGraphData(frame.t, frame.right.f));
            sum.append(QCPGraphData(frame.t, frame.totalForce()));
            count.append(QCPGraphData(frame.t, frame.totalContacts()));
        }
        plot->next = frames.end();
        plot->left->data()->add(left, true);
        plot->right->data()->add(right, true);
        plot->sum->data()->add(sum, true);
        plot->count->data()->add(count, true);
    }
    QVector<QCPGraphData> values;
    for (auto &plot : m_signals) {
        const RunSeries<ContactFrame> &frames = m_history.frames(plot->gripper);
        values.clear();
        for (qint64 i = std::max(plot->next, frames.begin()); i < frames.end(); ++i) {
            const ContactFrame &frame = frames.at(i);
            const double *value = frame.signalValues.find(plot->id);
            // A frame without the signal breaks the curve (a NaN is a gap).
            if (value || !plot->gap)
                values.append(QCPGraphData(
                    frame.t, value ? *value : std::numeric_limits<double>::quiet_NaN()));
            plot->gap = !value;
        }
        plot->next = frames.end();
        plot->graph->data()->add(values, true);
    }
    std::vector<QVector<QCPGraphData>> channels;
    for (auto &plot : m_devices) {
        const RunSeries<DeviceFrame> &frames = m_history.deviceFrames(plot->device);
        if (frames.rewinds() != plot->rewinds) {
            // The run went on where an audition had drawn ahead of it: draw it again.
            plot->rewinds = frames.rewinds();
            plot->next = frames.begin();
            for (QCPGraph *graph : plot->graphs)
                graph->data()->clear();
        }
        channels.assign(plot->graphs.size(), QVector<QCPGraphData>());
        for (qint64 i = std::max(plot->next, frames.begin()); i < frames.end(); ++i) {
            const DeviceFrame &frame = frames.at(i);
            const size_t n = std::min(channels.size(), size_t(frame.channelCount));
            for (size_t c = 0; c < n; ++c) {
                channels[c].append(QCPGraphData(frame.t, frame.values[c]));
                plot->low = std::min(plot->low, frame.values[c]);
                plot->high = std::max(plot->high, frame.values[c]);
            }
        }
        plot->next = frames.end();
        for (size_t c = 0; c < channels.size(); ++c)
            plot->graphs[c]->data()->add(channels[c], true);
    }
    // The history forgot what is older; so do the graphs.
    const double oldest = m_history.now() - m_history.keepSeconds();
    for (int i = 0; i < m_plot->graphCount(); ++i)
        m_plot->graph(i)->data()->removeBefore(oldest);
}

PlotPanel::SpanView PlotPanel::makeSpanView(const MessageSpan &span,
                                            const std::vector<QCPAxisRect *> &rects,
                                            QCPAxisRect *labelRect)
{
    SpanView view;
    view.gripper = span.gripper;
    view.node = span.node;
    view.message = span.message;
    view.begin = span.begin;
    // Confirmations blue, exceptions orange; slip hatched vermillion so it never reads as
    // a break even without colour.
    QColor color = Blue;
    QBrush brush;
    if (span.category == Category::Exception)
        color = span.message == Message::Slip ? Vermillion : Orange;
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
    // (layoutSpanLabels() places it).
    view.row = int(span.message) + (threshold ? 3 : 0);
    place(view.label->position, labelRect, QCPItemPosition::ptPlotCoords,
          QCPItemPosition::ptAxisRectRatio, span.begin, 0.0);
    return view;
}

void PlotPanel::placeSpan(const SpanView &view, const MessageSpan &span)
{
    for (size_t i = 0; i < view.shades.size(); ++i) {
        view.shades[i]->bottomRight->setCoords(span.end, 1.0);
        moveTimeLine(view.endLines[i], span.end);
        view.endLines[i]->setVisible(!span.active);
    }
}

void PlotPanel::syncSpans()
{
    for (SpanView &view : m_spans)
        view.seen = false;
    for (const MessageSpan &span : m_history.spans()) {
        auto view = std::find_if(m_spans.begin(), m_spans.end(),
                                 [&](const SpanView &v) { return v.shows(span); });
        if (view == m_spans.end()) {
            // On its gripper's force and contact rects, and on the plots of the signals its
            // threshold node reads.
            std::vector<QCPAxisRect *> rects;
            const auto plot =
                std::find_if(m_grippers.begin(), m_grippers.end(),
                             [&](const auto &p) { return p->gripper == span.gripper; });
            if (plot != m_grippers.end())
                rects = {(*plot)->forceRect, (*plot)->countRect};
            for (const auto &signal : m_signals) {
                if (span.detector == DetectorKind::Threshold && signal->nodes.contains(span.node))
                    rects.push_back(signal->rect);
            }
            if (rects.empty())
                continue;
            m_spans.push_back(makeSpanView(span, rects, rects.front()));
            view = m_spans.end() - 1;
            // Only a force rect's labels are laid out (layoutSpanLabels).
            view->label->setVisible(plot != m_grippers.end());
        }
        view->seen = true;
        view->end = span.end;
        view->active = span.active;
        placeSpan(*view, span);
    }
    // Spans the history forgot.
    const auto gone =
        std::partition(m_spans.begin(), m_spans.end(), [](const SpanView &v) { return v.seen; });
    for (auto it = gone; it != m_spans.end(); ++it) {
        for (size_t i = 0; i < it->shades.size(); ++i) {
            m_plot->removeItem(it->shades[i]);
            m_plot->removeItem(it->beginLines[i]);
            m_plot->removeItem(it->endLines[i]);
        }
        m_plot->removeItem(it->label);
    }
    m_spans.erase(gone, m_spans.end());
}

/** Sets the rect's value range on both sides, so the threshold names stay at their lines. */
static bool setValueRange(QCPAxisRect *rect, double lower, double upper)
{
    if (rect->axis(QCPAxis::atLeft)->range() == QCPRange(lower, upper))
        return false;
    rect->axis(QCPAxis::atLeft)->setRange(lower, upper);
    rect->axis(QCPAxis::atRight)->setRange(lower, upper);
    return true;
}

double PlotPanel::upperUnderHeader(QCPAxisRect *rect, double lower, double top,
                                   double headroom) const
{
    // The title and the legend sit over the top of the rect: the range reaches so far above
    // the data that its top runs under them, never behind (a band's 1.0 went behind both).
    QCPLegend *legend = legendOf(rect);
    const int legendHeight = legend ? legend->outerRect().height() : 0;
    const bool stacked =
        legend && rect->insetLayout()->insetPlacement(0) == QCPLayoutInset::ipFree;
    const int header =
        (stacked ? m_titleHeight + legendHeight : std::max(m_titleHeight, legendHeight)) + 2;
    const int height = rect->rect().height();
    const double span = top - lower;
    double upper = top + span * headroom;
    if (height > header) // laid out
        upper = std::max(upper, lower + span * height / (height - header));
    return upper;
}

bool PlotPanel::spaceValueTicks(QCPAxisRect *rect)
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

void PlotPanel::placeLegend(QCPAxisRect *rect)
{
    QCPLegend *legend = legendOf(rect);
    const auto title = m_titles.find(rect);
    const int width = rect->rect().width();
    if (!legend || title == m_titles.end() || width <= 0)
        return;
    // Beside the title while both fit the rect's width; else under it, at the right (in a
    // narrow dock the legend of a signal's rect hid its title, "rechter Greifer: Kraft").
    const QCPItemText *text = title->second;
    const int titleWidth = QFontMetrics(text->font()).horizontalAdvance(text->text()) +
                           text->padding().left() + text->padding().right();
    const QSize size = legend->minimumOuterSizeHint();
    QCPLayoutInset *inset = rect->insetLayout();
    const bool beside = titleWidth + 8 + size.width() <= width;
    const auto placement = beside ? QCPLayoutInset::ipBorderAligned : QCPLayoutInset::ipFree;
    const QRectF under(std::max(0.0, 1.0 - double(size.width()) / width),
                       double(m_titleHeight) / std::max(1, rect->rect().height()), 0.0, 0.0);
    if (inset->insetPlacement(0) == placement && (beside || inset->insetRect(0) == under))
        return;
    inset->setInsetPlacement(0, placement);
    if (!beside)
        inset->setInsetRect(0, under);
    requestReplot(); // the inset is laid out at the next replot
}

void PlotPanel::fitToLayout()
{
    for (QCPAxisRect *rect : m_rects)
        placeLegend(rect);
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
        changed |= setValueRange(plot->forceRect, 0.0,
                                 upperUnderHeader(plot->forceRect, 0.0, force, 0.3));
        const double count = visibleTop(plot->count, std::max(4.0, plot->countTop));
        changed |= setValueRange(plot->countRect, 0.0,
                                 std::ceil(upperUnderHeader(plot->countRect, 0.0, count, 0.1)));
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
        changed |=
            setValueRange(plot->rect, lower, upperUnderHeader(plot->rect, lower, high, 0.1));
    }
    for (auto &plot : m_devices) {
        // Normalised outputs keep a fixed 0..1 scale so devices compare at a glance; a
        // model with a wider range widens it (tracked as data come, not searched per frame:
        // sixteen channels at 1 kHz would cost more than drawing them).
        const double lower = plot->low - 0.06 * (plot->high - plot->low);
        changed |= setValueRange(plot->rect, lower,
                                 upperUnderHeader(plot->rect, lower, plot->high, 0.06));
    }
    for (QCPAxisRect *rect : m_rects) {
        changed |= spaceValueTicks(rect);
        changed |= nameLevels(rect);
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
    updateCursor();
}

void PlotPanel::layoutSpanLabels()
{
    for (const auto &plot : m_grippers) {
        const QRect area = plot->forceRect->rect();
        const QCPAxis *time = plot->forceRect->axis(QCPAxis::atBottom);
        const QCPRange range = time->range();
        // A span's label shows while the span does: from its begin, or from the view's left
        // edge while it goes on; an ended span out of view takes it along.
        std::vector<SpanView *> shown;
        for (SpanView &view : m_spans) {
            if (view.gripper != plot->gripper)
                continue;
            view.label->setVisible(false);
            const bool inView =
                view.begin <= range.upper && (view.active || view.end >= range.lower);
            if (inView && area.height() > 0)
                shown.push_back(&view);
        }
        std::stable_sort(shown.begin(), shown.end(),
                         [](const SpanView *a, const SpanView *b) { return a->begin < b->begin; });
        // In rows as tall as a label under the rect's title, in the upper part where the
        // force curves leave room: each kind of message on its own row, so the labels read
        // as lanes; a label that would cover another waits until it would not (its span is
        // shaded anyway). A rect too short for a kind's row lends it the first free row. The
        // legend's box is taken (under the title in a narrow rect).
        std::vector<QRectF> taken;
        if (const QCPLegend *legend = legendOf(plot->forceRect))
            taken.push_back(QRectF(legend->outerRect()));
        for (SpanView *view : shown) {
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
}

void PlotPanel::onTimeRangeChanged(const QCPRange &range)
{
    if (m_syncingRange)
        return;
    setTimeRange(range.lower, range.upper);
}

void PlotPanel::updateCursor()
{
    const bool placed = !std::isnan(m_cursorTime);
    for (QCPItemStraightLine *line : m_cursorLines) {
        line->setVisible(placed);
        if (placed)
            moveTimeLine(line, m_cursorTime);
    }
    if (!placed || m_rects.empty()) {
        m_readout->hide();
        return;
    }
    const double t = m_cursorTime;
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
    m_readout->setText(lines.join(QLatin1Char('\n')));
    m_readout->adjustSize();
    placeReadout();
}

void PlotPanel::placeReadout()
{
    if (std::isnan(m_cursorTime) || m_rects.empty())
        return;
    const double t = m_cursorTime;
    QCPAxis *time = m_rects.front()->axis(QCPAxis::atBottom);
    const int x = int(time->coordToPixel(t));
    // Right of the cursor, or left of it where it would cover the threshold names.
    int left = x + 10;
    if (left + m_readout->width() > m_rects.front()->right())
        left = x - 10 - m_readout->width();
    m_readout->move(std::max(0, left), m_rects.front()->top() + 2);
    m_readout->setVisible(time->range().contains(t));
}

void PlotPanel::onMousePress(QMouseEvent *event)
{
    if (event->button() != Qt::LeftButton || m_rects.empty())
        return;
    const bool inside = std::any_of(m_rects.begin(), m_rects.end(), [event](QCPAxisRect *r) {
        return r->rect().contains(event->pos());
    });
    if (!inside)
        return;
    // Live, a drag can only mean the cursor; paused, a plain drag pans and Shift picks the
    // cursor. The plot sees the press after this signal, so switching drag off works now.
    if (!m_paused || event->modifiers().testFlag(Qt::ShiftModifier)) {
        m_draggingCursor = true;
        m_plot->setInteraction(QCP::iRangeDrag, false);
    }
    placeCursorAt(event->pos().x());
}

void PlotPanel::onMouseMove(QMouseEvent *event)
{
    if (m_draggingCursor && event->buttons().testFlag(Qt::LeftButton))
        placeCursorAt(event->pos().x());
}

void PlotPanel::onMouseRelease(QMouseEvent *)
{
    if (!m_draggingCursor)
        return;
    m_draggingCursor = false;
    updateInteractions();
}

void PlotPanel::placeCursorAt(int pixelX)
{
    m_cursorTime = m_rects.front()->axis(QCPAxis::atBottom)->pixelToCoord(pixelX);
    updateCursor();
    requestReplot();
}

void PlotPanel::updateInteractions()
{
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
    m_cursorTime = t;
    updateCursor();
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

} // namespace semhap
