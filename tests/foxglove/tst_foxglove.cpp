// SPDX-License-Identifier: MIT
// `semhap listen --foxglove`: a robot played by the reference server (@foxglove/ws-protocol's
// FoxgloveServer, tests/interop/foxglove-robot.mjs) is followed live: its grasp gives the
// events the same grasp gives from a recording; the robot restarting is followed again; a
// robot without the map's topics is a clear error naming the topics it has.
// `--foxglove-server`: the reference client (tests/interop/foxglove-viewer.mjs) watches a run
// and a robot followed, every message decoded by its advertised schema, none decimated; a
// viewer that stalls loses its own oldest messages and is told so.
#include "cdrwriter.h"
#include "clirun.h"
#include "foxglovepeers.h"
#include "foxgloveserver.h"
#include "jsonlines.h"

#include <QJsonArray>
#include <QProcess>
#include <QRegularExpression>
#include <QTcpServer>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

namespace {

QString interop(const QString &name)
{
    return QStringLiteral(SEMHAP_INTEROP_DIR "/") + name;
}

/** `semhap listen --foxglove` on the robot at `port`, through the grasp's map. */
CliResult follow(int port, const QStringList &more)
{
    return semhapRun(QStringList{"listen", "--foxglove",
                                 QStringLiteral("ws://127.0.0.1:%1").arg(port), "--topics",
                                 interop("grasp.topics.json")} +
                     more);
}

/** A port nothing listens on now. */
int freePort()
{
    QTcpServer probe;
    return probe.listen(QHostAddress::LocalHost, 0) ? probe.serverPort() : 0;
}

/** How many messages a viewer got, over all topics. */
long long received(const QJsonObject &view)
{
    long long n = 0;
    for (const QJsonValue &topic : view["topics"].toObject())
        n += topic.toObject()["count"].toInteger();
    return n;
}

/** The header stamp of a decoded message, in ns. */
long long stampOf(const QJsonObject &message)
{
    const QJsonObject stamp = message["header"].toObject()["stamp"].toObject();
    return stamp["sec"].toInteger() * 1000000000LL + stamp["nanosec"].toInteger();
}

} // namespace

class TestFoxglove : public QObject
{
    Q_OBJECT

private slots:
    void followsARobotLive();
    void followsARobotThatRestarts();
    void aRobotWithoutTheMapsTopics();
    void aViewerWatchesARun();
    void aViewerWatchesTheRobotFollowed();
    void aStalledViewerLosesItsOldestMessages();
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

void TestFoxglove::aViewerWatchesARun()
{
    const int port = freePort();
    QVERIFY(port > 0);
    QProcess viewer;
    startViewer(viewer, QStringLiteral("ws://127.0.0.1:%1").arg(port));
    const CliResult run =
        semhapRun({"run", "--scene", "box_and_block", "--router", "C3", "--operator", "scripted",
                   "--duration", "6", "--foxglove-server", QString::number(port)});
    QVERIFY2(run.code == 0, run.err.constData());
    QVERIFY2(run.err.contains(
                 QStringLiteral("serving Foxglove on ws://127.0.0.1:%1").arg(port).toUtf8()),
             run.err.constData());
    const QJsonObject view = viewed(viewer);
    QCOMPARE(view["subprotocol"].toString(), QString("foxglove.websocket.v1"));
    QCOMPARE(view["serverInfo"].toString(), QString("semhap"));
    QCOMPARE(view["errors"].toArray().size(), 0);
    QCOMPARE(view["undecoded"].toInt(), 0);
    // Every message the run sent, the viewer decoded.
    QVERIFY2(
        run.err.contains(QStringLiteral("foxglove: %1 message(s) sent to 1 viewer(s), 0 dropped")
                             .arg(received(view))
                             .toUtf8()),
        run.err.constData());

    const QJsonObject topics = view["topics"].toObject();
    const QMap<QString, QString> types{
        {"/semhap/right/contact", "semhap_msgs/msg/ContactFrame"},
        {"/semhap/right/left/wrench", "geometry_msgs/msg/WrenchStamped"},
        {"/semhap/right/right/wrench", "geometry_msgs/msg/WrenchStamped"},
        {"/semhap/events", "semhap_msgs/msg/SemanticEvent"},
        {"/semhap/devices/right.air", "semhap_msgs/msg/DeviceFrame"},
        {"/semhap/devices/right.vibro", "semhap_msgs/msg/DeviceFrame"}};
    for (auto it = types.begin(); it != types.end(); ++it) {
        QVERIFY2(topics.contains(it.key()), qPrintable(it.key()));
        QCOMPARE(topics[it.key()].toObject()["type"].toString(), it.value());
    }
    // None decimated: on each of the gripper's topics, from the first frame the viewer got
    // to the last, every frame is there (box_and_block's come every 2 ms, its physics step).
    long long last = -1;
    for (const char *topic :
         {"/semhap/right/contact", "/semhap/right/left/wrench", "/semhap/right/right/wrench"}) {
        const QJsonObject seen = topics[topic].toObject();
        const long long count = seen["count"].toInteger();
        const long long span =
            stampOf(seen["last"].toObject()) - stampOf(seen["first"].toObject());
        QVERIFY2(count > 500 && std::llabs(span - (count - 1) * 2000000) <= 1,
                 qPrintable(
                     QStringLiteral("%1: %2 frames over %3 ns").arg(topic).arg(count).arg(span)));
        QVERIFY(last < 0 || stampOf(seen["last"].toObject()) == last);
        last = stampOf(seen["last"].toObject());
    }
    // The grasp was confirmed, and the air band told.
    bool grasp = false;
    const QJsonObject event = topics["/semhap/events"].toObject()["first"].toObject();
    grasp = event["message"].toString() == "grasp";
    QVERIFY2(grasp, QJsonDocument(event).toJson().constData());
    QCOMPARE(topics["/semhap/devices/right.air"].toObject()["last"].toObject()["model"].toString(),
             QString("pneumatic6"));
}

void TestFoxglove::aViewerWatchesTheRobotFollowed()
{
    // The robot plays once semhap and the viewer are both ready: the viewer sees it all.
    QProcess robot;
    const int port = startRobot(robot, {"--hold"});
    QVERIFY(port > 0);
    QTemporaryDir dir;
    QProcess listen;
    listen.setReadChannel(QProcess::StandardError);
    listen.start(QStringLiteral(SEMHAP_CLI_BINARY),
                 {"listen", "--foxglove", QStringLiteral("ws://127.0.0.1:%1").arg(port),
                  "--topics", interop("grasp.topics.json"), "--events", dir.filePath("live"),
                  "--silence", "1.5", "--duration", "10", "--foxglove-server", "0"});
    QByteArray err;
    QRegularExpressionMatch served;
    const QRegularExpression serving("serving Foxglove on (ws://127.0.0.1:[0-9]+)");
    while (!(served = serving.match(QString::fromUtf8(err))).hasMatch() &&
           listen.waitForReadyRead(30000))
        err += listen.readAllStandardError();
    QVERIFY2(served.hasMatch(), err.constData());
    QProcess viewer;
    startViewer(viewer, served.captured(1));
    const QByteArray subscribed = waitForViewer(viewer, "subscribed /semhap/right/contact");
    QVERIFY2(subscribed.contains("subscribed /semhap/right/contact"), subscribed.constData());
    robot.write("go\n");
    QVERIFY(robot.waitForBytesWritten(10000));
    QVERIFY(listen.waitForFinished(60000));
    err += listen.readAllStandardError();
    QVERIFY2(listen.exitCode() == 0, err.constData());

    const QJsonObject view = viewed(viewer);
    QCOMPARE(view["undecoded"].toInt(), 0);
    const QJsonObject topics = view["topics"].toObject();
    // Every frame and every event semhap made of the robot's grasp.
    const QJsonObject contact = topics["/semhap/right/contact"].toObject();
    QCOMPARE(contact["count"].toInteger(), 1000);
    const QList<QJsonObject> events = readLines(dir.filePath("live"));
    QVERIFY(events.size() > 10);
    const QJsonObject seen = topics["/semhap/events"].toObject();
    QCOMPARE(seen["count"].toInteger(), qint64(events.size()));
    QCOMPARE(seen["first"].toObject()["message"].toString(), events.first()["message"].toString());
    QVERIFY2(err.contains(QStringLiteral("foxglove: %1 message(s) sent to 1 viewer(s), 0 dropped")
                              .arg(received(view))
                              .toUtf8()),
             err.constData());
    // On the robot's own clock (tests/interop/grasp.mjs: 1.7e9 s since the epoch), where its
    // own topics are in the viewer.
    QVERIFY2(std::abs(double(stampOf(contact["first"].toObject())) / 1e9 - 1.7e9) < 3600,
             qPrintable(QString::number(stampOf(contact["first"].toObject()))));
    robot.waitForFinished(10000);
}

void TestFoxglove::aStalledViewerLosesItsOldestMessages()
{
    semhap::FoxgloveServer server(QStringLiteral("semhap-tests"));
    server.setQueueLimit(100);
    QString error;
    QVERIFY2(server.listen(QHostAddress::LocalHost, 0, &error), qPrintable(error));
    const int channel = server.addChannel("/counter", "std_msgs/msg/String", "string data\n");
    QProcess viewer;
    startViewer(viewer, server.url(), {"--stall", "3000"});
    QTRY_COMPARE_WITH_TIMEOUT(server.stats().subscriptions, 1, 30000);
    semhap::CdrWriter cdr;
    const auto publish = [&](int i) {
        cdr.clear();
        // Big enough that the sockets' buffers fill while the viewer does not read.
        cdr.string(QByteArray::number(i) + ':' + QByteArray(4000, 'x'));
        server.publish(channel, std::uint64_t(i), cdr.bytes());
    };
    publish(0);
    const QByteArray said = waitForViewer(viewer, "stalled");
    QVERIFY2(said.contains("stalled\n"), said.constData());
    const int count = 4000;
    for (int i = 1; i <= count; ++i)
        publish(i);
    // Each message is sent or dropped, and the sockets have written what they were given.
    QTRY_VERIFY_WITH_TIMEOUT(server.stats().sent + server.stats().dropped == count + 1 &&
                                 server.stats().outstanding == 0,
                             60000);
    server.close();
    const semhap::FoxgloveServer::Stats stats = server.stats();
    QVERIFY2(stats.dropped > 0, "the viewer read everything: it did not stall");
    const QJsonObject view = viewed(viewer);
    const QJsonObject counter = view["topics"].toObject()["/counter"].toObject();
    QCOMPARE(counter["count"].toInteger() + stats.dropped, qint64(count + 1));
    // The newest are kept.
    QVERIFY(counter["last"].toObject()["data"].toString().startsWith(
        QStringLiteral("%1:").arg(count)));
    bool told = false;
    for (const QJsonValue &status : view["statuses"].toArray())
        told = told || (status["level"].toInt() == 1 &&
                        status["message"].toString().contains("reads too slowly"));
    QVERIFY2(told, QJsonDocument(view["statuses"].toArray()).toJson().constData());
}

QTEST_GUILESS_MAIN(TestFoxglove)
#include "tst_foxglove.moc"
