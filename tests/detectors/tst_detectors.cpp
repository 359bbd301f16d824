// SPDX-License-Identifier: MIT
#include "actortable.h"
#include "forcedetector.h"
#include "impactdetector.h"
#include "messagetracker.h"
#include "routernodetype.h"
#include "slipdetector.h"

#include <QJsonDocument>
#include <QLocale>
#include <QTest>

#include <utility>

using namespace semhap;

namespace {

constexpr int Node = 7;

QString number(double value)
{
    return QString::number(value, 'g', QLocale::FloatingPointShortest);
}

/** "t message phase intensity", the form the expected lists in the rows use. */
QString describe(const SemanticEvent &event)
{
    return QStringList{number(event.t), messageName(event.message), eventPhaseName(event.phase),
                       number(event.intensity)}
        .join(QLatin1Char(' '));
}

double toDouble(const QString &text)
{
    bool ok = false;
    const double value = text.toDouble(&ok);
    if (!ok)
        qFatal("bad number in test row");
    return value;
}

/** Force rows give each tick as "t f_left f_right". */
ContactFrame forceFrame(const QString &text)
{
    const QStringList parts = text.split(QLatin1Char(' '), Qt::SkipEmptyParts);
    if (parts.size() != 3)
        qFatal("force frame needs 3 fields");
    ContactFrame frame;
    frame.gripper = Gripper::Right;
    frame.t = toDouble(parts[0]);
    frame.left.f = toDouble(parts[1]);
    frame.right.f = toDouble(parts[2]);
    return frame;
}

/** Slip rows give each tick as "t f_l n_l actor_l f_r n_r actor_r", "-" for no actor. */
ContactFrame slipFrame(const QString &text, ActorTable &actors)
{
    const QStringList parts = text.split(QLatin1Char(' '), Qt::SkipEmptyParts);
    if (parts.size() != 7)
        qFatal("slip frame needs 7 fields");
    ContactFrame frame;
    frame.gripper = Gripper::Left;
    frame.t = toDouble(parts[0]);
    Fingertip *tips[] = {&frame.left, &frame.right};
    for (int i = 0; i < 2; ++i) {
        tips[i]->f = toDouble(parts[1 + 3 * i]);
        tips[i]->n = int(toDouble(parts[2 + 3 * i]));
        const QString &actor = parts[3 + 3 * i];
        tips[i]->actor = actor == QLatin1String("-") ? -1 : actors.intern(actor);
    }
    return frame;
}

/** Test rows write their frames and events as plain string literals. */
QStringList lines(std::initializer_list<const char *> items)
{
    QStringList result;
    for (const char *item : items)
        result.append(QString::fromUtf8(item));
    return result;
}

/** Runs the frames and checks every event's fixed fields, returning the described events. */
QStringList run(Detector &detector, const QList<ContactFrame> &frames)
{
    QStringList events;
    EventBuffer buffer;
    for (const ContactFrame &frame : frames) {
        buffer.clear();
        detector.update(frame, buffer);
        for (const SemanticEvent &event : buffer) {
            if (event.node != Node || event.gripper != detector.gripper() ||
                event.detector != detector.kind() || event.category != categoryOf(event.message) ||
                event.t != frame.t)
                events.append(QStringLiteral("bad fields: ") + describe(event));
            else
                events.append(describe(event));
        }
    }
    return events;
}

/** The columns of a detector's parameter rows (json, key, reason), and the defaults' row. */
void paramColumns()
{
    QTest::addColumn<QString>("json");
    QTest::addColumn<QString>("key");
    QTest::addColumn<QString>("reason");
    QTest::newRow("defaults") << "{}"
                              << ""
                              << "";
}

/**
 * Reads and validates the row's `json` as a detector's Params, and checks the key and reason
 * of the row's error (none: valid, and its JSON reads back the same).
 */
template<typename Params> void checkParams()
{
    QFETCH(QString, json);
    QFETCH(QString, key);
    QFETCH(QString, reason);

    Params params;
    QString gotKey;
    QString gotReason;
    const bool ok =
        params.read(QJsonDocument::fromJson(json.toUtf8()).object(), &gotKey, &gotReason) &&
        params.validate(&gotKey, &gotReason);
    QCOMPARE(gotKey, key);
    QCOMPARE(gotReason, reason);
    QCOMPARE(ok, key.isEmpty());
    if (ok) {
        Params back;
        QVERIFY(back.read(params.toJson(), nullptr, nullptr));
        QCOMPARE(back.toJson(), params.toJson());
    }
}

} // namespace

class TestDetectors : public QObject
{
    Q_OBJECT

private slots:
    void names();
    void actorTable();
    void tracker();
    void forceEvents_data();
    void forceEvents();
    void slipEvents_data();
    void slipEvents();
    void otherGripperIgnored();
    void endAllAndClear();
    void forceParams_data();
    void forceParams();
    void slipParams_data();
    void slipParams();
    void impactEvents_data();
    void impactEvents();
    void impactParams_data();
    void impactParams();
};

void TestDetectors::names()
{
    QCOMPARE(gripperName(Gripper::Left), QStringLiteral("left"));
    QCOMPARE(messageName(Message::Break), QStringLiteral("break"));
    QCOMPARE(categoryName(Category::Exception), QStringLiteral("exception"));
    QCOMPARE(eventPhaseName(EventPhase::Update), QStringLiteral("update"));
    QCOMPARE(detectorKindName(DetectorKind::Slip), QStringLiteral("slip"));
    QCOMPARE(categoryOf(Message::Grasp), Category::Confirmation);
    QCOMPARE(categoryOf(Message::Slip), Category::Exception);

    Gripper gripper = Gripper::Left;
    QVERIFY(gripperFromName(QStringLiteral("right"), &gripper));
    QCOMPARE(gripper, Gripper::Right);
    QVERIFY(!gripperFromName(QStringLiteral("Right"), &gripper));
    Message message = Message::Grasp;
    QVERIFY(messageFromName(QStringLiteral("slip"), &message));
    QCOMPARE(message, Message::Slip);
    QVERIFY(!messageFromName(QStringLiteral("Grip!"), &message));
    // A new name of [a-z0-9_.] is a new message, the same id each time.
    Message aligned = Message::Grasp;
    QVERIFY(messageFromName(QStringLiteral("plug.aligned"), &aligned));
    QVERIFY(!isBuiltinMessage(aligned));
    QCOMPARE(messageName(aligned), QStringLiteral("plug.aligned"));
    QVERIFY(messageFromName(QStringLiteral("plug.aligned"), &message));
    QCOMPARE(message, aligned);
    EventPhase phase = EventPhase::Begin;
    QVERIFY(eventPhaseFromName(QStringLiteral("end"), &phase));
    QCOMPARE(phase, EventPhase::End);
    Category category = Category::Confirmation;
    QVERIFY(categoryFromName(QStringLiteral("exception"), &category));
    QCOMPARE(category, Category::Exception);
    DetectorKind kind = DetectorKind::Slip;
    QVERIFY(detectorKindFromName(QStringLiteral("force"), &kind));
    QCOMPARE(kind, DetectorKind::Force);
    QVERIFY(!detectorKindFromName(QString(), &kind));
}

void TestDetectors::actorTable()
{
    ActorTable actors;
    QCOMPARE(actors.intern(QString()), -1);
    QCOMPARE(actors.intern(QStringLiteral("")), -1);
    QCOMPARE(actors.intern(QStringLiteral("cube_3")), 0);
    QCOMPARE(actors.intern(QStringLiteral("ball")), 1);
    QCOMPARE(actors.intern(QStringLiteral("cube_3")), 0);
    QCOMPARE(actors.size(), 2);
    QCOMPARE(actors.find(QStringLiteral("ball")), 1);
    QCOMPARE(actors.find(QStringLiteral("cone")), -1);
    QCOMPARE(actors.name(1), QStringLiteral("ball"));
    QVERIFY(actors.name(-1).isNull());
    QVERIFY(actors.name(2).isNull());
}

void TestDetectors::tracker()
{
    MessageTracker tracker;
    tracker.configure(Gripper::Left, Node, DetectorKind::Slip, Message::Slip, Category::Exception,
                      0.5);
    EventBuffer out;
    tracker.update(0.0, true, 0.25, out);
    QVERIFY(tracker.isPending());
    QVERIFY(!tracker.isActive());
    tracker.forceEnd(0.25, out);
    QVERIFY(!tracker.isPending());
    QVERIFY(out.isEmpty());
    tracker.update(0.5, true, 0.25, out);
    tracker.update(1.0, true, 0.5, out);
    QVERIFY(tracker.isActive());
    QCOMPARE(tracker.intensity(), 0.5);
    QCOMPARE(out.size(), 1);
    QCOMPARE(describe(out[0]), QStringLiteral("1 slip begin 0.5"));
    QCOMPARE(out[0].category, Category::Exception);
    tracker.clear();
    QVERIFY(!tracker.isActive());
    QCOMPARE(out.size(), 1);
}

void TestDetectors::forceEvents_data()
{
    QTest::addColumn<QString>("params");
    QTest::addColumn<QStringList>("frames");
    QTest::addColumn<QStringList>("events");

    const QString spec = QStringLiteral(R"({"grasp": 20, "break": 80, "max": 120})");
    QTest::newRow("F equal to grasp is not a grasp")
        << spec << lines({"0 10 10", "1 20 0", "2 0 20"}) << QStringList();
    QTest::newRow("F just above grasp")
        << spec << lines({"0 10 10", "1 10 10.5"}) << lines({"1 grasp begin 1"});
    QTest::newRow("F equal to break is not a break")
        << spec << lines({"0 40 40"}) << lines({"0 grasp begin 1"});
    QTest::newRow("F just above break")
        << spec << lines({"0 40 41"}) << lines({"0 grasp begin 1", "0 break begin 0.025"});
    QTest::newRow("intensity clips at and beyond max")
        << spec << lines({"0 45 45", "1 60 60", "2 100 100", "3 150 0", "4 50 50"})
        << lines({"0 grasp begin 1", "0 break begin 0.25", "1 break update 1",
                  "4 break update 0.5"});
    QTest::newRow("break updates only when intensity changes")
        << spec << lines({"0 50 50", "1 60 40", "2 100 0", "3 50 51", "4 0 101"})
        << lines({"0 grasp begin 1", "0 break begin 0.5", "3 break update 0.525"});
    QTest::newRow("both end in one tick, grasp first")
        << spec << lines({"0 50 50", "1 10 0"})
        << lines({"0 grasp begin 1", "0 break begin 0.5", "1 grasp end 1", "1 break end 0.5"});
    QTest::newRow("break ends, grasp stays")
        << spec << lines({"0 50 50", "1 40 40", "2 20 0"})
        << lines({"0 grasp begin 1", "0 break begin 0.5", "1 break end 0.5", "2 grasp end 1"});
    QTest::newRow("default hysteresis and minDuration are the spec")
        << QStringLiteral(R"({"grasp": 20, "break": 80, "max": 120, "hysteresis": 0,
                              "minDuration": 0})")
        << lines({"0 10 10", "1 10 10.5", "2 40 41", "3 40 40", "4 10 10"})
        << lines({"1 grasp begin 1", "2 break begin 0.025", "3 break end 0.025", "4 grasp end 1"});
    QTest::newRow("hysteresis holds down to threshold - hysteresis")
        << QStringLiteral(R"({"hysteresis": 5})")
        << lines({"0 10 10", "1 12.5 12.5", "2 9 9", "3 7.5 7.5", "4 10 10.5", "5 42.5 42.5",
                  "6 39 39", "7 37.5 37.5"})
        << lines({"1 grasp begin 1", "3 grasp end 1", "4 grasp begin 1", "5 break begin 0.125",
                  "6 break update 0", "7 break end 0"});
    QTest::newRow("minDuration delays the begin to the tick it is met")
        << QStringLiteral(R"({"minDuration": 0.5})")
        << lines({"0 15 15", "0.25 15 15", "0.5 15 15", "0.75 5 5"})
        << lines({"0.5 grasp begin 1", "0.75 grasp end 1"});
    QTest::newRow("minDuration restarts when the condition drops")
        << QStringLiteral(R"({"minDuration": 0.5})")
        << lines({"0 15 15", "0.25 5 5", "0.5 50 50", "0.75 50 50", "1 60 40"})
        << lines({"1 grasp begin 1", "1 break begin 0.5"});
}

void TestDetectors::forceEvents()
{
    QFETCH(QString, params);
    QFETCH(QStringList, frames);
    QFETCH(QStringList, events);

    ForceDetector::Params p;
    QString key;
    QString reason;
    QVERIFY(p.read(QJsonDocument::fromJson(params.toUtf8()).object(), &key, &reason));
    QVERIFY2(p.validate(&key, &reason), qPrintable(key + QStringLiteral(": ") + reason));
    ForceDetector detector(Node, Gripper::Right, p);
    QList<ContactFrame> input;
    for (const QString &frame : std::as_const(frames))
        input.append(forceFrame(frame));
    QCOMPARE(run(detector, input), events);
}

void TestDetectors::slipEvents_data()
{
    QTest::addColumn<QString>("params");
    QTest::addColumn<QStringList>("frames");
    QTest::addColumn<QStringList>("events");

    const QString spec = QStringLiteral(R"({"grasp": 20, "loss": 28, "min": 8})");
    QTest::newRow("stable grasp, then slip graded down to min and beyond")
        << spec
        << lines({"0 15 16 cube 15 16 cube", "1 15 12 cube 15 12 cube", "2 15 8 cube 15 8 cube",
                  "3 15 4 cube 15 4 cube", "4 15 2 cube 15 2 cube", "5 15 14 cube 15 14 cube"})
        << lines({"0 grasp begin 1", "1 slip begin 0.2", "2 slip update 0.6", "3 slip update 1",
                  "5 slip end 1"});
    QTest::newRow("N equal to loss is not slipping")
        << spec << lines({"0 15 14 cube 15 14 cube"}) << lines({"0 grasp begin 1"});
    QTest::newRow("N at min gives intensity 1") << spec << lines({"0 15 4 cube 15 4 cube"})
                                                << lines({"0 grasp begin 1", "0 slip begin 1"});
    QTest::newRow("N below min gives intensity 1") << spec << lines({"0 15 0 cube 15 1 cube"})
                                                   << lines({"0 grasp begin 1", "0 slip begin 1"});
    QTest::newRow("actor switch while stable: ends, then begins, in one tick")
        << spec << lines({"0 15 10 cube 15 10 cube", "1 15 10 ball 15 10 ball"})
        << lines({"0 grasp begin 1", "0 slip begin 0.4", "1 grasp end 1", "1 slip end 0.4",
                  "1 grasp begin 1", "1 slip begin 0.4"});
    QTest::newRow("release: one fingertip loses the actor")
        << spec
        << lines({"0 15 10 cube 15 10 cube", "1 0 0 - 15 10 cube", "2 0 0 - 15 10 cube",
                  "3 15 10 cube 15 10 cube"})
        << lines({"0 grasp begin 1", "0 slip begin 0.4", "1 grasp end 1", "1 slip end 0.4",
                  "3 grasp begin 1", "3 slip begin 0.4"});
    QTest::newRow("fingertips on different actors release")
        << spec << lines({"0 15 16 cube 15 16 cube", "1 15 16 cube 15 16 ball"})
        << lines({"0 grasp begin 1", "1 grasp end 1"});
    QTest::newRow("one fingertip only touching is no grasp")
        << spec << lines({"0 50 4 cube 0 0 -", "1 0 0 - 50 4 cube"}) << QStringList();
    QTest::newRow("no actor on both fingertips while none grasped: nothing")
        << spec << lines({"0 50 4 - 50 4 -", "1 0 0 - 0 0 -"}) << QStringList();
    QTest::newRow("F dropping to grasp resets")
        << spec
        << lines({"0 15 10 cube 15 10 cube", "1 10 10 cube 10 10 cube", "2 5 10 cube 5 10 cube",
                  "3 15 16 cube 15 16 cube"})
        << lines({"0 grasp begin 1", "0 slip begin 0.4", "1 grasp end 1", "1 slip end 0.4",
                  "3 grasp begin 1"});
    QTest::newRow("F at or below grasp never grasps")
        << spec << lines({"0 10 16 cube 10 16 cube", "1 0 4 cube 0 4 cube"}) << QStringList();
    QTest::newRow("actor switch with low F ends once")
        << spec << lines({"0 15 16 cube 15 16 cube", "1 5 16 ball 5 16 ball"})
        << lines({"0 grasp begin 1", "1 grasp end 1"});
    QTest::newRow("default hysteresis and minDuration are the spec")
        << QStringLiteral(R"({"grasp": 20, "loss": 28, "min": 8, "hysteresis": 0,
                              "minDuration": 0})")
        << lines({"0 15 13 cube 15 13 cube", "1 15 14 cube 15 14 cube"})
        << lines({"0 grasp begin 1", "0 slip begin 0.1", "1 slip end 0.1"});
    QTest::newRow("hysteresis holds slip up to loss + hysteresis")
        << QStringLiteral(R"({"hysteresis": 4})")
        << lines({"0 15 14 cube 15 14 cube", "1 15 12 cube 15 12 cube", "2 15 15 cube 15 15 cube",
                  "3 15 16 cube 15 16 cube", "4 15 15 cube 15 15 cube"})
        << lines({"0 grasp begin 1", "1 slip begin 0.2", "2 slip update 0", "3 slip end 0"});
    QTest::newRow("minDuration delays grasp and slip separately")
        << QStringLiteral(R"({"minDuration": 0.5})")
        << lines({"0 15 16 cube 15 16 cube", "0.25 15 10 cube 15 10 cube",
                  "0.5 15 10 cube 15 10 cube", "0.75 15 8 cube 15 8 cube",
                  "1 15 16 cube 15 16 cube"})
        << lines({"0.5 grasp begin 1", "0.75 slip begin 0.6", "1 slip end 0.6"});
    QTest::newRow("a reset cancels a pending begin")
        << QStringLiteral(R"({"minDuration": 0.5})")
        << lines({"0 15 16 cube 15 16 cube", "0.25 15 16 ball 15 16 ball",
                  "0.5 15 16 ball 15 16 ball", "0.75 15 16 ball 15 16 ball"})
        << lines({"0.75 grasp begin 1"});
}

void TestDetectors::slipEvents()
{
    QFETCH(QString, params);
    QFETCH(QStringList, frames);
    QFETCH(QStringList, events);

    SlipDetector::Params p;
    QString key;
    QString reason;
    QVERIFY(p.read(QJsonDocument::fromJson(params.toUtf8()).object(), &key, &reason));
    QVERIFY2(p.validate(&key, &reason), qPrintable(key + QStringLiteral(": ") + reason));
    SlipDetector detector(Node, Gripper::Left, p);
    ActorTable actors;
    QList<ContactFrame> input;
    for (const QString &frame : std::as_const(frames))
        input.append(slipFrame(frame, actors));
    QCOMPARE(run(detector, input), events);
}

void TestDetectors::otherGripperIgnored()
{
    ForceDetector detector(Node, Gripper::Left, ForceDetector::Params());
    ContactFrame frame = forceFrame(QStringLiteral("0 50 50"));
    EventBuffer out;
    detector.update(frame, out);
    QVERIFY(out.isEmpty());
    frame.gripper = Gripper::Left;
    detector.update(frame, out);
    QCOMPARE(out.size(), 2);
}

void TestDetectors::endAllAndClear()
{
    ForceDetector force(Node, Gripper::Right, ForceDetector::Params());
    QCOMPARE(run(force, {forceFrame(QStringLiteral("0 50 50"))}),
             (lines({"0 grasp begin 1", "0 break begin 0.5"})));
    double intensity = 0.0;
    QVERIFY(force.isActive(Message::Break, &intensity));
    QCOMPARE(intensity, 0.5);
    QVERIFY(!force.isActive(Message::Slip));
    EventBuffer out;
    force.endAll(2.0, out);
    QCOMPARE(out.size(), 2);
    QCOMPARE(describe(out[0]), QStringLiteral("2 grasp end 1"));
    QCOMPARE(describe(out[1]), QStringLiteral("2 break end 0.5"));
    QVERIFY(!force.isActive(Message::Grasp));

    ActorTable actors;
    SlipDetector slip(Node, Gripper::Left, SlipDetector::Params());
    run(slip, {slipFrame(QStringLiteral("0 15 10 cube 15 10 cube"), actors)});
    QVERIFY(slip.isStable());
    QCOMPARE(slip.graspedActor(), actors.find(QStringLiteral("cube")));
    QVERIFY(slip.isActive(Message::Slip, &intensity));
    QCOMPARE(intensity, 0.4);
    slip.clear();
    QVERIFY(!slip.isStable());
    QCOMPARE(slip.graspedActor(), -1);
    QVERIFY(!slip.isActive(Message::Grasp));
    out.clear();
    slip.endAll(3.0, out);
    QVERIFY(out.isEmpty());
}

void TestDetectors::forceParams_data()
{
    paramColumns();
    QTest::newRow("all keys") << R"({"grasp": 1, "break": 2, "max": 3, "hysteresis": 0.5,
                                     "minDuration": 0.1})"
                              << ""
                              << "";
    QTest::newRow("unknown key") << R"({"brk": 90})"
                                 << "brk"
                                 << "unknown parameter";
    QTest::newRow("wrong type") << R"({"max": "120"})"
                                << "max"
                                << "must be a number";
    QTest::newRow("null") << R"({"grasp": null})"
                          << "grasp"
                          << "must be a number";
    QTest::newRow("grasp equal to break") << R"({"grasp": 80})"
                                          << "break"
                                          << "must be greater than grasp (80), got 80";
    QTest::newRow("break above max") << R"({"break": 130})"
                                     << "max"
                                     << "must be greater than break (130), got 120";
    QTest::newRow("negative hysteresis") << R"({"hysteresis": -1})"
                                         << "hysteresis"
                                         << "must not be negative, got -1";
    QTest::newRow("negative minDuration") << R"({"minDuration": -0.5})"
                                          << "minDuration"
                                          << "must not be negative, got -0.5";
}

void TestDetectors::forceParams()
{
    checkParams<ForceDetector::Params>();
}

void TestDetectors::slipParams_data()
{
    paramColumns();
    QTest::newRow("all keys") << R"({"grasp": 5, "loss": 20, "min": 4, "hysteresis": 2,
                                     "minDuration": 0.05})"
                              << ""
                              << "";
    QTest::newRow("unknown key") << R"({"break": 90})"
                                 << "break"
                                 << "unknown parameter";
    QTest::newRow("wrong type") << R"({"loss": true})"
                                << "loss"
                                << "must be a number";
    QTest::newRow("min equal to loss") << R"({"min": 28})"
                                       << "loss"
                                       << "must be greater than min (28), got 28";
    QTest::newRow("negative grasp") << R"({"grasp": -1})"
                                    << "grasp"
                                    << "must not be negative, got -1";
    QTest::newRow("negative hysteresis") << R"({"hysteresis": -2})"
                                         << "hysteresis"
                                         << "must not be negative, got -2";
}

void TestDetectors::slipParams()
{
    checkParams<SlipDetector::Params>();
}

void TestDetectors::impactEvents_data()
{
    QTest::addColumn<QStringList>("frames");
    QTest::addColumn<QStringList>("events");

    // tau 0: the rate is the difference quotient of F, exactly.
    QTest::newRow("a slow rise is no impact")
        << lines({"0 0 0", "1 25 25", "2 50 50"}) << QStringList();
    QTest::newRow("the first frame is no impact") << lines({"0 100 100"}) << QStringList();
    QTest::newRow("a strike is felt for hold after it")
        << lines({"0 0 0", "0.1 10 10", "0.2 10 10", "0.5 10 10", "0.6 10 10"})
        << lines({"0.1 impact begin 0.5", "0.6 impact end 0.5"});
    QTest::newRow("its intensity is its steepest rise's")
        << lines({"0 0 0", "0.1 10 10", "0.2 25 25", "0.3 30 30", "0.8 30 30"})
        << lines({"0.1 impact begin 0.5", "0.2 impact update 1", "0.8 impact end 1"});
    QTest::newRow("a new strike after the end begins anew")
        << lines({"0 0 0", "0.125 12.5 12.5", "0.75 12.5 12.5", "0.875 21.875 21.875"})
        << lines({"0.125 impact begin 0.5", "0.75 impact end 0.5", "0.875 impact begin 0.25"});
}

void TestDetectors::impactEvents()
{
    QFETCH(QStringList, frames);
    QFETCH(QStringList, events);

    ImpactDetector::Params p;
    QString key;
    QString reason;
    QVERIFY(p.read(
        QJsonDocument::fromJson(R"({"rate": 100, "full": 300, "tau": 0, "hold": 0.5})").object(),
        &key, &reason));
    QVERIFY2(p.validate(&key, &reason), qPrintable(key + QStringLiteral(": ") + reason));
    // Its kind is its node type's, as the router builds it.
    const DetectorKind kind = routerNodeType(QStringLiteral("impact"))->detectorKind;
    QCOMPARE(detectorKindName(kind), QStringLiteral("impact"));
    ImpactDetector detector(Node, Gripper::Right, p, kind);
    QStringList got;
    EventBuffer buffer;
    for (const QString &text : std::as_const(frames)) {
        buffer.clear();
        detector.update(forceFrame(text), buffer);
        for (const SemanticEvent &event : buffer) {
            QCOMPARE(event.detector, kind);
            QCOMPARE(event.category, Category::Exception);
            QCOMPARE(event.node, Node);
            got.append(describe(event));
        }
    }
    QCOMPARE(got, events);
}

void TestDetectors::impactParams_data()
{
    paramColumns();
    QTest::newRow("all keys") << R"({"rate": 50, "full": 60, "tau": 0, "hold": 0,
                                     "minDuration": 0.1})"
                              << ""
                              << "";
    QTest::newRow("full equal to rate") << R"({"full": 1000})"
                                        << "full"
                                        << "must be greater than rate (1000), got 1000";
    QTest::newRow("negative hold") << R"({"hold": -1})"
                                   << "hold"
                                   << "must not be negative, got -1";
    QTest::newRow("unknown key") << R"({"threshold": 5})"
                                 << "threshold"
                                 << "unknown parameter";
}

void TestDetectors::impactParams()
{
    checkParams<ImpactDetector::Params>();
}

QTEST_GUILESS_MAIN(TestDetectors)
#include "tst_detectors.moc"
