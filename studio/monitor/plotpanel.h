// SPDX-License-Identifier: MIT
#pragma once

#include "runhistory.h"

#include <QElapsedTimer>
#include <QTimer>
#include <QWidget>

#include <map>
#include <memory>
#include <vector>

class QCPAbstractItem;
class QCPAxisRect;
class QCPGraph;
class QCPItemStraightLine;
class QCPItemText;
class QCPMarginGroup;
class QCPRange;
class QCustomPlot;
class QLabel;
class QMouseEvent;
class QSpinBox;
class QToolButton;

namespace semhap {

/**
 * The studio's live plots: per gripper its fingertip forces and contact count with the
 * detectors' thresholds and the messages as shaded spans, each frame signal a threshold
 * node reads with its levels and that node's spans, and per device its channel outputs, on
 * one shared scrolling time axis. It reads only what is new in a RunHistory
 * on each `updated()`, and can pause, inspect a moment with a cursor and export what it
 * shows.
 */
class PlotPanel : public QWidget
{
    Q_OBJECT

public:
    /** Shows `history`, which must outlive the panel. */
    explicit PlotPanel(RunHistory &history, QWidget *parent = nullptr);
    ~PlotPanel() override;

    /** The live view's width in pipeline seconds (2–120); the history keeps at least it. */
    double windowSeconds() const { return m_windowSeconds; }
    /** True while the view is frozen for inspection. */
    bool isPaused() const { return m_paused; }
    /** The cursor's time, or NaN while there is none. */
    double cursorTime() const { return m_cursorTime; }

    /**
     * Writes the visible time range as CSV (`t`, then one column per plotted series) so a
     * moment seen live can be analysed elsewhere; false with `error` when it cannot write.
     */
    bool exportCsv(const QString &path, QString *error) const;
    /** Saves the plots as they are shown, for reports. */
    bool exportPng(const QString &path, QString *error);

public slots:
    /** Sets the live window (clamped to 2–120 s) and keeps the history at least as long. */
    void setWindowSeconds(double seconds);
    /** Freezes the view (data keep coming into the history) or follows it again. */
    void setPaused(bool paused);
    /** Follows the newest data again. */
    void goLive();
    /** Pauses, brings `t` into view and places the cursor there (the event log's jump). */
    void setCursorTime(double t);

private:
    struct GripperPlot;
    struct SignalPlot;
    struct DevicePlot;
    struct SpanView;

    void rebuild();
    void clearPlots();
    void addGripper(Gripper gripper);
    /** A plot per frame signal of the gripper that threshold nodes read, with their levels. */
    void addSignals(Gripper gripper);
    void addDevice(int device);
    QCPAxisRect *addRect(const QString &label, int stretch);
    QCPGraph *addGraph(QCPAxisRect *rect, const QString &id, const QString &name,
                       const QColor &color, double width);
    void addThreshold(QCPAxisRect *rect, const QString &id, const QString &name, double value,
                      const QColor &color, Qt::PenStyle style = Qt::DashLine);
    /** The detectors' levels of `quantity` on the gripper's force or contacts rect. */
    void addLevels(GripperPlot *plot, DetectorLevel::Quantity quantity,
                   const std::vector<DetectorLevel> &levels);
    bool needsRebuild() const;

    void onUpdated();
    /** Replots at the next event loop turn, at most ~33 times a second. */
    void requestReplot();
    void appendNew();
    void syncSpans();
    /** Shades `span` on `rects`; its label goes on `labelRect` (laid out when a force rect). */
    SpanView makeSpanView(const MessageSpan &span, const std::vector<QCPAxisRect *> &rects,
                          QCPAxisRect *labelRect);
    void placeSpan(const SpanView &view, const MessageSpan &span);
    /** Shows the labels of the spans in view, none over another (the pixels are laid out). */
    void layoutSpanLabels();
    /** Holds the plot as high as its rects need, so the panel scrolls instead (afterLayout). */
    void keepReadableHeight();
    /** Fits the value axes to the data in view; true when a range or tick count changed. */
    bool fitValueAxes();
    /** Fits them again once a layout has set the rects' pixels. */
    void fitToLayout();
    /**
     * The upper end of a value range from `lower` that shows `top` below the rect's title and
     * legend, with at least `headroom` (a part of the data's span) above it.
     */
    double upperUnderHeader(QCPAxisRect *rect, double lower, double top, double headroom) const;
    /** As many value ticks on the rect as its height lets stand apart (true: changed). */
    static bool spaceValueTicks(QCPAxisRect *rect);
    /**
     * Names the levels beside the rect, on its right axis: levels closer than a label's
     * height share one label, a line each, so no name is drawn over another (true: changed).
     */
    bool nameLevels(QCPAxisRect *rect);
    /** Moves the legend under the title where the two do not fit side by side. */
    void placeLegend(QCPAxisRect *rect);
    void setTimeRange(double lower, double upper);
    void onTimeRangeChanged(const QCPRange &range);
    void updateCursor();
    void placeReadout();

    void onMousePress(QMouseEvent *event);
    void onMouseMove(QMouseEvent *event);
    void onMouseRelease(QMouseEvent *event);
    void placeCursorAt(int pixelX);
    void updateInteractions();
    void exportCsvDialog();
    void exportPngDialog();

    RunHistory &m_history;
    QCustomPlot *m_plot = nullptr;
    QToolButton *m_pauseButton = nullptr;
    QToolButton *m_liveButton = nullptr;
    QSpinBox *m_windowSpin = nullptr;
    QLabel *m_readout = nullptr;
    QCPMarginGroup *m_marginGroup = nullptr;

    std::vector<QCPAxisRect *> m_rects;
    /** A level's name beside its rect (nameLevels() lays them out). */
    struct LevelName
    {
        QCPAxisRect *rect;
        double value;
        QString name;
    };
    std::vector<LevelName> m_levelNames;
    /** Per rect: its title, whose width decides where the legend goes. */
    std::map<QCPAxisRect *, QCPItemText *> m_titles;
    std::vector<std::unique_ptr<GripperPlot>> m_grippers;
    std::vector<std::unique_ptr<SignalPlot>> m_signals;
    std::vector<std::unique_ptr<DevicePlot>> m_devices;
    std::vector<SpanView> m_spans;
    std::vector<QCPItemStraightLine *> m_cursorLines;
    QTimer m_replotTimer;
    QElapsedTimer m_sinceReplot;

    double m_windowSeconds = 10.0;
    int m_titleHeight = 0; ///< a rect's title's pixels, over the top of the rect
    bool m_paused = false;
    double m_cursorTime;
    bool m_draggingCursor = false;
    bool m_syncingRange = false;
};

} // namespace semhap
