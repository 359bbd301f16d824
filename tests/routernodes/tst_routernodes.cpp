// SPDX-License-Identifier: MIT
// The logic nodes of the router, driven directly with events: what passes, when, and how.
#include "patternlibrary.h"
#include "routernodes.h"

#include <QLocale>
#include <QTest>

using namespace semhap;

namespace {

/** Records what reaches it as "t message phase intensity". */
class Recorder : public RuntimeNode
{
public:
    void onEvent(int, const SemanticEvent &e) override
    {
        seen.append(QStringList{QString::number(e.t, 'g', QLocale::FloatingPointShortest),
                                messageName(e.message), eventPhaseName(e.phase),
                                QString::number(e.intensity, 'g', QLocale::FloatingPointShortest)}
                        .join(' '));
    }
    QStringList seen;
};

/** An event of detector node `node`, e.g. makeEvent(1.0, 0, "break", "begin", 0.5). */
SemanticEvent makeEvent(double t, int node, const QString &message, const QString &phase,
                        double intensity = 1.0, Gripper gripper = Gripper::Right)
{
    SemanticEvent e;
    e.t = t;
    e.node = node;
    e.gripper = gripper;
    messageFromName(message, &e.message);
    e.category = categoryOf(e.message);
    eventPhaseFromName(phase, &e.phase);
    e.intensity = intensity;
    return e;
}

/** Feeds "t node message phase intensity" lines to port 0 (or port 1 with a "c " prefix). */
void feed(RuntimeNode &node, const QStringList &lines)
{
    for (const QString &line : lines) {
        QStringList parts = line.split(' ');
        int port = 0;
        if (parts.first() == "c") {
            port = 1;
            parts.removeFirst();
        }
        if (parts.first() == "timer") {
            node.fireTimers(parts[1].toDouble());
            continue;
        }
        node.onEvent(port, makeEvent(parts[0].toDouble(), parts[1].toInt(), parts[2], parts[3],
                                     parts.size() > 4 ? parts[4].toDouble() : 1.0));
    }
}

} // namespace

class TestRouterNodes : public QObject
{
    Q_OBJECT

private slots:
    void filter_data();
    void filter();
    void gate_data();
    void gate();
    void hysteresis_data();
    void hysteresis();
    void curve();
    void patternNodeMergesMessages();
    void continuousPatternStartsAtStart();
    void activeMessagesKeepOrder();
};

void TestRouterNodes::filter_data()
{
    QTest::addColumn<unsigned>("messages");
    QTest::addColumn<unsigned>("categories");
    QTest::addColumn<unsigned>("grippers");
    QTest::addColumn<QStringList>("expected");
    const unsigned grasp = 1u << unsigned(Message::Grasp);
    const unsigned brk = 1u << unsigned(Message::Break);
    const unsigned exception = 1u << unsigned(Category::Exception);
    const unsigned left = 1u << unsigned(Gripper::Left);
    QTest::newRow("everything") << 0u << 0u << 0u
                                << QStringList{"1 grasp begin 1", "2 break begin 0.5"};
    QTest::newRow("grasp") << grasp << 0u << 0u << QStringList{"1 grasp begin 1"};
    QTest::newRow("grasp or break")
        << (grasp | brk) << 0u << 0u << QStringList{"1 grasp begin 1", "2 break begin 0.5"};
    QTest::newRow("exceptions") << 0u << exception << 0u << QStringList{"2 break begin 0.5"};
    QTest::newRow("left gripper only") << 0u << 0u << left << QStringList{};
    QTest::newRow("grasp and exception") << grasp << exception << 0u << QStringList{};
}

void TestRouterNodes::filter()
{
    QFETCH(unsigned, messages);
    QFETCH(unsigned, categories);
    QFETCH(unsigned, grippers);
    QFETCH(QStringList, expected);
    FilterNode node(messages, categories, grippers);
    Recorder out;
    node.eventTargets.push_back({&out, 0});
    feed(node, {"1 0 grasp begin", "2 0 break begin 0.5"});
    QCOMPARE(out.seen, expected);
}

void TestRouterNodes::gate_data()
{
    QTest::addColumn<bool>("openOnControl");
    QTest::addColumn<QStringList>("input");
    QTest::addColumn<QStringList>("expected");
    // Port 0: a confirmation; control (c): a break warning of another detector.
    QTest::newRow("block: passes while no control")
        << false << QStringList{"1 0 grasp begin", "2 0 grasp end"}
        << QStringList{"1 grasp begin 1", "2 grasp end 1"};
    QTest::newRow("block: control ends and resumes")
        << false
        << QStringList{"1 0 grasp begin", "c 2 1 break begin 0.3", "3 0 grasp update 0.8",
                       "c 4 1 break end 0.3", "5 0 grasp end 0.8"}
        << QStringList{"1 grasp begin 1", "2 grasp end 1", "4 grasp begin 0.8", "5 grasp end 0.8"};
    QTest::newRow("block: message ends while blocked")
        << false
        << QStringList{"c 1 1 break begin", "2 0 grasp begin", "3 0 grasp end", "c 4 1 break end"}
        << QStringList{};
    QTest::newRow("open: passes only during control")
        << true
        << QStringList{"1 0 grasp begin", "c 2 1 break begin", "c 3 1 break end", "4 0 grasp end"}
        << QStringList{"2 grasp begin 1", "3 grasp end 1"};
    QTest::newRow("two control messages keep it closed")
        << false
        << QStringList{"c 1 1 break begin", "c 1 2 slip begin", "2 0 grasp begin",
                       "c 3 1 break end", "c 4 2 slip end"}
        << QStringList{"4 grasp begin 1"};
}

void TestRouterNodes::gate()
{
    QFETCH(bool, openOnControl);
    QFETCH(QStringList, input);
    QFETCH(QStringList, expected);
    GateNode node(openOnControl);
    Recorder out;
    node.eventTargets.push_back({&out, 0});
    feed(node, input);
    QCOMPARE(out.seen, expected);
}

void TestRouterNodes::hysteresis_data()
{
    QTest::addColumn<double>("hold");
    QTest::addColumn<double>("band");
    QTest::addColumn<QStringList>("input");
    QTest::addColumn<QStringList>("expected");
    QTest::addColumn<double>("nextTimer");
    const double never = std::numeric_limits<double>::infinity();
    QTest::newRow("defaults pass everything")
        << 0.0 << 0.0
        << QStringList{"1 0 break begin 0.2", "2 0 break update 0.21", "3 0 break end 0.21"}
        << QStringList{"1 break begin 0.2", "2 break update 0.21", "3 break end 0.21"} << never;
    QTest::newRow("hold delays the end")
        << 0.5 << 0.0 << QStringList{"1 0 break begin 0.2", "2 0 break end 0.2"}
        << QStringList{"1 break begin 0.2"} << 2.5;
    QTest::newRow("hold fires at its time")
        << 0.5 << 0.0 << QStringList{"1 0 break begin 0.2", "2 0 break end 0.2", "timer 2.5"}
        << QStringList{"1 break begin 0.2", "2.5 break end 0.2"} << never;
    QTest::newRow("begin within hold continues")
        << 0.5 << 0.0
        << QStringList{"1 0 break begin 0.2", "2 0 break end 0.2", "2.2 0 break begin 0.4",
                       "timer 2.5"}
        << QStringList{"1 break begin 0.2", "2.2 break update 0.4"} << never;
    QTest::newRow("begin at same intensity is silent")
        << 0.5 << 0.0
        << QStringList{"1 0 break begin 0.2", "2 0 break end 0.2", "2.2 0 break begin 0.2"}
        << QStringList{"1 break begin 0.2"} << never;
    QTest::newRow("band drops small updates")
        << 0.0 << 0.1
        << QStringList{"1 0 break begin 0.2",   "2 0 break update 0.25", "3 0 break update 0.31",
                       "4 0 break update 0.95", "5 0 break update 1",    "6 0 break end 1"}
        << QStringList{"1 break begin 0.2", "3 break update 0.31", "4 break update 0.95",
                       "5 break update 1", "6 break end 1"}
        << never;
    QTest::newRow("end carries the last passed intensity")
        << 0.0 << 0.1
        << QStringList{"1 0 break begin 0.2", "2 0 break update 0.25", "3 0 break end 0.25"}
        << QStringList{"1 break begin 0.2", "3 break end 0.2"} << never;
}

void TestRouterNodes::hysteresis()
{
    QFETCH(double, hold);
    QFETCH(double, band);
    QFETCH(QStringList, input);
    QFETCH(QStringList, expected);
    QFETCH(double, nextTimer);
    HysteresisNode node(hold, band);
    Recorder out;
    node.eventTargets.push_back({&out, 0});
    feed(node, input);
    QCOMPARE(out.seen, expected);
    QCOMPARE(node.nextTimer(), nextTimer);
}

void TestRouterNodes::curve()
{
    // A dead zone below 0.5, then full scale: low urgency is not worth a warning's loudness.
    CurveNode node(Curve::points({{0.5, 0.0}, {1.0, 1.0}}));
    Recorder out;
    node.eventTargets.push_back({&out, 0});
    feed(node, {"1 0 break begin 0.1", "2 0 break update 0.3", "3 0 break update 0.75",
                "4 0 break update 2", "5 0 break end 0.9"});
    QCOMPARE(out.seen, (QStringList{"1 break begin 0", "3 break update 0.5", "4 break update 1",
                                    "5 break end 1"}));
}

void TestRouterNodes::patternNodeMergesMessages()
{
    PatternNode node(PatternLibrary::builtin("vib.geiger"), false);
    node.voices.push_back(std::make_unique<VoiceInput>(PatternLibrary::builtin("vib.geiger")));
    Voice &voice = node.voices.front()->voice;
    node.start(0.0);
    QVERIFY(voice.isIdle());

    node.onEvent(0, makeEvent(1.0, 0, "break", "begin", 0.3));
    QVERIFY(voice.isActive());
    QCOMPARE(voice.param(ParamTable::Intensity), 0.3);
    QCOMPARE(node.voices.front()->priority(), PlayerInput::Exception);
    node.onEvent(0, makeEvent(1.1, 1, "slip", "begin", 0.6));
    QCOMPARE(voice.param(ParamTable::Intensity), 0.6);
    node.onEvent(0, makeEvent(1.2, 1, "slip", "update", 0.2));
    QCOMPARE(voice.param(ParamTable::Intensity), 0.3);
    node.onEvent(0, makeEvent(1.3, 0, "break", "end", 0.3));
    QVERIFY(voice.isActive());
    QCOMPARE(voice.param(ParamTable::Intensity), 0.2);
    node.onEvent(0, makeEvent(1.4, 1, "slip", "end", 0.2));
    QVERIFY(!voice.isActive());
}

void TestRouterNodes::continuousPatternStartsAtStart()
{
    const PatternPtr pattern = PatternLibrary::builtin("air.proportional");
    PatternNode node(pattern, true);
    node.voices.push_back(std::make_unique<VoiceInput>(pattern));
    node.signalParams = {-1, pattern->params().indexOf("left")};
    Voice &voice = node.voices.front()->voice;
    node.start(2.0);
    QVERIFY(voice.isActive());
    QCOMPARE(node.voices.front()->priority(), PlayerInput::Continuous);
    node.onSignal(1, 60.0, 2.5);
    voice.advance(2.5);
    QCOMPARE(voice.value(0), 0.5); // 60 N of the default ref 120 N
}

void TestRouterNodes::activeMessagesKeepOrder()
{
    ActiveMessages set;
    for (int key = 0; key < ActiveMessages::Capacity; ++key)
        QVERIFY(set.insert(key));
    QVERIFY(!set.insert(100));
    QCOMPARE(set.insert(3), set.find(3));
    set.remove(3);
    QCOMPARE(set.size(), ActiveMessages::Capacity - 1);
    int previous = -1;
    for (const ActiveMessages::Entry &entry : set) {
        QVERIFY(entry.key > previous);
        QVERIFY(entry.key != 3);
        previous = entry.key;
    }
}

QTEST_GUILESS_MAIN(TestRouterNodes)
#include "tst_routernodes.moc"
