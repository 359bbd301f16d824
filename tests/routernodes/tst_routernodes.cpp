// SPDX-License-Identifier: MIT
// The logic nodes of the router, driven directly with events: what passes, when, and how.
#include "patternlibrary.h"
#include "routernodes.h"

#include <QLocale>

#include <cmath>
#include <QTest>
#include <tuple>

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

/** Records the signal values that reach it. */
class SignalRecorder : public RuntimeNode
{
public:
    void onSignal(int, double value, double) override { values.push_back(value); }
    std::vector<double> values;
};

/** A slip warning from 80 % of the friction available, C3p's, recording what it sends. */
struct FrictionMargin
{
    static ThresholdNode::Params params()
    {
        ThresholdNode::Params p;
        p.message = Message::Slip;
        p.begin = p.end = 0.8;
        p.mapsIntensity = true;
        p.intensityFrom = 0.8;
        p.intensityTo = 1.0;
        return p;
    }
    FrictionMargin()
    {
        node.eventTargets.push_back({&out, 0});
        node.setOutput(&events);
    }
    ThresholdNode node{0, Gripper::Left, params()};
    Recorder out;
    EventBuffer events;
};

/** A fingertip pressing with `normal` N along the grip axis and `tangential` N across it. */
Fingertip pressing(double normal, double tangential, double mu)
{
    Fingertip tip;
    tip.f = std::hypot(normal, tangential);
    tip.n = 16;
    tip.actor = 0;
    tip.hasFxyz = true;
    tip.fxyz = {tangential * 0.6, -normal, tangential * 0.8};
    tip.mu = mu;
    return tip;
}

/** An event of detector node `node`, e.g. makeEvent(1.0, 0, "break", "begin", 0.5). */
SemanticEvent makeEvent(double t, int node, const QString &message, const QString &phase,
                        double intensity = 1.0, Gripper gripper = Gripper::Right)
{
    SemanticEvent e;
    e.t = t;
    e.node = node;
    e.gripper = gripper;
    messageFromName(message, &e.message);
    // A new message is a confirmation here, as "aligned" would be.
    e.category = isBuiltinMessage(e.message) ? categoryOf(e.message) : Category::Confirmation;
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
    void debounce_data();
    void debounce();
    void curve();
    void patternNodeMergesMessages();
    void continuousPatternStartsAtStart();
    void activeMessagesKeepOrder();
    void slopeOfARamp_data();
    void slopeOfARamp();
    void slopeOfAStep();
    void predictExtrapolatesOverTheHorizon();
    void threshold_data();
    void threshold();
    void thresholdIntensitySteps();
    void compose_data();
    void compose();
    void thresholdEndsOnEndAll();
    void frictionUse_data();
    void frictionUse();
    void frictionSignal();
};

void TestRouterNodes::filter_data()
{
    QTest::addColumn<unsigned>("messages");
    QTest::addColumn<unsigned>("categories");
    QTest::addColumn<unsigned>("grippers");
    QTest::addColumn<QStringList>("expected");
    const unsigned grasp = 1u << unsigned(Message::Grasp);
    const unsigned brk = 1u << unsigned(Message::Break);
    Message aligned = Message::Grasp;
    QVERIFY(messageFromName("aligned", &aligned));
    const unsigned alignedOnly = 1u << 5; // a new message: the test's own bit for it
    const unsigned exception = 1u << unsigned(Category::Exception);
    const unsigned left = 1u << unsigned(Gripper::Left);
    QTest::newRow("everything") << 0u << 0u << 0u
                                << QStringList{"1 grasp begin 1", "2 break begin 0.5",
                                               "3 aligned begin 1"};
    QTest::newRow("grasp") << grasp << 0u << 0u << QStringList{"1 grasp begin 1"};
    QTest::newRow("grasp or break")
        << (grasp | brk) << 0u << 0u << QStringList{"1 grasp begin 1", "2 break begin 0.5"};
    QTest::newRow("exceptions") << 0u << exception << 0u << QStringList{"2 break begin 0.5"};
    QTest::newRow("left gripper only") << 0u << 0u << left << QStringList{};
    QTest::newRow("grasp and exception") << grasp << exception << 0u << QStringList{};
    QTest::newRow("a new message passes by name")
        << alignedOnly << 0u << 0u << QStringList{"3 aligned begin 1"};
}

void TestRouterNodes::filter()
{
    QFETCH(unsigned, messages);
    QFETCH(unsigned, categories);
    QFETCH(unsigned, grippers);
    QFETCH(QStringList, expected);
    std::vector<Message> list;
    Message aligned = Message::Grasp;
    messageFromName("aligned", &aligned);
    for (Message m : {Message::Grasp, Message::Break}) {
        if (messages & (1u << unsigned(m)))
            list.push_back(m);
    }
    if (messages & (1u << 5))
        list.push_back(aligned);
    FilterNode node(list, categories, grippers);
    Recorder out;
    node.eventTargets.push_back({&out, 0});
    feed(node, {"1 0 grasp begin", "2 0 break begin 0.5", "3 0 aligned begin"});
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

void TestRouterNodes::debounce_data()
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

void TestRouterNodes::debounce()
{
    QFETCH(double, hold);
    QFETCH(double, band);
    QFETCH(QStringList, input);
    QFETCH(QStringList, expected);
    QFETCH(double, nextTimer);
    DebounceNode node(hold, band);
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
    node.voices.push_back(std::make_unique<VoiceInput>(PatternLibrary::builtin("vib.geiger"), 0));
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
    node.voices.push_back(std::make_unique<VoiceInput>(pattern, 0));
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
    MessageKey previous = -1;
    for (const ActiveMessages::Entry &entry : set) {
        QVERIFY(entry.key > previous);
        QVERIFY(entry.key != 3);
        previous = entry.key;
    }
}

void TestRouterNodes::slopeOfARamp_data()
{
    QTest::addColumn<double>("tau");
    QTest::addColumn<double>("dt");
    QTest::newRow("tau 0: the difference quotient") << 0.0 << 0.002;
    QTest::newRow("tau 50 ms, 2 ms ticks") << 0.05 << 0.002;
    QTest::newRow("tau 50 ms, 10 ms ticks") << 0.05 << 0.01;
}

void TestRouterNodes::slopeOfARamp()
{
    // x = 3 + 40 t: the slope settles on 40 within a few tau; after n ticks of dt it has come
    // 1 - e^(-(n-1) dt / tau) of the way (the first difference is the first step).
    QFETCH(double, tau);
    QFETCH(double, dt);
    SlopeFilter filter(tau);
    QCOMPARE(filter.update(3.0, 0.0), 0.0); // one sample: no slope yet
    for (int k = 1; k * dt <= 0.5 + 1e-9; ++k) {
        const double slope = filter.update(3.0 + 40.0 * k * dt, k * dt);
        const double expected = tau > 0 ? 40.0 * (1 - std::exp(-k * dt / tau)) : 40.0;
        QVERIFY2(std::abs(slope - expected) < 1e-9,
                 qPrintable(QString("%1 at %2").arg(slope).arg(k * dt)));
    }
}

void TestRouterNodes::slopeOfAStep()
{
    // A step is a steep slope for one tick; the filter spreads it and forgets it. Irregular
    // ticks weigh by their length; a repeated time changes nothing.
    SlopeFilter filter(0.05);
    filter.update(0.0, 0.0);
    const double first = filter.update(10.0, 0.002);
    QVERIFY(std::abs(first - 5000.0 * (1 - std::exp(-0.002 / 0.05))) < 1e-6);
    QCOMPARE(filter.update(99.0, 0.002), first);
    double slope = first;
    for (double t : {0.01, 0.03, 0.1, 0.8})
        slope = filter.update(10.0, t);
    QVERIFY(std::abs(slope) < 1e-3);
}

void TestRouterNodes::predictExtrapolatesOverTheHorizon()
{
    // On a ramp the prediction is the value the ramp will have `horizon` later.
    PredictNode predict(0.0);
    predict.setHorizon(0.3);
    SignalRecorder out;
    predict.signalTargets.push_back({&out, 0});
    for (int k = 0; k <= 100; ++k)
        predict.onSignal(0, 20.0 + 100.0 * k * 0.002, k * 0.002);
    QVERIFY(std::abs(out.values.back() - (20.0 + 100.0 * (0.2 + 0.3))) < 1e-9);
    QCOMPARE(out.values.front(), 20.0); // no slope yet: the value itself
}

void TestRouterNodes::threshold_data()
{
    // condition begin-low begin-high end-low end-high intensity-from intensity-to (equal: 1).
    QTest::addColumn<QString>("condition");
    QTest::addColumn<QList<double>>("levels");
    QTest::addColumn<double>("minDuration");
    QTest::addColumn<QList<double>>("inputs"); // one per 10 ms from t = 0
    QTest::addColumn<QStringList>("expected");
    QTest::newRow("above: strict, intensity to 120, ends at the level")
        << "above" << QList<double>{80, 0, 80, 0, 80, 120} << 0.0
        << QList<double>{70, 80, 90, 100, 120, 130, 80, 70}
        << QStringList{"0.02 break begin 0.25", "0.03 break update 0.5", "0.04 break update 1",
                       "0.06 break end 1"};
    QTest::newRow("above: an end level 3 below holds it")
        << "above" << QList<double>{80, 0, 77, 0, 80, 120} << 0.0 << QList<double>{81, 78, 77, 81}
        << QStringList{"0 break begin 0.03", "0.01 break update 0", "0.02 break end 0",
                       "0.03 break begin 0.03"};
    QTest::newRow("above: minDuration, begins once it has held 20 ms")
        << "above" << QList<double>{80, 0, 80, 0, 80, 120} << 0.02
        << QList<double>{90, 90, 70, 90, 90, 90} << QStringList{"0.05 break begin 0.25"};
    QTest::newRow("below: strict, a falling intensity map")
        << "below" << QList<double>{0.5, 0, 0.5, 0, 0.5, 0} << 0.0
        << QList<double>{0.6, 0.5, 0.25, 0.0, 0.7}
        << QStringList{"0.02 break begin 0.5", "0.03 break update 1", "0.04 break end 1"};
    QTest::newRow("below: an end level above holds it; no map: intensity 1")
        << "below" << QList<double>{0.1, 0, 0.2, 0, 0, 0} << 0.0
        << QList<double>{0.15, 0.05, 0.15, 0.2, 0.15}
        << QStringList{"0.01 break begin 1", "0.03 break end 1"};
    QTest::newRow("inside: both edges belong to the range")
        << "inside" << QList<double>{-1, 1, -1, 1, 0, 0} << 0.0
        << QList<double>{-2, -1, 0, 1, 1.01, 2}
        << QStringList{"0.01 break begin 1", "0.04 break end 1"};
    QTest::newRow("inside: the wider end range holds it")
        << "inside" << QList<double>{-1, 1, -2, 2, 0, 0} << 0.0
        << QList<double>{0, 1.5, -1.9, -2.1, -1.5, -0.5}
        << QStringList{"0 break begin 1", "0.03 break end 1", "0.05 break begin 1"};
    QTest::newRow("outside: strict, either side")
        << "outside" << QList<double>{-1, 1, -1, 1, 0, 0} << 0.0
        << QList<double>{0, 1, 1.01, 0, -1, -1.5}
        << QStringList{"0.02 break begin 1", "0.03 break end 1", "0.05 break begin 1"};
    QTest::newRow("outside: the narrower end range holds it")
        << "outside" << QList<double>{-1, 1, -0.5, 0.5, 0, 0} << 0.0
        << QList<double>{1.5, 0.7, 0.4, 0.9} << QStringList{"0 break begin 1", "0.02 break end 1"};
}

void TestRouterNodes::threshold()
{
    QFETCH(QString, condition);
    QFETCH(QList<double>, levels);
    QFETCH(double, minDuration);
    QFETCH(QList<double>, inputs);
    QFETCH(QStringList, expected);
    ThresholdNode::Params params;
    params.message = Message::Break;
    params.condition =
        ThresholdNode::Condition(ThresholdNode::conditionNames().indexOf(condition));
    params.begin = levels[0];
    params.beginHigh = levels[1];
    params.end = levels[2];
    params.endHigh = levels[3];
    params.mapsIntensity = levels[4] != levels[5];
    params.intensityFrom = levels[4];
    params.intensityTo = levels[5];
    params.minDuration = minDuration;
    ThresholdNode node(3, Gripper::Right, params);
    Recorder out;
    node.eventTargets.push_back({&out, 0});
    EventBuffer events;
    node.setOutput(&events);
    for (int k = 0; k < inputs.size(); ++k)
        node.onSignal(0, inputs[k], k * 0.01);
    QCOMPARE(out.seen, expected);
    // What went downstream also went into the tick's buffer, as a detector's events do.
    QCOMPARE(events.size(), int(expected.size()));
    for (const SemanticEvent &e : events) {
        QCOMPARE(e.node, 3);
        QCOMPARE(e.detector, DetectorKind::Threshold);
        QCOMPARE(e.category, Category::Exception);
    }
}

void TestRouterNodes::compose_data()
{
    // Lines as feed() takes them: "c" first for input b.
    QTest::addColumn<QString>("mode");
    QTest::addColumn<QStringList>("lines");
    QTest::addColumn<QStringList>("expected");
    QTest::newRow("all: both, the lower intensity")
        << "all"
        << QStringList{"1 0 grasp begin 0.5", "c 2 1 slip begin 0.8", "3 0 grasp update 0.3",
                       "c 4 1 slip end 0.8", "5 0 grasp end 0.3"}
        << QStringList{"2 aligned begin 0.5", "3 aligned update 0.3", "4 aligned end 0.3"};
    QTest::newRow("all: a second message on an input keeps it active")
        << "all"
        << QStringList{"1 0 grasp begin", "1 2 break begin", "c 2 1 slip begin", "3 0 grasp end",
                       "4 2 break end"}
        << QStringList{"2 aligned begin 1", "4 aligned end 1"};
    QTest::newRow("any: either, the higher intensity")
        << "any"
        << QStringList{"1 0 grasp begin 0.5", "c 2 1 slip begin 0.8", "c 3 1 slip end 0.8",
                       "4 0 grasp end 0.5"}
        << QStringList{"1 aligned begin 0.5", "2 aligned update 0.8", "3 aligned update 0.5",
                       "4 aligned end 0.5"};
    QTest::newRow("while: a's intensity, only while b")
        << "while"
        << QStringList{"c 1 1 slip begin 0.9", "2 0 grasp begin 0.4", "c 3 1 slip update 0.2",
                       "4 0 grasp update 0.6", "c 5 1 slip end 0.2",  "6 0 grasp end 0.6"}
        << QStringList{"2 aligned begin 0.4", "4 aligned update 0.6", "5 aligned end 0.6"};
    QTest::newRow("while: a alone is nothing")
        << "while" << QStringList{"1 0 grasp begin", "2 0 grasp end"} << QStringList{};
}

void TestRouterNodes::compose()
{
    QFETCH(QString, mode);
    QFETCH(QStringList, lines);
    QFETCH(QStringList, expected);
    ComposeNode::Params params;
    QVERIFY(messageFromName("aligned", &params.message));
    params.category = Category::Confirmation;
    params.mode = ComposeNode::Mode(ComposeNode::modeNames().indexOf(mode));
    ComposeNode node(7, params);
    Recorder out;
    node.eventTargets.push_back({&out, 0});
    EventBuffer events;
    node.setOutput(&events);
    feed(node, lines);
    QCOMPARE(out.seen, expected);
    QCOMPARE(events.size(), int(expected.size()));
    for (const SemanticEvent &e : events) {
        QCOMPARE(e.node, 7);
        QCOMPARE(e.detector, DetectorKind::Compose);
        QCOMPARE(e.category, Category::Confirmation);
        QCOMPARE(messageName(e.message), QStringLiteral("aligned"));
    }
}

void TestRouterNodes::thresholdIntensitySteps()
{
    // A signal that wanders by less than a step sends no updates.
    FrictionMargin margin;
    for (int k = 0; k < 50; ++k)
        margin.node.onSignal(0, 0.9 + 0.0009 * std::sin(k), k * 0.002);
    margin.node.onSignal(0, 0.95, 0.1);
    QCOMPARE(margin.out.seen, (QStringList{"0 slip begin 0.5", "0.1 slip update 0.75"}));
}

void TestRouterNodes::thresholdEndsOnEndAll()
{
    FrictionMargin margin;
    ThresholdNode &node = margin.node;
    Recorder &out = margin.out;
    node.onSignal(0, 0.9, 1.0);
    EventBuffer ends;
    node.endAll(1.5, ends);
    QCOMPARE(out.seen, (QStringList{"1 slip begin 0.5", "1.5 slip end 0.5"}));
    QCOMPARE(ends.size(), 1);
}

void TestRouterNodes::frictionUse_data()
{
    QTest::addColumn<double>("normal");
    QTest::addColumn<double>("tangential");
    QTest::addColumn<double>("mu");
    QTest::addColumn<double>("use");
    QTest::newRow("at the cone's edge") << 20.0 << 2.0 << 0.1 << 1.0;
    QTest::newRow("inside it") << 20.0 << 1.0 << 0.1 << 0.5;
    QTest::newRow("beyond it (sliding)") << 10.0 << 1.5 << 0.1 << 1.5;
    QTest::newRow("no coefficient: unknown") << 20.0 << 2.0 << 0.0 << 0.0;
    QTest::newRow("no normal force: nothing pressed") << 0.05 << 0.0 << 0.1 << 0.0;
}

void TestRouterNodes::frictionUse()
{
    QFETCH(double, normal);
    QFETCH(double, tangential);
    QFETCH(double, mu);
    QFETCH(double, use);
    const Fingertip tip = pressing(normal, tangential, mu);
    QVERIFY2(std::abs(tip.frictionUse(tip.mu) - use) < 1e-12,
             qPrintable(QString::number(tip.frictionUse(tip.mu))));
    Fingertip without = tip;
    without.hasFxyz = false;
    QCOMPARE(without.frictionUse(0.1), 0.0);
}

void TestRouterNodes::frictionSignal()
{
    // The larger fingertip's use; a node's own mu beats the frame's (a live rig's setting).
    ContactFrame frame;
    frame.gripper = Gripper::Left;
    frame.left = pressing(20.0, 1.0, 0.1);
    frame.right = pressing(20.0, 1.6, 0.1);
    SignalRecorder out;
    const std::tuple<SignalNode::Quantity, double, double> cases[] = {
        {SignalNode::Quantity::Friction, 0.0, 0.8},
        {SignalNode::Quantity::FrictionLeft, 0.0, 0.5},
        {SignalNode::Quantity::FrictionRight, 0.2, 0.4}};
    for (const auto &[quantity, mu, expected] : cases) {
        SignalNode node(Gripper::Left, quantity, mu);
        node.signalTargets.push_back({&out, 0});
        node.process(frame);
        QVERIFY(std::abs(out.values.back() - expected) < 1e-12);
    }
}

QTEST_GUILESS_MAIN(TestRouterNodes)
#include "tst_routernodes.moc"
