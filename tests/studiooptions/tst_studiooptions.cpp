// SPDX-License-Identifier: MIT
// The studio's command line: defaults are the embedded ones (box_and_block, C3, scripted,
// running at real time), every option reaches its field, and bad values say what is wrong.
#include "studiooptions.h"

#include <QTest>

using namespace semhap;

class TestStudioOptions : public QObject
{
    Q_OBJECT

private slots:
    void defaults();
    void options();
    void rejects_data();
    void rejects();
    void help();
};

namespace {

bool parse(const QStringList &args, StudioOptions *options, QString *message)
{
    bool help = false;
    return StudioOptions::parse(args, options, message, &help);
}

} // namespace

void TestStudioOptions::defaults()
{
    StudioOptions o;
    QString message;
    QVERIFY2(parse({}, &o, &message), qPrintable(message));
    QCOMPARE(o.run.scene, QString("box_and_block"));
    QCOMPARE(o.run.router, QString("C3"));
    QCOMPARE(o.run.operatorName, QString("scripted"));
    QCOMPARE(o.run.reactionTime, DefaultReactionTime);
    QVERIFY(o.run.sceneOptions.gripper.isEmpty()); // the scene's own
    QVERIFY(!o.runGiven);
    QVERIFY(o.run.duration >= 3600.0); // the studio runs until stopped
    QVERIFY(o.autoRun);
    QCOMPARE(o.speed, 1.0);
    QVERIFY(o.screenshot.isEmpty());
    QVERIFY(o.quitAfter < 0);
    QVERIFY(o.restoreLayout);
    QCOMPARE(o.posePort, 9870);
    QVERIFY(!o.live);
}

void TestStudioOptions::options()
{
    StudioOptions o;
    QString message;
    QVERIFY2(parse({"--scene",
                    "bimanual_sorting",
                    "--router",
                    "C1",
                    "--operator",
                    "reactive",
                    "--seed",
                    "7",
                    "--reaction-time",
                    "0.4",
                    "--cubes",
                    "4",
                    "--gripper",
                    "robotiq_2f85",
                    "--speed",
                    "0.5",
                    "--paused",
                    "--screenshot",
                    "a.png",
                    "--quit-after",
                    "2.5",
                    "--size",
                    "1920x1080",
                    "--language",
                    "de",
                    "--pose-port",
                    "0",
                    "--default-layout"},
                   &o, &message),
             qPrintable(message));
    QCOMPARE(o.run.scene, QString("bimanual_sorting"));
    QCOMPARE(o.run.router, QString("C1"));
    QCOMPARE(o.run.operatorName, QString("reactive"));
    QCOMPARE(o.run.seed, std::uint64_t(7));
    QCOMPARE(o.run.reactionTime, 0.4);
    QCOMPARE(o.run.sceneOptions.cubes, 4);
    QCOMPARE(o.run.sceneOptions.gripper, QString("robotiq_2f85"));
    QVERIFY(o.runGiven);
    QCOMPARE(o.speed, 0.5);
    QVERIFY(!o.autoRun);
    QCOMPARE(o.screenshot, QString("a.png"));
    QCOMPARE(o.quitAfter, 2.5);
    QCOMPARE(o.size, QSize(1920, 1080));
    QCOMPARE(o.language, QString("de"));
    QCOMPARE(o.posePort, 0);
    QVERIFY(!o.restoreLayout);

    // A gripper alone names a run too: the default scene with that gripper; a file is kept
    // as given (the loader reads names and files alike).
    QVERIFY(parse({"--gripper", "/lab/hands/ours.json"}, &o, &message));
    QCOMPARE(o.run.sceneOptions.gripper, QString("/lab/hands/ours.json"));
    QCOMPARE(o.run.scene, QString("box_and_block"));
    QVERIFY(o.runGiven);

    // The perceiving operator with its person's parameters.
    QVERIFY(parse({"--operator", "perceiving", "--person", "saccade=0.25", "--person",
                   "first_reliance=0.5"},
                  &o, &message));
    QCOMPARE(o.run.operatorName, QString("perceiving"));
    QCOMPARE(o.run.person.saccade, 0.25);
    QCOMPARE(o.run.person.firstReliance, 0.5);
    QVERIFY(o.runGiven);

    // A live rig: on this machine unless an address is given; the router is --router's.
    QVERIFY(parse({"--listen", "9900", "--router", "C2"}, &o, &message));
    QVERIFY(o.live);
    QCOMPARE(o.liveRig.port, 9900);
    QCOMPARE(o.liveRig.address, QString("127.0.0.1"));
    QCOMPARE(o.liveRig.router, QString("C2"));
    QVERIFY(parse({"--listen", "0.0.0.0:0"}, &o, &message));
    QCOMPARE(o.liveRig.port, 0);
    QCOMPARE(o.liveRig.address, QString("0.0.0.0"));

    // A screenshot alone grabs once the studio has run a moment.
    QVERIFY(parse({"--screenshot", "b.png"}, &o, &message));
    QVERIFY(o.quitAfter > 0);

    // A study with its participant, whose next step starts at once; no run of its own.
    QVERIFY(parse({"--study", "lab/bimanual.db", "--participant", "P07", "--start-step"}, &o,
                  &message));
    QCOMPARE(o.study, QString("lab/bimanual.db"));
    QCOMPARE(o.participant, QString("P07"));
    QVERIFY(o.startStep);
    QVERIFY(!o.runGiven);
}

void TestStudioOptions::rejects_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("expected");
    QTest::newRow("unknown option") << QStringList{"--bogus"} << "bogus";
    QTest::newRow("missing value") << QStringList{"--scene"} << "scene";
    QTest::newRow("missing gripper") << QStringList{"--gripper"} << "gripper";
    QTest::newRow("speed not a number") << QStringList{"--speed", "fast"} << "--speed";
    QTest::newRow("speed too high") << QStringList{"--speed", "1000"} << "0.01 to 100";
    QTest::newRow("negative seed") << QStringList{"--seed", "-1"} << "--seed";
    QTest::newRow("reaction time") << QStringList{"--reaction-time", "-1"} << "0 to 10";
    QTest::newRow("bad size") << QStringList{"--size", "big"} << "WIDTHxHEIGHT";
    QTest::newRow("tiny size") << QStringList{"--size", "10x10"} << "10x10";
    QTest::newRow("language") << QStringList{"--language", "fr"} << "en or de";
    QTest::newRow("port") << QStringList{"--pose-port", "70000"} << "--pose-port";
    QTest::newRow("listen port") << QStringList{"--listen", "70000"} << "--listen";
    QTest::newRow("listen text") << QStringList{"--listen", "rig"} << "ADDRESS:PORT";
    QTest::newRow("listen no address") << QStringList{"--listen", ":9871"} << "--listen";
    QTest::newRow("person out of range")
        << QStringList{"--person", "saccade=2"} << "--person saccade=2: expected a number from";
    QTest::newRow("person unknown") << QStringList{"--person", "mood=1"} << "NAME one of";
    QTest::newRow("positional") << QStringList{"scene.xml"} << "scene.xml";
    QTest::newRow("participant without a study")
        << QStringList{"--participant", "P01"} << "--participant: name the study";
    QTest::newRow("start without a participant")
        << QStringList{"--study", "s.db", "--start-step"} << "--start-step: name the participant";
}

void TestStudioOptions::rejects()
{
    QFETCH(QStringList, args);
    QFETCH(QString, expected);
    StudioOptions o;
    QString message;
    bool help = true;
    QVERIFY(!StudioOptions::parse(args, &o, &message, &help));
    QVERIFY(!help);
    QVERIFY2(message.contains(expected), qPrintable(message));
}

void TestStudioOptions::help()
{
    StudioOptions o;
    QString message;
    bool help = false;
    QVERIFY(!StudioOptions::parse({"--help"}, &o, &message, &help));
    QVERIFY(help);
    QVERIFY(message.contains("--screenshot"));
    QVERIFY(message.contains("--router"));
    QVERIFY(message.contains("--gripper"));
}

QTEST_GUILESS_MAIN(TestStudioOptions)
#include "tst_studiooptions.moc"
