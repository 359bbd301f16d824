// SPDX-License-Identifier: MIT
// PlotPanel fed from a RunHistory directly: the graphs, threshold lines and message spans
// it draws, and its controls driven as a user would (spin box, clicks, buttons).
#include "forcedetector.h"
#include "plotchecks.h"
#include "plotpanel.h"
#include "runhistory.h"
#include "slipdetector.h"

#include <QFile>
#include <QJsonDocument>
#include <QLabel>
#include <QScrollArea>
#include <QScrollBar>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QTest>
#include <QToolButton>

#include <qcustomplot.h>

#include <cmath>
#include <map>

using namespace semhap;

namespace {

constexpr int Ticks = 50; // frames at k / 10 s: 0 .. 5 s

// The synthetic run: F = 5 t (left 2 t, right 3 t), 32 contacts; the device's ch0 = t / 10,
// ch1 = 0.5, at twice the contact rate.
double leftForce(double t)
{
    return 2.0 * t;
}
double rightForce(double t)
{
    return 3.0 * t;
}

ContactFrame frameAt(double t, Gripper gripper)
{
    ContactFrame frame;
    frame.t = t;
    frame.gripper = gripper;
    frame.left.f = leftForce(t);
    frame.left.n = 16;
    frame.right.f = rightForce(t);
    frame.right.n = 16;
    return frame;
}

SemanticEvent eventAt(double t, int node, Message message, EventPhase phase)
{
    SemanticEvent event;
    event.t = t;
    event.node = node;
    event.detector = message == Message::Slip ? DetectorKind::Slip : DetectorKind::Force;
    event.message = message;
    event.category = categoryOf(message);
    event.phase = phase;
    return event;
}

GripperThresholds rightThresholds()
{
    // The levels as the detectors report them.
    ForceDetector::Params force;
    force.grasp = 5.0;
    force.brk = 80.0;
    force.max = 100.0;
    SlipDetector::Params slip;
    slip.loss = 24.0;
    slip.min = 8.0;
    GripperThresholds thresholds;
    thresholds.levels = ForceDetector(0, Gripper::Right, force).levels();
    for (const DetectorLevel &level : SlipDetector(1, Gripper::Right, slip).levels())
        thresholds.levels.push_back(level);
    return thresholds;
}

void startRun(RunHistory &history)
{
    std::array<GripperThresholds, 2> thresholds{};
    thresholds[size_t(Gripper::Right)] = rightThresholds();
    history.start({{QStringLiteral("right.vibro"), QStringLiteral("vibro"), {"ch0", "ch1"}}},
                  thresholds, {"right.force", "right.slip", "right.break"});
}

void appendTicks(RunHistory &history, int from, int to)
{
    for (int k = from; k <= to; ++k) {
        history.append(frameAt(k / 10.0, Gripper::Right));
        // Device frames in between, never after the newest contact frame (which is now).
        for (int half = k == 0 ? 0 : 1; half >= 0; --half) {
            DeviceFrame device;
            device.t = (2 * k - half) / 20.0;
            device.device = 0;
            device.channelCount = 2;
            device.values[0] = device.t / 10.0;
            device.values[1] = 0.5;
            history.append(device);
        }
    }
}

void fill(RunHistory &history)
{
    startRun(history);
    appendTicks(history, 0, Ticks);
    const std::pair<Message, std::pair<double, double>> spans[] = {
        {Message::Grasp, {1.0, 2.0}}, {Message::Break, {3.0, 3.5}}, {Message::Slip, {4.0, 4.5}}};
    for (const auto &[message, times] : spans) {
        const int node = message == Message::Slip ? 1 : 0;
        history.append(eventAt(times.first, node, message, EventPhase::Begin));
        history.append(eventAt(times.second, node, message, EventPhase::End));
    }
    // A predictive warning: a threshold node's break, beginning before the detector's.
    for (const auto &[t, phase] : {std::pair(2.75, EventPhase::Begin), {3.4, EventPhase::End}}) {
        SemanticEvent event = eventAt(t, 2, Message::Break, phase);
        event.detector = DetectorKind::Threshold;
        history.append(event);
    }
    history.commit();
}

/** Both hands, with detectors, and seven two-channel bands (a bimanual router, a live rig). */
void startBimanual(RunHistory &history)
{
    std::array<GripperThresholds, 2> thresholds{};
    thresholds[size_t(Gripper::Right)] = rightThresholds();
    thresholds[size_t(Gripper::Left)] = rightThresholds();
    std::vector<RunDevice> devices;
    for (int d = 0; d < 7; ++d)
        devices.push_back({QStringLiteral("band%1").arg(d), QStringLiteral("lra4"), {"m1", "m2"}});
    history.start(devices, thresholds, {"right.force", "right.slip"});
}

/** The router of a `semhap.router/1` text; null (and a warning) when it does not compile. */
std::unique_ptr<Router> routerOf(const char *json)
{
    RouterGraph graph;
    LoadError error;
    std::unique_ptr<Router> router;
    if (RouterGraph::fromJson(QJsonDocument::fromJson(json).object(), "r.json", &graph, &error))
        router = Router::compile(graph, &error);
    if (!router)
        qWarning("%s", qPrintable(error.toString()));
    return router;
}

template<typename T> T *itemNamed(QCustomPlot *plot, const QString &name)
{
    for (int i = 0; i < plot->itemCount(); ++i) {
        auto *item = qobject_cast<T *>(plot->item(i));
        if (item && item->objectName() == name)
            return item;
    }
    return nullptr;
}

QCPGraph *graphNamed(QCustomPlot *plot, const QString &name)
{
    for (int i = 0; i < plot->graphCount(); ++i) {
        if (plot->graph(i)->objectName() == name)
            return plot->graph(i);
    }
    return nullptr;
}

} // namespace

class TestPlots : public QObject
{
    Q_OBJECT

private slots:
    void init();
    void cleanup();
    void graphsHoldData_data();
    void graphsHoldData();
    void thresholdLines_data();
    void thresholdLines();
    void spans_data();
    void spans();
    void spanLabelsNeverOverlap_data();
    void spanLabelsNeverOverlap();
    void spanLabelLeavesWithItsSpan();
    void onlyNewSamplesAppended();
    void bimanualRightFirst();
    void windowSpinBox_data();
    void windowSpinBox();
    void clickPlacesCursor_data();
    void clickPlacesCursor();
    void setCursorTimePauses();
    void exportCsv();
    void exportPng();
    void resetClears();
    void manyDevicesScroll();
    void signalPlotsShowLevelsAndSpans();
    void dataAndLabelsStayClear_data();
    void dataAndLabelsStayClear();
    void namesLegendsAndTitlesNeverOverlap_data();
    void namesLegendsAndTitlesNeverOverlap();

private:
    QCPAxis *timeAxis() const { return m_plot->axisRect(0)->axis(QCPAxis::atBottom); }

    std::unique_ptr<RunHistory> m_history;
    std::unique_ptr<PlotPanel> m_panel;
    QCustomPlot *m_plot = nullptr;
};

void TestPlots::init()
{
    QLocale::setDefault(QLocale::c());
    m_history = std::make_unique<RunHistory>();
    m_panel = std::make_unique<PlotPanel>(*m_history);
    m_panel->resize(1280, 800);
    m_plot = m_panel->findChild<QCustomPlot *>();
    QVERIFY(m_plot);
    fill(*m_history);
    m_panel->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_panel.get()));
    m_plot->replot(); // lays the rects out, so pixels map to times
}

void TestPlots::cleanup()
{
    m_panel.reset();
    m_history.reset();
}

void TestPlots::graphsHoldData_data()
{
    QTest::addColumn<QString>("graph");
    QTest::addColumn<int>("count");
    QTest::addColumn<double>("key");
    QTest::addColumn<double>("value");
    QTest::newRow("sum") << "right.F" << Ticks + 1 << 2.0 << 10.0;
    QTest::newRow("left.f") << "right.left.f" << Ticks + 1 << 2.0 << 4.0;
    QTest::newRow("right.f") << "right.right.f" << Ticks + 1 << 2.0 << 6.0;
    QTest::newRow("contacts") << "right.N" << Ticks + 1 << 2.0 << 32.0;
    QTest::newRow("device ch0") << "right.vibro.ch0" << 2 * Ticks + 1 << 2.5 << 0.25;
    QTest::newRow("device ch1") << "right.vibro.ch1" << 2 * Ticks + 1 << 2.5 << 0.5;
}

void TestPlots::graphsHoldData()
{
    QFETCH(QString, graph);
    QFETCH(int, count);
    QFETCH(double, key);
    QFETCH(double, value);
    QCPGraph *g = graphNamed(m_plot, graph);
    QVERIFY(g);
    QCOMPARE(g->dataCount(), count);
    const auto it = g->data()->findBegin(key, false);
    QCOMPARE(it->key, key);
    QCOMPARE(it->value, value);
    QVERIFY(!graphNamed(m_plot, "left.F")); // no detector and no data on the left
}

void TestPlots::thresholdLines_data()
{
    QTest::addColumn<QString>("line");
    QTest::addColumn<double>("value");
    QTest::newRow("grasp") << "right.grasp" << 5.0;
    QTest::newRow("break") << "right.break" << 80.0;
    QTest::newRow("max") << "right.max" << 100.0;
    QTest::newRow("loss") << "right.loss" << 24.0;
    QTest::newRow("min") << "right.min" << 8.0;
}

void TestPlots::thresholdLines()
{
    QFETCH(QString, line);
    QFETCH(double, value);
    auto *item = itemNamed<QCPItemStraightLine>(m_plot, line);
    QVERIFY(item);
    QCOMPARE(item->point1->coords().y(), value);
    QCOMPARE(item->point2->coords().y(), value);
    QVERIFY(item->pen().style() == Qt::DashLine);
    // The value axis keeps the highest threshold in view.
    QVERIFY(item->point1->valueAxis()->range().contains(value));
}

void TestPlots::spans_data()
{
    QTest::addColumn<QString>("span");
    QTest::addColumn<QString>("label");
    QTest::addColumn<QColor>("color");
    QTest::addColumn<int>("pattern");
    QTest::addColumn<double>("begin");
    QTest::addColumn<double>("end");
    QTest::newRow("grasp: confirmation")
        << "span.right.grasp"
        << "grasp" << QColor(0x0072B2) << int(Qt::SolidPattern) << 1.0 << 2.0;
    QTest::newRow("break: exception")
        << "span.right.break"
        << "break" << QColor(0xE69F00) << int(Qt::SolidPattern) << 3.0 << 3.5;
    QTest::newRow("slip: hatched exception")
        << "span.right.slip"
        << "slip" << QColor(0xD55E00) << int(Qt::BDiagPattern) << 4.0 << 4.5;
    QTest::newRow("threshold node: named after it")
        << "span.right.break/right.break"
        << "right.break" << QColor(0xE69F00) << int(Qt::SolidPattern) << 2.75 << 3.4;
}

void TestPlots::spans()
{
    QFETCH(QString, span);
    QFETCH(QString, label);
    QFETCH(QColor, color);
    QFETCH(int, pattern);
    QFETCH(double, begin);
    QFETCH(double, end);
    auto *shade = itemNamed<QCPItemRect>(m_plot, span);
    QVERIFY(shade);
    QCOMPARE(shade->brush().color().rgb(), color.rgb());
    QVERIFY(shade->brush().color().alpha() < 255); // the data stay visible through it
    QCOMPARE(int(shade->brush().style()), pattern);
    QCOMPARE(shade->topLeft->coords().x(), begin);
    QCOMPARE(shade->bottomRight->coords().x(), end);
    auto *text = itemNamed<QCPItemText>(m_plot, span);
    QVERIFY(text);
    QCOMPARE(text->text(), label);
}

/** The message-span labels drawn in the plot: their rectangles on screen, by name. */
static QList<std::pair<QString, QRectF>> spanLabels(QCustomPlot *plot)
{
    QList<std::pair<QString, QRectF>> labels;
    for (int i = 0; i < plot->itemCount(); ++i) {
        auto *text = qobject_cast<QCPItemText *>(plot->item(i));
        if (!text || !text->objectName().startsWith("span.") || !text->visible())
            continue;
        const QRectF box(text->topLeft->pixelPosition(), text->bottomRight->pixelPosition());
        if (box.intersects(text->clipAxisRect()->rect()))
            labels.append({text->objectName(), box});
    }
    return labels;
}

void TestPlots::spanLabelsNeverOverlap_data()
{
    QTest::addColumn<QSize>("size");
    QTest::newRow("1280x800") << QSize(1280, 800);
    QTest::newRow("a short dock, 400x300") << QSize(400, 300);
}

// Short spans close together, of every kind (a grip that chatters, breaks and slips, a
// threshold node's warnings): their labels are laid out so that none covers another.
void TestPlots::spanLabelsNeverOverlap()
{
    QFETCH(QSize, size);
    m_panel->resize(size);
    startRun(*m_history); // forgets the spans fill() made
    appendTicks(*m_history, 0, Ticks);
    for (int k = 0; k < 30; ++k) {
        const double t = 0.1 + 0.15 * k;
        const Message message = k % 3 == 0   ? Message::Grasp
                                : k % 3 == 1 ? Message::Break
                                             : Message::Slip;
        const int node = message == Message::Slip ? 1 : 0;
        m_history->append(eventAt(t, node, message, EventPhase::Begin));
        m_history->append(eventAt(t + 0.1, node, message, EventPhase::End));
        SemanticEvent warning = eventAt(t + 0.05, 2, Message::Break, EventPhase::Begin);
        warning.detector = DetectorKind::Threshold;
        m_history->append(warning);
        warning.t += 0.08;
        warning.phase = EventPhase::End;
        m_history->append(warning);
    }
    // The left hand holds something the while: its label shows in its own plot.
    for (int k = 0; k <= Ticks; ++k)
        m_history->append(frameAt(k / 10.0, Gripper::Left));
    SemanticEvent held = eventAt(0.5, 0, Message::Grasp, EventPhase::Begin);
    held.gripper = Gripper::Left;
    m_history->append(held);
    m_history->commit();
    m_plot->replot();
    const QList<std::pair<QString, QRectF>> labels = spanLabels(m_plot);
    const auto shows = [&labels](const QString &prefix) {
        return std::any_of(labels.begin(), labels.end(), [&prefix](const auto &label) {
            return label.first.startsWith(prefix);
        });
    };
    QVERIFY(shows("span.right."));
    QVERIFY(shows("span.left."));
    for (int i = 0; i < labels.size(); ++i) {
        for (int j = i + 1; j < labels.size(); ++j) {
            QVERIFY2(
                !labels[i].second.intersects(labels[j].second),
                qPrintable(QString("%1 and %2 overlap").arg(labels[i].first, labels[j].first)));
        }
    }
    if (const QString dir = qEnvironmentVariable("SEMHAP_SCREENSHOTS"); !dir.isEmpty())
        m_panel->grab().save(QString("%1/plots-span-labels-%2.png").arg(dir).arg(size.width()));
}

// A span that ended before the view's left edge takes its label along; one still active
// keeps it at the edge.
void TestPlots::spanLabelLeavesWithItsSpan()
{
    m_history->append(eventAt(4.8, 0, Message::Grasp, EventPhase::Begin)); // still active
    m_history->commit();
    m_panel->setWindowSeconds(2.0); // 3 .. 5 s: the grasp of 1 .. 2 s is out of view
    m_plot->replot();
    QStringList names;
    for (const auto &[name, box] : spanLabels(m_plot))
        names.append(name);
    QCOMPARE(names.count("span.right.grasp"), 1); // the active one, not the ended one
    QVERIFY2(names.contains("span.right.break"), qPrintable(names.join(", ")));
    QVERIFY2(names.contains("span.right.slip"), qPrintable(names.join(", ")));

    // Further on, the break and the slip go too; the active grasp stays at the left edge.
    appendTicks(*m_history, Ticks + 1, Ticks + 25); // now 7.5 s: 5.5 .. 7.5
    m_history->commit();
    m_plot->replot();
    names.clear();
    QRectF grasp;
    for (const auto &[name, box] : spanLabels(m_plot)) {
        names.append(name);
        grasp = name == "span.right.grasp" ? box : grasp;
    }
    QCOMPARE(names, QStringList{"span.right.grasp"});
    QCOMPARE(grasp.left(), timeAxis()->axisRect()->rect().left() * 1.0);
}

void TestPlots::onlyNewSamplesAppended()
{
    appendTicks(*m_history, Ticks + 1, Ticks + 10);
    m_history->commit();
    QCPGraph *g = graphNamed(m_plot, "right.F");
    QCOMPARE(g->dataCount(), Ticks + 11);
    QCOMPARE((g->data()->constEnd() - 1)->key, (Ticks + 10) / 10.0);
    // The live view follows the newest data.
    QCOMPARE(timeAxis()->range().upper, (Ticks + 10) / 10.0);
}

void TestPlots::bimanualRightFirst()
{
    m_history->append(frameAt(5.1, Gripper::Left));
    m_history->commit();
    QCPGraph *right = graphNamed(m_plot, "right.F");
    QCPGraph *left = graphNamed(m_plot, "left.F");
    QVERIFY(right && left);
    QCOMPARE(left->dataCount(), 1);
    QCOMPARE(right->dataCount(), Ticks + 1); // the rebuilt plot reads the history again
    m_plot->replot();
    QVERIFY(right->keyAxis()->axisRect()->top() < left->keyAxis()->axisRect()->top());
}

void TestPlots::windowSpinBox_data()
{
    QTest::addColumn<QString>("typed");
    QTest::addColumn<double>("seconds");
    QTest::newRow("30 s") << "30" << 30.0;
    QTest::newRow("2 s") << "2" << 2.0;
    QTest::newRow("above the maximum") << "500" << 50.0; // the spin box refuses the last 0
}

void TestPlots::windowSpinBox()
{
    QFETCH(QString, typed);
    QFETCH(double, seconds);
    auto *spin = m_panel->findChild<QSpinBox *>();
    QVERIFY(spin);
    spin->setFocus();
    QTest::keyClick(spin, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClicks(spin, typed);
    QTest::keyClick(spin, Qt::Key_Return);
    QCOMPARE(m_panel->windowSeconds(), seconds);
    QCOMPARE(timeAxis()->range().size(), seconds);
    QCOMPARE(timeAxis()->range().upper, Ticks / 10.0);
    QVERIFY(m_history->keepSeconds() >= seconds);
}

void TestPlots::clickPlacesCursor_data()
{
    QTest::addColumn<double>("t");
    QTest::newRow("in the grasp") << 1.55;
    QTest::newRow("in the break") << 3.25;
}

void TestPlots::clickPlacesCursor()
{
    QFETCH(double, t);
    QCPAxisRect *rect = m_plot->axisRect(0);
    const QPoint at(int(std::lround(timeAxis()->coordToPixel(t))), rect->center().y());
    QTest::mouseClick(m_plot, Qt::LeftButton, Qt::NoModifier, at);
    QVERIFY(std::abs(m_panel->cursorTime() - t) < 0.02);
    // Sample and hold: the readout shows the last frame at or before the cursor.
    const double sample = std::floor(m_panel->cursorTime() * 10.0) / 10.0;
    auto *readout = m_plot->findChild<QLabel *>("cursorReadout");
    QVERIFY(readout && readout->isVisible());
    const QString text = readout->text();
    QVERIFY2(text.contains(QString::number(5.0 * sample, 'f', 2) + " N"), qPrintable(text));
    QVERIFY2(text.contains("N 32"), qPrintable(text));
    const double ch0 = std::floor(m_panel->cursorTime() * 20) / 20.0 / 10.0;
    QVERIFY2(text.contains("ch0 " + QString::number(ch0, 'f', 2)), qPrintable(text));
    auto *cursor = itemNamed<QCPItemStraightLine>(m_plot, "cursor");
    QVERIFY(cursor && cursor->visible());
    QCOMPARE(cursor->point1->coords().x(), m_panel->cursorTime());
}

void TestPlots::setCursorTimePauses()
{
    m_panel->setWindowSeconds(2.0); // 3 .. 5 s
    m_panel->setCursorTime(1.0);
    QVERIFY(m_panel->isPaused());
    auto *pause = m_panel->findChild<QToolButton *>();
    QVERIFY(pause->isChecked());
    QVERIFY(timeAxis()->range().contains(1.0));
    QCOMPARE(m_panel->cursorTime(), 1.0);
    const QCPRange frozen = timeAxis()->range();

    // Data keep coming; the paused view stays.
    appendTicks(*m_history, Ticks + 1, Ticks + 20);
    m_history->commit();
    QCOMPARE(timeAxis()->range(), frozen);
    QCOMPARE(graphNamed(m_plot, "right.F")->dataCount(), Ticks + 21);

    QToolButton *live = nullptr;
    for (auto *button : m_panel->findChildren<QToolButton *>()) {
        if (button->text() == "Live")
            live = button;
    }
    QVERIFY(live);
    QTest::mouseClick(live, Qt::LeftButton);
    QVERIFY(!m_panel->isPaused());
    QCOMPARE(timeAxis()->range().upper, (Ticks + 20) / 10.0);
}

void TestPlots::exportCsv()
{
    m_panel->setWindowSeconds(2.0); // rows at 3.0, 3.1, ... 5.0
    QTemporaryDir dir;
    const QString path = dir.filePath("plots.csv");
    QString error;
    QVERIFY2(m_panel->exportCsv(path, &error), qPrintable(error));
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly | QIODevice::Text));
    const QStringList lines = QString::fromUtf8(file.readAll()).split('\n', Qt::SkipEmptyParts);
    QCOMPARE(lines.value(0),
             "t,right.F,right.left.f,right.right.f,right.N,right.vibro.ch0,right.vibro.ch1");
    QCOMPARE(lines.size(), 1 + 21);
    for (int row = 1; row < lines.size(); ++row) {
        const QStringList cells = lines[row].split(',');
        QCOMPARE(cells.size(), 7);
        const double t = cells[0].toDouble();
        QCOMPARE(t, (29 + row) / 10.0);
        QCOMPARE(cells[1].toDouble(), leftForce(t) + rightForce(t));
        QCOMPARE(cells[2].toDouble(), leftForce(t));
        QCOMPARE(cells[3].toDouble(), rightForce(t));
        QCOMPARE(cells[4].toInt(), 32);
        QCOMPARE(cells[5].toDouble(), t / 10.0);
        QCOMPARE(cells[6].toDouble(), 0.5);
    }
    QVERIFY(!m_panel->exportCsv(dir.filePath("missing/plots.csv"), &error));
    QVERIFY(!error.isEmpty());
}

void TestPlots::exportPng()
{
    QTemporaryDir dir;
    const QString path = dir.filePath("plots.png");
    QString error;
    QVERIFY2(m_panel->exportPng(path, &error), qPrintable(error));
    QImage image(path);
    QCOMPARE(image.size(), m_plot->size());
}

void TestPlots::resetClears()
{
    m_panel->setCursorTime(2.0);
    m_history->start({}, {}, {});
    QCOMPARE(m_plot->graphCount(), 0);
    QCOMPARE(m_plot->itemCount(), 0);
    QCOMPARE(m_plot->axisRectCount(), 0);
    QVERIFY(!m_panel->isPaused());
    QVERIFY(std::isnan(m_panel->cursorTime()));

    // The next run's data show again.
    startRun(*m_history);
    appendTicks(*m_history, 0, 3);
    m_history->commit();
    QCOMPARE(graphNamed(m_plot, "right.F")->dataCount(), 4);
}

void TestPlots::manyDevicesScroll()
{
    // Both hands and seven devices (the bimanual task, a live rig) in a short dock: every
    // rect keeps room to be read and the panel scrolls, rather than squash them to strips.
    startBimanual(*m_history);
    m_panel->resize(640, 600);
    QTest::qWait(50);
    m_plot->replot();
    auto *scroll = m_panel->findChild<QScrollArea *>("plotScroll");
    QVERIFY(scroll);
    QCOMPARE(m_plot->axisRectCount(), 4 + 7);
    // Each with at least two value labels under its title (a device's rect had one, "0", in
    // dish_wiping's dock at 1280x800: issue 33, D12).
    for (int i = 0; i < m_plot->axisRectCount(); ++i) {
        const int labels = valueLabelsInView(m_plot->axisRect(i));
        QVERIFY2(labels >= 2, qPrintable(QString("rect %1: %2 value label(s) in %3 px")
                                             .arg(i)
                                             .arg(labels)
                                             .arg(m_plot->axisRect(i)->height())));
    }
    QVERIFY(scroll->verticalScrollBar()->maximum() > 0);
    // Tall enough, it fits without scrolling.
    m_panel->resize(640, 1400);
    QTest::qWait(50);
    QCOMPARE(scroll->verticalScrollBar()->maximum(), 0);
}

void TestPlots::dataAndLabelsStayClear_data()
{
    QTest::addColumn<int>("height");
    QTest::newRow("short dock: every rect at its least") << 600;
    QTest::newRow("tall dock") << 1400;
}

void TestPlots::dataAndLabelsStayClear()
{
    // Both hands and seven bands, each sending 1.0 (full scale) on a channel: the curve at
    // 1.0 runs below its rect's title and legend (it ran behind them), and no two value
    // labels of a rect overlap (the force's seven did in a short rect, as at 1920×1080).
    QFETCH(int, height);
    startBimanual(*m_history);
    for (int k = 0; k <= Ticks; ++k) {
        for (Gripper gripper : {Gripper::Right, Gripper::Left})
            m_history->append(frameAt(k / 10.0, gripper));
        for (int d = 0; d < 7; ++d) {
            DeviceFrame device;
            device.t = k / 10.0;
            device.device = d;
            device.channelCount = 2;
            device.values[0] = 1.0;
            m_history->append(device);
        }
    }
    m_history->commit();
    m_panel->resize(640, height);
    QTest::qWait(50);
    m_plot->replot();
    QCOMPARE(m_plot->axisRectCount(), 4 + 7);
    // The rects' titles: the texts at each rect's top left corner.
    std::map<QCPAxisRect *, double> titleBottoms;
    for (int i = 0; i < m_plot->itemCount(); ++i) {
        auto *text = qobject_cast<QCPItemText *>(m_plot->item(i));
        if (text && text->position->typeY() == QCPItemPosition::ptAxisRectRatio &&
            text->position->coords() == QPointF(0.0, 0.0))
            titleBottoms[text->clipAxisRect()] = text->bottom->pixelPosition().y();
    }
    QCOMPARE(int(titleBottoms.size()), m_plot->axisRectCount());
    for (int i = 0; i < m_plot->axisRectCount(); ++i) {
        QCPAxisRect *rect = m_plot->axisRect(i);
        const QString where = QString::number(i);
        QCPAxis *values = rect->axis(QCPAxis::atLeft);
        const auto *legend = qobject_cast<QCPLegend *>(rect->insetLayout()->elementAt(0));
        QVERIFY(legend);
        if (i >= 4) { // a band's rect: its 1.0
            const double one = values->coordToPixel(1.0);
            QVERIFY2(one > legend->outerRect().bottom(), qPrintable(where));
            QVERIFY2(one > titleBottoms[rect], qPrintable(where));
        }
        // At least two value labels (a band's 0 and 1), none over the next.
        const QFontMetrics metrics(values->tickLabelFont());
        std::vector<double> shown;
        for (double tick : values->tickVector()) {
            if (values->range().contains(tick))
                shown.push_back(values->coordToPixel(tick));
        }
        QVERIFY2(shown.size() >= 2, qPrintable(where));
        for (size_t t = 1; t < shown.size(); ++t)
            QVERIFY2(std::abs(shown[t] - shown[t - 1]) >= metrics.height(), qPrintable(where));
    }
}

void TestPlots::signalPlotsShowLevelsAndSpans()
{
    // A router whose threshold nodes read the right hand's plug.angle directly ("aligned":
    // inside a range, with hysteresis), through a derivative ("turning": other units, so
    // no levels) and F through predict (a built-in: the force rect's, no plot of its own).
    const char *json = R"({"format": "semhap.router/1", "nodes": [
        {"id": "angle", "type": "signal",
         "params": {"gripper": "right", "quantity": "plug.angle"}},
        {"id": "aligned", "type": "threshold",
         "params": {"gripper": "right", "message": "aligned", "category": "confirmation",
                    "condition": "inside", "begin": [-0.05, 0.05], "end": [-0.06, 0.06]}},
        {"id": "rate", "type": "derivative", "params": {}},
        {"id": "turning", "type": "threshold",
         "params": {"gripper": "right", "message": "turning", "category": "exception",
                    "begin": 2}},
        {"id": "F", "type": "signal", "params": {"gripper": "right", "quantity": "F"}},
        {"id": "Fp", "type": "predict", "params": {}},
        {"id": "depth", "type": "signal",
         "params": {"gripper": "right", "quantity": "plug.depth"}},
        {"id": "speed", "type": "derivative", "params": {}},
        {"id": "pushing", "type": "threshold",
         "params": {"gripper": "right", "message": "pushing", "category": "exception",
                    "begin": 0.1}},
        {"id": "soon", "type": "threshold",
         "params": {"gripper": "right", "message": "break", "begin": 70}}
      ], "links": [
        {"from": "angle", "to": "aligned"}, {"from": "angle", "to": "rate"},
        {"from": "rate", "to": "turning"}, {"from": "F", "to": "Fp"}, {"from": "Fp", "to": "soon"},
        {"from": "depth", "to": "speed"}, {"from": "speed", "to": "pushing"}
      ]})";
    const std::unique_ptr<Router> router = routerOf(json);
    QVERIFY(router);

    RunHistory history;
    PlotPanel panel(history);
    panel.resize(1280, 800);
    history.start({}, thresholdsOf(*router, Hands{false, true}), router->nodeIds());
    // The angle falls from 0.2 by 0.05 per second; the frames from 2.0 to 2.4 s lack it.
    // plug.depth holds at 2 mm.
    const int angle = signalNames().find("plug.angle");
    const int depth = signalNames().find("plug.depth");
    for (int k = 0; k <= Ticks; ++k) {
        ContactFrame frame = frameAt(k / 10.0, Gripper::Right);
        frame.signalValues.set(depth, 0.002);
        if (k < 20 || k > 24)
            frame.signalValues.set(angle, 0.2 - 0.05 * frame.t);
        history.append(frame);
    }
    const int aligned = int(router->nodeIds().indexOf("aligned"));
    SemanticEvent event = eventAt(3.0, aligned, Message::Grasp, EventPhase::Begin);
    QVERIFY(messageFromName("aligned", &event.message));
    event.detector = DetectorKind::Threshold;
    event.category = Category::Confirmation;
    history.append(event);
    event.t = 4.5;
    event.phase = EventPhase::End;
    history.append(event);
    history.commit();
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    auto *plot = panel.findChild<QCustomPlot *>();
    plot->replot();

    // One plot for plug.angle, its axis named after it, with the values and a gap.
    QCPGraph *values = graphNamed(plot, "right.plug.angle");
    QVERIFY(values);
    QCOMPARE(values->valueAxis()->label(), QStringLiteral("plug.angle"));
    QCOMPARE(values->data()->findBegin(1.0, false)->value, 0.15);
    QVERIFY(std::isnan(values->data()->findBegin(2.0, false)->value));
    QCOMPARE(values->data()->findBegin(2.5, false)->value, 0.2 - 0.05 * 2.5);
    QVERIFY(!graphNamed(plot, "right.F.predicted"));
    QCOMPARE(plot->axisRectCount(), 4); // force, contacts, plug.angle, plug.depth
    // A flat signal without levels is shown at its own scale.
    QCPGraph *flat = graphNamed(plot, "right.plug.depth");
    QVERIFY(flat);
    QVERIFY(flat->valueAxis()->range().contains(0.002));
    QVERIFY2(flat->valueAxis()->range().size() < 0.01,
             qPrintable(QString::number(flat->valueAxis()->range().size())));

    // Its levels: the begin range dashed, the end range dotted; none for the derivative's.
    const std::pair<const char *, double> lines[] = {
        {"begin", -0.05}, {"beginHigh", 0.05}, {"end", -0.06}, {"endHigh", 0.06}};
    for (const auto &[key, level] : lines) {
        auto *line = itemNamed<QCPItemStraightLine>(
            plot, QStringLiteral("right.plug.angle/aligned.") + key);
        QVERIFY2(line, key);
        QCOMPARE(line->point1->coords().y(), level);
        QVERIFY(line->pen().style() ==
                (QByteArray(key).startsWith("begin") ? Qt::DashLine : Qt::DotLine));
        QCOMPARE(line->clipAxisRect(), values->keyAxis()->axisRect());
        QVERIFY(values->valueAxis()->range().contains(level));
    }
    QVERIFY(!itemNamed<QCPItemStraightLine>(plot, "right.plug.angle/turning.begin"));

    // The message's span shaded on the signal's plot as on the gripper's two rects.
    int shades = 0;
    bool onSignal = false;
    for (int i = 0; i < plot->itemCount(); ++i) {
        auto *shade = qobject_cast<QCPItemRect *>(plot->item(i));
        if (!shade || shade->objectName() != "span.right.aligned/aligned")
            continue;
        ++shades;
        onSignal |= shade->clipAxisRect() == values->keyAxis()->axisRect();
        QCOMPARE(shade->topLeft->coords().x(), 3.0);
        QCOMPARE(shade->bottomRight->coords().x(), 4.5);
        QCOMPARE(shade->brush().color().rgb(), QColor(0x0072B2).rgb()); // a confirmation
    }
    QCOMPARE(shades, 3);
    QVERIFY(onSignal);

    // Exported with the rest.
    panel.setWindowSeconds(2.0);
    QTemporaryDir dir;
    QVERIFY2(panel.exportCsv(dir.filePath("plots.csv"), nullptr), "cannot export");
    QFile file(dir.filePath("plots.csv"));
    QVERIFY(file.open(QIODevice::ReadOnly | QIODevice::Text));
    const QStringList rows = QString::fromUtf8(file.readAll()).split('\n', Qt::SkipEmptyParts);
    QCOMPARE(rows.value(0),
             "t,right.F,right.left.f,right.right.f,right.N,right.plug.angle,right.plug.depth");
    QCOMPARE(rows.value(1).split(',').value(5).toDouble(), 0.2 - 0.05 * 3.0);
    if (qEnvironmentVariableIsSet("SEMHAP_SCREENSHOTS")) {
        panel.setWindowSeconds(5.0);
        plot->replot();
        QVERIFY(
            panel.grab().save(qEnvironmentVariable("SEMHAP_SCREENSHOTS") + "/plots-signal.png"));
    }
}

void TestPlots::namesLegendsAndTitlesNeverOverlap_data()
{
    QTest::addColumn<int>("width");
    QTest::newRow("a narrow dock, 560 px") << 560;
    QTest::newRow("1280 px") << 1280;
}

// Issue 33, D12. Two threshold nodes on plug.lateral at 1 cm and 0.3 mm, a scale of 20 cm:
// their names stood over each other beside the plot; in a narrow dock each rect's legend hid
// its title; a span begun near the right edge had its label cut there ("right.b").
void TestPlots::namesLegendsAndTitlesNeverOverlap()
{
    QFETCH(int, width);
    const char *json = R"({"format": "semhap.router/1", "nodes": [
        {"id": "lateral", "type": "signal",
         "params": {"gripper": "right", "quantity": "plug.lateral"}},
        {"id": "right.over.port", "type": "threshold",
         "params": {"gripper": "right", "message": "over", "category": "confirmation",
                    "condition": "below", "begin": 0.01, "end": 0.015}},
        {"id": "right.off.axis", "type": "threshold",
         "params": {"gripper": "right", "message": "off", "category": "exception",
                    "begin": 0.0003, "end": 0.00025}},
        {"id": "right.centred", "type": "threshold",
         "params": {"gripper": "right", "message": "centred", "category": "confirmation",
                    "condition": "below", "begin": 0.0005}}
      ], "links": [
        {"from": "lateral", "to": "right.over.port"}, {"from": "lateral", "to": "right.off.axis"},
        {"from": "lateral", "to": "right.centred"}
      ]})";
    const std::unique_ptr<Router> router = routerOf(json);
    QVERIFY(router);
    RunHistory history;
    PlotPanel panel(history);
    panel.resize(width, 800);
    history.start({}, thresholdsOf(*router, Hands{false, true}), router->nodeIds());
    const int lateral = signalNames().find("plug.lateral");
    for (int k = 0; k <= Ticks; ++k) {
        ContactFrame frame = frameAt(k / 10.0, Gripper::Right);
        frame.signalValues.set(lateral, 0.2 - 0.04 * frame.t);
        history.append(frame);
    }
    // A break warning in the last tenth of a second: its label would run past the edge.
    SemanticEvent warning = eventAt(4.95, 0, Message::Break, EventPhase::Begin);
    history.append(warning);
    history.commit();
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    auto *plot = panel.findChild<QCustomPlot *>();
    plot->replot();
    QTest::qWait(100); // a legend moved under its title is laid out at the next replot
    plot->replot();

    // Every level's name is beside the plot once, and no two labels overlap.
    for (int r = 0; r < plot->axisRectCount(); ++r) {
        QCPAxis *names = plot->axisRect(r)->axis(QCPAxis::atRight);
        auto ticker = names->ticker().dynamicCast<QCPAxisTickerText>();
        if (!ticker || ticker->ticks().isEmpty())
            continue;
        const double line = QFontMetrics(names->tickLabelFont()).height();
        const QList<double> values = ticker->ticks().keys();
        for (int i = 0; i + 1 < values.size(); ++i) {
            const double apart =
                std::abs(names->coordToPixel(values[i + 1]) - names->coordToPixel(values[i]));
            const int lines = int(ticker->ticks()[values[i]].count('\n') +
                                  ticker->ticks()[values[i + 1]].count('\n')) +
                              2;
            QVERIFY2(
                apart >= lines * line / 2 - 0.5,
                qPrintable(QString("%1 and %2: %3 px apart")
                               .arg(ticker->ticks()[values[i]], ticker->ticks()[values[i + 1]])
                               .arg(apart)));
        }
    }
    bool named = false;
    for (int r = 0; r < plot->axisRectCount(); ++r) {
        auto ticker =
            plot->axisRect(r)->axis(QCPAxis::atRight)->ticker().dynamicCast<QCPAxisTickerText>();
        if (!ticker)
            continue;
        const QString all = QStringList(ticker->ticks().values()).join('\n');
        if (all.contains("right.over.port")) {
            named = true;
            for (const char *node : {"right.over.port", "right.off.axis", "right.centred"})
                QCOMPARE(all.count(node), 1);
        }
    }
    QVERIFY(named);

    // Each rect's title and legend stand clear of each other.
    for (int i = 0; i < plot->itemCount(); ++i) {
        auto *title = qobject_cast<QCPItemText *>(plot->item(i));
        if (!title || !title->objectName().isEmpty() || !title->clipAxisRect())
            continue;
        QCPAxisRect *rect = title->clipAxisRect();
        if (rect->insetLayout()->elementCount() == 0 || title->position->coords() != QPointF(0, 0))
            continue;
        const QRectF box(title->topLeft->pixelPosition(), title->bottomRight->pixelPosition());
        const QRect legend = rect->insetLayout()->elementAt(0)->outerRect();
        QVERIFY2(!box.intersects(QRectF(legend).adjusted(1, 1, -1, -1)),
                 qPrintable(QString("%1 under its legend").arg(title->text())));
    }

    // A span's label ends inside its rect.
    const QList<std::pair<QString, QRectF>> labels = spanLabels(plot);
    QVERIFY(!labels.isEmpty());
    for (const auto &[name, box] : labels) {
        const QRect area = plot->axisRect(0)->rect();
        QVERIFY2(box.right() <= area.right() + 1.0,
                 qPrintable(
                     QString("%1 ends at %2 of %3").arg(name).arg(box.right()).arg(area.right())));
    }
    if (const QString dir = qEnvironmentVariable("SEMHAP_SCREENSHOTS"); !dir.isEmpty())
        panel.grab().save(QString("%1/plots-names-%2.png").arg(dir).arg(width));
}

QTEST_MAIN(TestPlots)
#include "tst_plots.moc"
