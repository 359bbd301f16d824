// SPDX-License-Identifier: MIT
#pragma once

#include "paneldock.h"
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

namespace plotlayout {
struct LevelName;
}
struct DevicePlot;
struct GripperPlot;
class PlotCursor;
struct SignalPlot;
class SpanOverlay;

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
    /** Where the main window docks it by default (PanelDock). */
    static PanelDock dock();
    /** Shows `history`, which must outlive the panel. */
    explicit PlotPanel(RunHistory &history, QWidget *parent = nullptr);
    ~PlotPanel() override;

    /** The live view's width in pipeline seconds (2–120); the history keeps at least it. */
    double windowSeconds() const { return m_windowSeconds; }
    /** True while the view is frozen for inspection. */
    bool isPaused() const { return m_paused; }
    /** The cursor's time, or NaN while there is none. */
    double cursorTime() const;

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
    void rebuild();
    void clearPlots();
    void addGripper(Gripper gripper);
    /** A plot per frame signal of the gripper that threshold nodes read, with their levels. */
    void addSignals(Gripper gripper);
    void addDevice(int device);
    QCPAxisRect *addRect(const QString &label, int stretch);
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
    /** Shows the labels of the spans in view, none over another (the pixels are laid out). */
    void layoutSpanLabels();
    /** Holds the plot as high as its rects need, so the panel scrolls instead (afterLayout). */
    void keepReadableHeight();
    /** Fits the value axes to the data in view; true when a range or tick count changed. */
    bool fitValueAxes();
    /** Fits them again once a layout has set the rects' pixels. */
    void fitToLayout();
    void setTimeRange(double lower, double upper);
    void onTimeRangeChanged(const QCPRange &range);
    /** What the cursor reads at `t`: each plot's latest value at or before it. */
    QString readoutAt(double t) const;
    void updateInteractions();
    void exportCsvDialog();
    void exportPngDialog();

    RunHistory &m_history;
    QCustomPlot *m_plot = nullptr;
    QToolButton *m_pauseButton = nullptr;
    QToolButton *m_liveButton = nullptr;
    QSpinBox *m_windowSpin = nullptr;
    PlotCursor *m_cursor = nullptr;
    QCPMarginGroup *m_marginGroup = nullptr;

    std::vector<QCPAxisRect *> m_rects;
    std::vector<plotlayout::LevelName> m_levelNames; ///< laid out by plotlayout::nameLevels

    /** Per rect: its title, whose width decides where the legend goes. */
    std::map<QCPAxisRect *, QCPItemText *> m_titles;
    std::vector<std::unique_ptr<GripperPlot>> m_grippers;
    std::vector<std::unique_ptr<SignalPlot>> m_signals;
    std::vector<std::unique_ptr<DevicePlot>> m_devices;
    std::unique_ptr<SpanOverlay> m_spanOverlay;
    QTimer m_replotTimer;
    QElapsedTimer m_sinceReplot;

    double m_windowSeconds = 10.0;
    int m_titleHeight = 0; ///< a rect's title's pixels, over the top of the rect
    bool m_paused = false;
    bool m_syncingRange = false;
};

} // namespace semhap
