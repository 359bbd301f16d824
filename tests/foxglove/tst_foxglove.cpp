// SPDX-License-Identifier: MIT
// `semhap listen --foxglove`: a robot played by the reference server (@foxglove/ws-protocol's
// FoxgloveServer, tests/interop/foxglove-robot.mjs) is followed live: its grasp gives the
// events the same grasp gives from a recording; the robot restarting is followed again; a
// robot without the map's topics is a clear error naming the topics it has.
#include "clirun.h"
#include "jsonlines.h"

#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

namespace {

QString interop(const QString &name)
{
    return QStringLiteral(SEMHAP_INTEROP_DIR "/") + name;
}

/** The reference robot, started; its port, or 0. */
int startRobot(QProcess &robot, const QStringList &args)
{
    robot.setProcessChannelMode(QProcess::ForwardedErrorChannel);
    robot.start(QStringLiteral(SEMHAP_NODE),
                QStringList{QStringLiteral(SEMHAP_INTEROP_TOOLS "/foxglove-robot.mjs")} + args);
    if (!robot.waitForReadyRead(30000))
        return 0;
    return QJsonDocument::fromJson(robot.readLine()).object().value("port").toInt();
}

/** `semhap listen --foxglove` on the robot at `port`, through the grasp's map. */
CliResult follow(int port, const QStringList &more)
{
    return semhapRun(QStringList{"listen", "--foxglove",
                                 QStringLiteral("ws://127.0.0.1:%1").arg(port), "--topics",
                                 interop("grasp.topics.json")} +
                     more);
}

} // namespace

class TestFoxglove : public QObject
{
    Q_OBJECT

private slots:
    void followsARobotLive();
    void followsARobotThatRestarts();
    void aRobotWithoutTheMapsTopics();
};

void TestFoxglove::followsARobotLive()
{
    QProcess robot;
    const int port = startRobot(robot, {});
    QVERIFY(port > 0);
    QTemporaryDir dir;
    // A silence well above any stall of a loaded machine: the grasp is one stretch.
    const CliResult live =
        follow(port, {"--events", dir.filePath("live"), "--silence", "1.5", "--duration", "6"});
    QVERIFY2(live.code == 0, live.err.constData());
    QVERIFY2(live.err.contains(": 1 connection(s), 2200 message(s), 1000 frame(s), 0 rejected"),
             live.err.constData());
    QCOMPARE(semhapRun({"route", "--router", "C3", "--frames", interop("grasp.frames.jsonl"),
                        "--events", dir.filePath("recorded")})
                 .code,
             0);
    const QList<QJsonObject> events = readLines(dir.filePath("live"));
    QVERIFY(events.size() > 10);
    compareLines(events, readLines(dir.filePath("recorded")));
    robot.waitForFinished(10000);
}

void TestFoxglove::followsARobotThatRestarts()
{
    QProcess robot;
    const int port = startRobot(robot, {"--restarts", "1"});
    QVERIFY(port > 0);
    QTemporaryDir dir;
    const CliResult live =
        follow(port, {"--events", dir.filePath("live"), "--silence", "1.5", "--duration", "12"});
    QVERIFY2(live.code == 0, live.err.constData());
    // Followed again after the restart; the quiet between stopped the bands.
    QVERIFY2(live.err.contains(": 2 connection(s), 4400 message(s), 2000 frame(s), 0 rejected"),
             live.err.constData());
    QVERIFY2(live.err.contains("no frame for 1.5 s: messages ended, bands stopped"),
             live.err.constData());
    // The second grasp is 10 s after the first: it begins and ends where the first did.
    QList<double> begins;
    QList<double> ends;
    for (const QJsonObject &e : readLines(dir.filePath("live"))) {
        if (e["message"].toString() != "grasp")
            continue;
        (e["phase"].toString() == "begin" ? begins : ends) << e["t"].toDouble();
    }
    QCOMPARE(begins.size(), 2);
    QCOMPARE(ends.size(), 2);
    QVERIFY(std::abs(begins[1] - begins[0] - 10.0) < 1e-6);
    QVERIFY(std::abs(ends[1] - ends[0] - 10.0) < 1e-6);
    robot.waitForFinished(10000);
}

void TestFoxglove::aRobotWithoutTheMapsTopics()
{
    QProcess robot;
    const int port = startRobot(robot, {"--topics", "/arm/wrist/wrench,/arm/joint_states"});
    QVERIFY(port > 0);
    QTemporaryDir dir;
    const CliResult live = follow(port, {"--duration", "20"});
    QCOMPARE(live.code, 1);
    QVERIFY2(live.err.contains(QStringLiteral("ws://127.0.0.1:%1 advertises none of the map's "
                                              "topics (/right/left_tip/wrench, "
                                              "/right/right_tip/wrench, "
                                              "/right/right_tip/contacts); it has: "
                                              "/arm/joint_states, /arm/wrist/wrench")
                                   .arg(port)
                                   .toUtf8()),
             live.err.constData());
    robot.kill();
    robot.waitForFinished(5000);
}

QTEST_GUILESS_MAIN(TestFoxglove)
#include "tst_foxglove.moc"
