// SPDX-License-Identifier: MIT
// The event log and the metrics panel on a live history: rows and their columns, batched
// appends and the row cap, the filters driven through their widgets, the time a click
// reports, reset; metrics shown with human labels and formatted values.
#include "colors.h"
#include "eventlogmodel.h"
#include "eventlogpanel.h"
#include "metricspanel.h"
#include "metricspec.h"
#include "runhistory.h"

#include <QCheckBox>
#include <QComboBox>
#include <QElapsedTimer>
#include <QFile>
#include <QGuiApplication>
#include <QHeaderView>
#include <QJsonObject>
#include <QLabel>
#include <QLineEdit>
#include <QRegularExpression>
#include <QScreen>
#include <QScrollBar>
#include <QSignalSpy>
#include <QTableView>
#include <QTest>
#include <QToolTip>
#include <QTranslator>

using namespace semhap;

namespace {

SemanticEvent makeEvent(double t, Gripper gripper, int node, DetectorKind detector,
                        Message message, EventPhase phase, double intensity)
{
    SemanticEvent e;
    e.t = t;
    e.gripper = gripper;
    e.node = node;
    e.detector = detector;
    e.message = message;
    e.category = categoryOf(message);
    e.phase = phase;
    e.intensity = intensity;
    return e;
}

/** A short run: grasps on both hands, a slip and a break on the right. */
const std::vector<SemanticEvent> &run()
{
    static const std::vector<SemanticEvent> events = {
        makeEvent(0.1, Gripper::Right, 1, DetectorKind::Force, Message::Grasp, EventPhase::Begin,
                  0.5),
        makeEvent(0.25, Gripper::Right, 1, DetectorKind::Force, Message::Grasp, EventPhase::Update,
                  0.7),
        makeEvent(1.0, Gripper::Left, 0, DetectorKind::Force, Message::Grasp, EventPhase::Begin,
                  0.4),
        makeEvent(2.5, Gripper::Right, 2, DetectorKind::Slip, Message::Slip, EventPhase::Begin,
                  0.9),
        makeEvent(3.0, Gripper::Right, 1, DetectorKind::Force, Message::Break, EventPhase::Begin,
                  1.0),
        makeEvent(3.2, Gripper::Right, 1, DetectorKind::Force, Message::Break, EventPhase::End,
                  0.8),
        makeEvent(4.0, Gripper::Left, 0, DetectorKind::Force, Message::Grasp, EventPhase::End,
                  0.3),
    };
    return events;
}

void startRun(RunHistory &history)
{
    history.start({}, {}, {"left.force", "right.force", "right.slip"});
}

void append(RunHistory &history, size_t from, size_t to)
{
    for (size_t i = from; i < to; ++i)
        history.append(run()[i]);
    history.commit();
}

QStringList visibleTimes(const QTableView *view)
{
    QStringList times;
    for (int row = 0; row < view->model()->rowCount(); ++row)
        times.append(view->model()->index(row, EventLogModel::TimeColumn).data().toString());
    return times;
}

/** Picks a combo box entry with the keyboard, as a user would. */
void choose(QComboBox *box, int index)
{
    box->setFocus();
    while (box->currentIndex() > index)
        QTest::keyClick(box, Qt::Key_Up);
    while (box->currentIndex() < index)
        QTest::keyClick(box, Qt::Key_Down);
}

/** Shows every phase, updates included: the panel starts on begins and ends. */
void showAllPhases(EventLogPanel &panel)
{
    choose(panel.findChild<QComboBox *>(QStringLiteral("phaseFilter")), 1);
}

} // namespace

class TestEventLog : public QObject
{
    Q_OBJECT

private slots:
    void rowsShowTheEvents();
    void appendsInOneBatchPerUpdate();
    void capKeepsTheNewest();
    void filters_data();
    void filters();
    void clickReportsTheTime();
    void longMessagesFitTheirColumn();
    void followKeepsTheNewestInView();
    void resetClears();
    void longRunStaysCapped();
    void metrics_data();
    void metrics();
    void everyDocumentedMetricHasARow();
    void metricTooltipsSayWhichWayIsBetter_data();
    void metricTooltipsSayWhichWayIsBetter();
    void metricsRowsFollowTheKeys();
    void screenshot();
};

void TestEventLog::rowsShowTheEvents()
{
    RunHistory history;
    startRun(history);
    EventLogModel model(history);
    append(history, 0, run().size());
    QCOMPARE(model.rowCount(), int(run().size()));
    const auto text = [&](int row, int column) {
        return model.index(row, column).data().toString();
    };
    QCOMPARE(text(3, EventLogModel::TimeColumn), QStringLiteral("2.500"));
    QCOMPARE(text(3, EventLogModel::GripperColumn), QStringLiteral("right"));
    QCOMPARE(text(3, EventLogModel::DetectorColumn), QStringLiteral("right.slip (slip)"));
    QCOMPARE(text(3, EventLogModel::MessageColumn), QStringLiteral("slip"));
    QCOMPARE(text(3, EventLogModel::PhaseColumn), QStringLiteral("begin"));
    QCOMPARE(text(3, EventLogModel::IntensityColumn), QStringLiteral("0.90"));
    QCOMPARE(text(1, EventLogModel::PhaseColumn), QStringLiteral("update"));
    // The category is a coloured shape and words, never the colour alone.
    const QModelIndex message = model.index(3, EventLogModel::MessageColumn);
    QVERIFY(!message.data(Qt::DecorationRole).value<QPixmap>().isNull());
    QVERIFY(message.data(Qt::ToolTipRole).toString().contains(QStringLiteral("exception")));
    QCOMPARE(model.index(0, EventLogModel::MessageColumn).data(Qt::ToolTipRole).toString(),
             QStringLiteral("grasp: confirmation"));
    QCOMPARE(colors::category(Category::Exception), colors::Orange);
}

void TestEventLog::appendsInOneBatchPerUpdate()
{
    RunHistory history;
    startRun(history);
    EventLogModel model(history);
    QSignalSpy inserted(&model, &QAbstractItemModel::rowsInserted);
    append(history, 0, 3);
    append(history, 3, run().size());
    QCOMPARE(inserted.count(), 2);
    QCOMPARE(inserted[1][1].toInt(), 3);
    QCOMPARE(inserted[1][2].toInt(), int(run().size()) - 1);
    // An update without events inserts nothing.
    history.append(ContactFrame{});
    history.commit();
    QCOMPARE(inserted.count(), 2);
}

void TestEventLog::capKeepsTheNewest()
{
    RunHistory history;
    startRun(history);
    EventLogModel model(history);
    model.setMaxRows(5);
    append(history, 0, 4);
    append(history, 4, run().size());
    QCOMPARE(model.rowCount(), 5);
    QCOMPARE(model.index(0, EventLogModel::TimeColumn).data().toString(), QStringLiteral("1.000"));
    QCOMPARE(model.index(4, EventLogModel::TimeColumn).data().toString(), QStringLiteral("4.000"));
}

void TestEventLog::filters_data()
{
    QTest::addColumn<int>("gripper");  ///< combo index: all, left, right
    QTest::addColumn<int>("category"); ///< all, confirmation, exception
    QTest::addColumn<int>("phase");    ///< begin and end (the default), all, begin, update, end
    QTest::addColumn<QString>("text");
    QTest::addColumn<QStringList>("times");
    const QStringList all = {"0.100", "0.250", "1.000", "2.500", "3.000", "3.200", "4.000"};
    QTest::newRow("by default, no updates")
        << 0 << 0 << 0 << "" << QStringList{"0.100", "1.000", "2.500", "3.000", "3.200", "4.000"};
    QTest::newRow("everything") << 0 << 0 << 1 << "" << all;
    QTest::newRow("left") << 1 << 0 << 1 << "" << QStringList{"1.000", "4.000"};
    QTest::newRow("right") << 2 << 0 << 1 << ""
                           << QStringList{"0.100", "0.250", "2.500", "3.000", "3.200"};
    QTest::newRow("confirmations")
        << 0 << 1 << 1 << "" << QStringList{"0.100", "0.250", "1.000", "4.000"};
    QTest::newRow("exceptions") << 0 << 2 << 1 << "" << QStringList{"2.500", "3.000", "3.200"};
    QTest::newRow("updates") << 0 << 0 << 3 << "" << QStringList{"0.250"};
    QTest::newRow("ends") << 0 << 0 << 4 << "" << QStringList{"3.200", "4.000"};
    QTest::newRow("text detector") << 0 << 0 << 1 << "left.FORCE" << QStringList{"1.000", "4.000"};
    QTest::newRow("text message") << 0 << 0 << 1 << "break" << QStringList{"3.000", "3.200"};
    QTest::newRow("right exception begins") << 2 << 2 << 2 << "" << QStringList{"2.500", "3.000"};
    QTest::newRow("nothing matches") << 1 << 2 << 1 << "" << QStringList{};
    QTest::newRow("no such text") << 0 << 0 << 1 << "zzz" << QStringList{};
}

void TestEventLog::filters()
{
    QFETCH(int, gripper);
    QFETCH(int, category);
    QFETCH(int, phase);
    QFETCH(QString, text);
    QFETCH(QStringList, times);
    RunHistory history;
    startRun(history);
    EventLogPanel panel(history);
    panel.resize(640, 800);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    append(history, 0, run().size());
    choose(panel.findChild<QComboBox *>(QStringLiteral("gripperFilter")), gripper);
    choose(panel.findChild<QComboBox *>(QStringLiteral("categoryFilter")), category);
    choose(panel.findChild<QComboBox *>(QStringLiteral("phaseFilter")), phase);
    QTest::keyClicks(panel.findChild<QLineEdit *>(QStringLiteral("filterText")), text);
    QCOMPARE(visibleTimes(panel.view()), times);
}

void TestEventLog::clickReportsTheTime()
{
    RunHistory history;
    startRun(history);
    EventLogPanel panel(history);
    showAllPhases(panel);
    panel.resize(640, 800);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    append(history, 0, run().size());
    QSignalSpy activated(&panel, &EventLogPanel::eventActivated);
    QTableView *view = panel.view();
    const auto click = [view](int row) {
        const QModelIndex index = view->model()->index(row, EventLogModel::MessageColumn);
        QTest::mouseClick(view->viewport(), Qt::LeftButton, {}, view->visualRect(index).center());
    };
    click(3);
    QCOMPARE(activated.count(), 1);
    QCOMPARE(activated.last()[0].toDouble(), 2.5);
    click(3); // again: the plots' cursor may have moved meanwhile
    QCOMPARE(activated.count(), 2);
    click(5);
    QCOMPARE(activated.count(), 3);
    QCOMPARE(activated.last()[0].toDouble(), 3.2);
    QTest::keyClick(view, Qt::Key_Down);
    QCOMPARE(activated.count(), 4);
    QCOMPARE(activated.last()[0].toDouble(), 4.0);
}

void TestEventLog::longMessagesFitTheirColumn()
{
    // A router's own message is longer than "break": its column grows to show it whole.
    RunHistory history;
    startRun(history);
    EventLogPanel panel(history);
    panel.resize(640, 400);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    QHeaderView *header = panel.view()->horizontalHeader();
    const int before = header->sectionSize(EventLogModel::MessageColumn);
    Message collision = Message::Grasp;
    QVERIFY(messageFromName("plug.collision_imminent", &collision));
    SemanticEvent e = makeEvent(0.5, Gripper::Right, 2, DetectorKind::Compose, collision,
                                EventPhase::Begin, 1.0);
    e.category = Category::Exception;
    history.append(e);
    history.commit();
    QTRY_COMPARE(panel.view()->model()->rowCount(), 1);
    const int text = panel.fontMetrics().horizontalAdvance("plug.collision_imminent");
    QVERIFY2(header->sectionSize(EventLogModel::MessageColumn) > text,
             qPrintable(QString::number(header->sectionSize(EventLogModel::MessageColumn))));
    QVERIFY(header->sectionSize(EventLogModel::MessageColumn) > before);
}

void TestEventLog::followKeepsTheNewestInView()
{
    RunHistory history;
    startRun(history);
    EventLogPanel panel(history);
    showAllPhases(panel);
    panel.resize(420, 600);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    const auto burst = [&history](double from) {
        for (int i = 0; i < 100; ++i)
            history.append(makeEvent(from + i * 0.01, Gripper::Right, 1, DetectorKind::Force,
                                     Message::Grasp, EventPhase::Update, 0.5));
        history.commit();
    };
    QScrollBar *bar = panel.view()->verticalScrollBar();
    burst(0.0);
    QVERIFY(bar->maximum() > 0);
    QCOMPARE(bar->value(), bar->maximum());
    auto *follow = panel.findChild<QCheckBox *>(QStringLiteral("follow"));
    QTest::mouseClick(follow, Qt::LeftButton, {}, QPoint(4, follow->height() / 2));
    QVERIFY(!follow->isChecked());
    bar->setValue(0);
    burst(1.0);
    QCOMPARE(bar->value(), 0);
}

void TestEventLog::resetClears()
{
    RunHistory history;
    startRun(history);
    EventLogPanel panel(history);
    showAllPhases(panel);
    append(history, 0, run().size());
    QCOMPARE(panel.view()->model()->rowCount(), int(run().size()));
    startRun(history);
    QCOMPARE(panel.view()->model()->rowCount(), 0);
    append(history, 2, 3);
    QCOMPARE(visibleTimes(panel.view()), QStringList{"1.000"});
}

void TestEventLog::longRunStaysCapped()
{
    RunHistory history;
    startRun(history);
    EventLogPanel panel(history);
    showAllPhases(panel);
    panel.resize(640, 800);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    QElapsedTimer clock;
    clock.start();
    const int updates = 300;
    for (int u = 0; u < updates; ++u) {
        for (int i = 0; i < 50; ++i)
            history.append(makeEvent(u * 0.05 + i * 0.001, Gripper::Right, 1, DetectorKind::Force,
                                     Message::Grasp, EventPhase::Update, 0.5));
        history.commit();
        QCoreApplication::processEvents();
    }
    const double perUpdateMs = double(clock.elapsed()) / updates;
    qInfo("%d events in %d updates: %.2f ms per update, repaints included", updates * 50, updates,
          perUpdateMs);
    QCOMPARE(panel.model()->rowCount(), panel.model()->maxRows());
    QCOMPARE(panel.model()->maxRows(), 10000);
    QCOMPARE(panel.view()->verticalScrollBar()->value(),
             panel.view()->verticalScrollBar()->maximum());
}

void TestEventLog::metrics_data()
{
    QTest::addColumn<QString>("key");
    QTest::addColumn<QJsonValue>("value");
    QTest::addColumn<QString>("label");
    QTest::addColumn<QString>("text");
    QTest::newRow("count") << "cubes_transferred" << QJsonValue(3) << "Cubes transferred"
                           << "3";
    QTest::newRow("count as double") << "cubes_broken" << QJsonValue(2.0) << "Cubes broken"
                                     << "2";
    QTest::newRow("slips") << "cubes_dropped" << QJsonValue(1) << "Cubes dropped (slipped out)"
                           << "1";
    QTest::newRow("ratio") << "grasps_per_transfer" << QJsonValue(5.0 / 3.0)
                           << "Grasps per transfer"
                           << "1.67";
    QTest::newRow("seconds") << "warning_lead_time" << QJsonValue(0.4321) << "Warning lead time"
                             << "0.43 s";
    QTest::newRow("force") << "average_grasp_force" << QJsonValue(12.345) << "Average grasp force"
                           << "12.35 N";
    QTest::newRow("share") << "breaks_warned_share" << QJsonValue(0.5) << "Breaks warned"
                           << "50 %";
    QTest::newRow("mean of nothing")
        << "average_peak_grasp_force" << QJsonValue() << "Average peak grasp force"
        << "n/a";
    QTest::newRow("factor") << "realtime_factor" << QJsonValue(28.96) << "Real-time factor"
                            << "28.96×";
    QTest::newRow("text") << "router" << QJsonValue("C3") << "Router"
                          << "C3";
    QTest::newRow("usb insertions") << "insertions" << QJsonValue(3) << "Plugs inserted"
                                    << "3";
    QTest::newRow("usb time") << "time_to_insert" << QJsonValue(6.5) << "Time to insert"
                              << "6.50 s";
    QTest::newRow("usb collisions") << "collisions" << QJsonValue(2) << "Collisions with the port"
                                    << "2";
    QTest::newRow("usb force") << "peak_insertion_force" << QJsonValue(9.876)
                               << "Peak insertion force"
                               << "9.88 N";
    // dish_wiping's (docs/metrics.md).
    QTest::newRow("area cleaned") << "area_cleaned" << QJsonValue(3.0555)
                                  << "Area cleaned (plates)"
                                  << "3.06";
    QTest::newRow("time to clean: not yet") << "time_to_clean" << QJsonValue() << "Time to clean"
                                            << "n/a";
    QTest::newRow("peak force") << "peak_force" << QJsonValue(40.218) << "Peak force"
                                << "40.22 N";
    QTest::newRow("above the safe force")
        << "time_above_safe_force" << QJsonValue(17.566) << "Time above the safe force"
        << "17.57 s";
    QTest::newRow("plates broken") << "plates_broken" << QJsonValue(2) << "Plates broken"
                                   << "2";
    // The perceiving operator's own counts.
    QTest::newRow("cues misread") << "cues_misread" << QJsonValue(3) << "Cues misread"
                                  << "3";
    QTest::newRow("reliance") << "left_reliance" << QJsonValue(0.729) << "Left reliance"
                              << "73 %";
    QTest::newRow("unknown count") << "retries" << QJsonValue(4) << "retries"
                                   << "4";
    QTest::newRow("unknown rate") << "transfers_per_minute" << QJsonValue(2.456)
                                  << "transfers_per_minute"
                                  << "2.46";
    QTest::newRow("unknown seconds") << "idle_seconds" << QJsonValue(3.0) << "idle_seconds"
                                     << "3.00 s";
}

void TestEventLog::metrics()
{
    QFETCH(QString, key);
    QFETCH(QJsonValue, value);
    QFETCH(QString, label);
    QFETCH(QString, text);
    RunHistory history;
    MetricsPanel panel(history);
    history.setMetrics(QJsonObject{{key, value}});
    auto *shown = panel.findChild<QLabel *>(key);
    QVERIFY(shown);
    QCOMPARE(shown->text(), text);
    QCOMPARE(MetricsPanel::label(key), label);
    const QList<QLabel *> labels = panel.findChildren<QLabel *>();
    QVERIFY(std::any_of(labels.begin(), labels.end(),
                        [&](const QLabel *l) { return l->text() == label; }));
}

void TestEventLog::everyDocumentedMetricHasARow()
{
    // docs/metrics.md's tables (the names in their first column) and the metric table
    // (MetricSpec) hold the same metrics, and each reads as words in the panel, not as its key.
    QFile doc(QStringLiteral(SEMHAP_METRICS_DOC));
    QVERIFY(doc.open(QIODevice::ReadOnly));
    const QRegularExpression row(QStringLiteral("^\\| ([^|]+)\\|"),
                                 QRegularExpression::MultilineOption);
    const QRegularExpression name(QStringLiteral("`([a-z_]+)`"));
    QStringList documented;
    for (const auto &cell : row.globalMatch(QString::fromUtf8(doc.readAll()))) {
        for (const auto &match : name.globalMatch(cell.captured(1)))
            documented << match.captured(1);
    }
    QStringList registered;
    QStringList unnamed;
    for (const MetricSpec &spec : MetricSpec::all()) {
        registered << QString::fromUtf8(spec.name);
        if (MetricsPanel::label(registered.last()) == registered.last())
            unnamed << registered.last();
    }
    QStringList undocumented;
    for (const QString &key : registered) {
        if (!documented.contains(key))
            undocumented << key;
    }
    QStringList unregistered;
    for (const QString &key : documented) {
        if (!registered.contains(key))
            unregistered << key;
    }
    QVERIFY(registered.size() > 40);
    QVERIFY2(undocumented.isEmpty(), qPrintable(undocumented.join(QStringLiteral(", "))));
    QVERIFY2(unregistered.isEmpty(), qPrintable(unregistered.join(QStringLiteral(", "))));
    QVERIFY2(unnamed.isEmpty(), qPrintable(unnamed.join(QStringLiteral(", "))));
    QCOMPARE(registered.removeDuplicates(), 0);
}

void TestEventLog::metricTooltipsSayWhichWayIsBetter_data()
{
    QTest::addColumn<QString>("key");
    QTest::addColumn<QString>("better");
    QTest::newRow("fewer breaks") << "cubes_broken"
                                  << "Lower is better.";
    QTest::newRow("more transfers") << "cubes_transferred"
                                    << "Higher is better.";
    QTest::newRow("grasps describe") << "grasps"
                                     << "";
    QTest::newRow("the machine's speed") << "realtime_factor"
                                         << "";
}

void TestEventLog::metricTooltipsSayWhichWayIsBetter()
{
    QFETCH(QString, key);
    QFETCH(QString, better);
    const QString tooltip = MetricsPanel::tooltip(key);
    QVERIFY2(tooltip.endsWith(QStringLiteral("in exports: ") + key), qPrintable(tooltip));
    if (better.isEmpty())
        QVERIFY2(!tooltip.contains(QStringLiteral("is better")), qPrintable(tooltip));
    else
        QVERIFY2(tooltip.contains(better), qPrintable(tooltip));
}

void TestEventLog::metricsRowsFollowTheKeys()
{
    RunHistory history;
    MetricsPanel panel(history);
    history.setMetrics(
        QJsonObject{{"grasps", 1}, {"custom", QJsonObject{{"left", 2}, {"right", 0.25}}}});
    QCOMPARE(panel.findChild<QLabel *>(QStringLiteral("custom.left"))->text(),
             QStringLiteral("2"));
    QCOMPARE(panel.findChild<QLabel *>(QStringLiteral("custom.right"))->text(),
             QStringLiteral("0.25"));
    // The same keys: values change in place.
    QLabel *grasps = panel.findChild<QLabel *>(QStringLiteral("grasps"));
    history.setMetrics(
        QJsonObject{{"grasps", 2}, {"custom", QJsonObject{{"left", 2}, {"right", 0.25}}}});
    QCOMPARE(panel.findChild<QLabel *>(QStringLiteral("grasps")), grasps);
    QCOMPARE(grasps->text(), QStringLiteral("2"));
    // A new run forgets them.
    history.start({}, {}, {});
    QTRY_VERIFY(!panel.findChild<QLabel *>(QStringLiteral("custom.left")));
}

/** With SEMHAP_SCREENSHOTS=DIR: the log and the metrics of a minute's run, for the docs. */
void TestEventLog::screenshot()
{
    const QString dir = qEnvironmentVariable("SEMHAP_SCREENSHOTS");
    if (dir.isEmpty())
        QSKIP("set SEMHAP_SCREENSHOTS to a folder to write the screenshot");
    RunHistory history;
    startRun(history);
    EventLogPanel log(history);
    MetricsPanel metrics(history);
    // Cycles of a transfer: grasp with updates, now and then a slip or a break warning.
    for (int cycle = 0; cycle < 12; ++cycle) {
        const double t0 = cycle * 4.7;
        const Gripper hand = cycle % 3 == 2 ? Gripper::Left : Gripper::Right;
        const int node = hand == Gripper::Left ? 0 : 1;
        history.append(makeEvent(t0, hand, node, DetectorKind::Force, Message::Grasp,
                                 EventPhase::Begin, 0.42));
        history.append(makeEvent(t0 + 0.35, hand, node, DetectorKind::Force, Message::Grasp,
                                 EventPhase::Update, 0.61));
        if (cycle % 4 == 1) {
            history.append(makeEvent(t0 + 1.2, Gripper::Right, 2, DetectorKind::Slip,
                                     Message::Slip, EventPhase::Begin, 0.73));
            history.append(makeEvent(t0 + 1.55, Gripper::Right, 2, DetectorKind::Slip,
                                     Message::Slip, EventPhase::End, 0.2));
        }
        if (cycle % 5 == 3) {
            history.append(makeEvent(t0 + 1.8, hand, node, DetectorKind::Force, Message::Break,
                                     EventPhase::Begin, 0.88));
            history.append(makeEvent(t0 + 2.1, hand, node, DetectorKind::Force, Message::Break,
                                     EventPhase::End, 1.0));
        }
        history.append(makeEvent(t0 + 2.9, hand, node, DetectorKind::Force, Message::Grasp,
                                 EventPhase::End, 0.35));
        history.commit();
    }
    history.setMetrics(QJsonObject{{"cubes_transferred", 9},
                                   {"cubes_dropped", 1},
                                   {"cubes_broken", 2},
                                   {"grasps", 12},
                                   {"average_grasp_force", 6.834},
                                   {"grasps_per_transfer", 12.0 / 9.0},
                                   {"average_peak_grasp_force", 11.27},
                                   {"warning_lead_time", 0.412},
                                   {"breaks_warned_share", 0.5},
                                   {"breaks_warned_in_time_share", 0.0},
                                   {"containers_dropped", 4},
                                   {"drop_warning_lead_time", 1.73},
                                   {"drops_warned_share", 1.0},
                                   {"drops_warned_in_time_share", 0.75},
                                   {"confirmations_per_grasp", 1.04},
                                   {"slip_episodes", 12},
                                   {"warnings_per_slip_episode", 0.58},
                                   {"box_refills", 0},
                                   {"sim_seconds", 56.4},
                                   {"wall_seconds", 57.1},
                                   {"realtime_factor", 0.988},
                                   {"scene", "box_and_block"},
                                   {"router", "C3"},
                                   {"cues_taken_in", 31},
                                   {"cues_misread", 2},
                                   {"warnings_ignored", 4},
                                   {"right_reliance", 0.81},
                                   {"operator", "perceiving"},
                                   {"seed", 7}});
    // The metrics' labels in German too: they are the longest strings of the panel.
    QTranslator german;
    QVERIFY(german.load(QLocale(QLocale::German), "semhap", "_", ":/i18n"));
    QCoreApplication::installTranslator(&german);
    MetricsPanel metricsDe(history);
    metricsDe.resize(420, 800);
    metricsDe.show();
    QVERIFY(QTest::qWaitForWindowExposed(&metricsDe));
    QVERIFY(metricsDe.grab().save(dir + "/metrics-de-420x800.png"));
    // A label's tooltip: the help, the unit, which way is better, the key (German).
    QLabel *brokenLabel = nullptr;
    for (QLabel *label : metricsDe.findChildren<QLabel *>()) {
        if (label->text() == MetricsPanel::label(QStringLiteral("cubes_broken")))
            brokenLabel = label;
    }
    QVERIFY(brokenLabel);
    QToolTip::showText(brokenLabel->mapToGlobal(QPoint(0, brokenLabel->height())),
                       brokenLabel->toolTip(), brokenLabel);
    QTest::qWait(400);
    const QPoint corner = metricsDe.mapToGlobal(QPoint(0, 0));
    QVERIFY(QGuiApplication::primaryScreen()
                ->grabWindow(0, corner.x(), corner.y(), 700, 300)
                .save(dir + "/metrics-tooltip-de.png"));
    QToolTip::hideText();
    QCoreApplication::removeTranslator(&german);
    for (const QSize size : {QSize(420, 600), QSize(640, 800)}) {
        for (QWidget *panel : {static_cast<QWidget *>(&log), static_cast<QWidget *>(&metrics)}) {
            panel->resize(size);
            panel->show();
            QVERIFY(QTest::qWaitForWindowExposed(panel));
            const QString name =
                panel == &log ? QStringLiteral("eventlog") : QStringLiteral("metrics");
            QVERIFY(panel->grab().save(QStringLiteral("%1/%2-%3x%4.png")
                                           .arg(dir, name)
                                           .arg(size.width())
                                           .arg(size.height())));
        }
    }
}

QTEST_MAIN(TestEventLog)
#include "tst_eventlog.moc"
