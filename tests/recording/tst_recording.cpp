// SPDX-License-Identifier: MIT
// `semhap route --frames REC.mcap --topics MAP.json`: a robot's recording, written by the
// reference libraries in each compression and as a plain stream (tests/interop), routes to
// the events and device frames of the same grasp given as JSON Lines contact frames, which
// the fixture works out from the map's rules on its own. A bad map or recording is a located
// error, and nothing is written.
#include "clirun.h"
#include "jsonlines.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QtEndian>
#include <QTest>

namespace {

QString recording(const QString &name)
{
    return QStringLiteral(SEMHAP_INTEROP_DIR "/") + name;
}

QJsonObject graspMap()
{
    QFile file(recording("grasp.topics.json"));
    if (!file.open(QIODevice::ReadOnly))
        qFatal("no grasp.topics.json");
    return QJsonDocument::fromJson(file.readAll()).object();
}

void write(const QString &path, const QByteArray &bytes)
{
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(bytes) != bytes.size())
        qFatal("cannot write %s", qPrintable(path));
}

/** The map with one value changed, at a path of keys. */
QJsonObject changed(QJsonObject map, const QStringList &keys, const QJsonValue &value)
{
    if (keys.size() == 1) {
        map.insert(keys[0], value);
        return map;
    }
    map.insert(keys[0], changed(map.value(keys[0]).toObject(), keys.mid(1), value));
    return map;
}

/** What the reference libraries read of an MCAP file (tests/interop/mcap-check.mjs). */
QJsonObject referenceRead(const QString &mcap)
{
    QProcess node;
    node.start(QStringLiteral(SEMHAP_NODE),
               {QStringLiteral(SEMHAP_INTEROP_TOOLS "/mcap-check.mjs"), mcap});
    if (!node.waitForFinished(120000) || node.exitCode() != 0)
        qFatal("mcap-check.mjs: %s", node.readAllStandardError().constData());
    return QJsonDocument::fromJson(node.readAllStandardOutput()).object();
}

} // namespace

class TestRecording : public QObject
{
    Q_OBJECT

private slots:
    void routesAsItsFrames_data();
    void routesAsItsFrames();
    void badMapOrRecording_data();
    void badMapOrRecording();
    void usage_data();
    void usage();
    void importMakesASession();
    void importOfABadRecordingMakesNothing();
    void jsonMessagesWithoutAHeader();
    void exportOpensInTheReferenceReader_data();
    void exportOpensInTheReferenceReader();
    void exportImportsBackToTheSameEvents();
};

void TestRecording::routesAsItsFrames_data()
{
    QTest::addColumn<QString>("file");
    QTest::newRow("zstd") << "grasp-zstd.mcap";
    QTest::newRow("lz4") << "grasp-lz4.mcap";
    QTest::newRow("uncompressed") << "grasp-none.mcap";
    QTest::newRow("no chunks, summary or index") << "grasp-stream.mcap";
}

void TestRecording::routesAsItsFrames()
{
    QFETCH(QString, file);
    QTemporaryDir dir;
    const CliResult fromJson = semhapRun(
        {"route", "--router", "C3", "--frames", recording("grasp.frames.jsonl"), "--events",
         dir.filePath("want.events"), "--device-frames", dir.filePath("want.frames")});
    QCOMPARE(fromJson.code, 0);
    const CliResult fromMcap =
        semhapRun({"route", "--router", "C3", "--frames", recording(file), "--topics",
                   recording("grasp.topics.json"), "--events", dir.filePath("got.events"),
                   "--device-frames", dir.filePath("got.frames")});
    QVERIFY2(fromMcap.code == 0, fromMcap.err.constData());
    QCOMPARE(fromMcap.err, QByteArray());
    const QList<QJsonObject> events = readLines(dir.filePath("got.events"));
    // The grasp, its squeeze past the break line, and its end: not an empty agreement.
    QVERIFY(events.size() > 10);
    compareLines(events, readLines(dir.filePath("want.events")));
    compareLines(readLines(dir.filePath("got.frames")), readLines(dir.filePath("want.frames")));
}

void TestRecording::badMapOrRecording_data()
{
    QTest::addColumn<QJsonObject>("map");
    QTest::addColumn<QByteArray>("mcap"); // empty: the zstd recording as it is
    QTest::addColumn<QString>("error");   // MAP and REC stand for the files' paths

    const QJsonObject map = graspMap();
    QTest::newRow("no such topic")
        << changed(map, {"grippers", "right", "left", "topic"}, "/right/left_tip/force")
        << QByteArray()
        << "MAP: /grippers/right/left/topic: REC has no topic '/right/left_tip/force'; its "
           "topics: /operator/note, /right/left_tip/wrench, /right/right_tip/contacts, "
           "/right/right_tip/wrench";
    QTest::newRow("no such field")
        << changed(map, {"grippers", "right", "left", "force"}, "wrench.forc") << QByteArray()
        << "MAP: /grippers/right/left/force: in REC: '/right/left_tip/wrench' "
           "(geometry_msgs/msg/WrenchStamped): 'wrench.forc': geometry_msgs/Wrench has no field "
           "'forc'; its fields: force, torque";
    QTest::newRow("a number for a vector")
        << changed(map, {"grippers", "right", "right", "force"}, "wrench.force.y") << QByteArray()
        << "MAP: /grippers/right/right/force: in REC: '/right/right_tip/wrench' "
           "(geometry_msgs/msg/WrenchStamped): 'wrench.force.y' gives 1 number(s), not the 3 "
           "wanted";
    QTest::newRow("a string for a signal")
        << changed(map, {"grippers", "right", "signals", "left.torque_z", "field"},
                   "header.frame_id")
        << QByteArray()
        << "MAP: /grippers/right/signals/left.torque_z/field: in REC: '/right/left_tip/wrench' "
           "(geometry_msgs/msg/WrenchStamped): 'header.frame_id': 'frame_id' is a string, not a "
           "number";
    QTest::newRow("bad axis") << changed(map, {"grippers", "right", "left", "normal_axis"}, "w")
                              << QByteArray()
                              << "MAP: /grippers/right/left/normal_axis: expected one of x, -x, "
                                 "y, -y, z, -z, got 'w'";
    QTest::newRow("bad time") << changed(map, {"time"}, "receive") << QByteArray()
                              << "MAP: /time: expected 'header' or 'log', got 'receive'";
    QTest::newRow("clock not its own")
        << changed(map, {"grippers", "right", "clock"}, "/operator/note") << QByteArray()
        << "MAP: /grippers/right/clock: '/operator/note' is none of this gripper's topics";

    // The recording damaged: its first chunk's CRC fails, located at the chunk.
    QFile file(recording("grasp-none.mcap"));
    if (!file.open(QIODevice::ReadOnly))
        qFatal("no grasp-none.mcap");
    QByteArray damaged = file.readAll();
    qsizetype at = 8;
    while (quint8(damaged[at]) != 0x06)
        at += 9 + qsizetype(qFromLittleEndian<quint64>(damaged.constData() + at + 1));
    const auto length = qsizetype(qFromLittleEndian<quint64>(damaged.constData() + at + 1));
    damaged[at + 9 + length - 1] ^= 0x5a;
    QTest::newRow("damaged recording")
        << map << damaged << QStringLiteral("REC: offset %1: chunk CRC mismatch").arg(at);
}

void TestRecording::badMapOrRecording()
{
    QFETCH(QJsonObject, map);
    QFETCH(QByteArray, mcap);
    QFETCH(QString, error);
    QTemporaryDir dir;
    const QString mapPath = dir.filePath("map.json");
    write(mapPath, QJsonDocument(map).toJson());
    QString mcapPath = recording("grasp-zstd.mcap");
    if (!mcap.isEmpty()) {
        mcapPath = dir.filePath("robot.mcap");
        write(mcapPath, mcap);
    }
    const QString events = dir.filePath("events.jsonl");
    const CliResult r = semhapRun({"route", "--router", "C3", "--frames", mcapPath, "--topics",
                                   mapPath, "--events", events});
    QCOMPARE(r.code, 1);
    error.replace(QLatin1String("MAP"), mapPath).replace(QLatin1String("REC"), mcapPath);
    QCOMPARE(QString::fromUtf8(r.err).trimmed(), error);
    QVERIFY2(!QFile::exists(events), "nothing is written");
}

void TestRecording::usage_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("error");
    QTest::newRow("a recording without its map")
        << QStringList{"--frames", recording("grasp-zstd.mcap")}
        << "--frames " + recording("grasp-zstd.mcap") +
               ": a recording needs its topic map: --topics MAP.json";
    QTest::newRow("a map without a recording")
        << QStringList{"--frames", recording("grasp.frames.jsonl"), "--topics",
                       recording("grasp.topics.json")}
        << "--topics: only with a recording (--frames FILE.mcap)";
}

void TestRecording::usage()
{
    QFETCH(QStringList, args);
    QFETCH(QString, error);
    const CliResult r = semhapRun(QStringList{"route", "--router", "C3"} + args);
    QCOMPARE(r.code, 2);
    QVERIFY2(QString::fromUtf8(r.err).contains(error), r.err.constData());
}

void TestRecording::importMakesASession()
{
    // The session replays to the events route gives, and exports the frames it was made of.
    QTemporaryDir dir;
    const QString session = dir.filePath("grasp.db");
    const CliResult imported =
        semhapRun({"import", recording("grasp-lz4.mcap"), "--topics",
                   recording("grasp.topics.json"), "--session", session, "--notes", "bench 3"});
    QVERIFY2(imported.code == 0, imported.err.constData());
    QVERIFY2(imported.err.contains(": 1000 frame(s) from "), imported.err.constData());
    const CliResult replayed =
        semhapRun({"replay", session, "--events", dir.filePath("replayed.events")});
    QVERIFY2(replayed.code == 0, replayed.err.constData());
    const CliResult routed =
        semhapRun({"route", "--router", "C3", "--frames", recording("grasp.frames.jsonl"),
                   "--events", dir.filePath("routed.events")});
    QCOMPARE(routed.code, 0);
    compareLines(readLines(dir.filePath("replayed.events")),
                 readLines(dir.filePath("routed.events")));
    const CliResult exported = semhapRun({"export", session, "--jsonl", dir.filePath("out")});
    QVERIFY2(exported.code == 0, exported.err.constData());
    QCOMPARE(readLines(dir.filePath("out/frames.jsonl")).size(), 1000);
    const QList<QJsonObject> events = readLines(dir.filePath("out/events.jsonl"));
    compareLines(events, readLines(dir.filePath("routed.events")));
}

void TestRecording::importOfABadRecordingMakesNothing()
{
    QTemporaryDir dir;
    const QString session = dir.filePath("none.db");
    QJsonObject map = changed(graspMap(), {"grippers", "right", "left", "topic"}, "/nope");
    write(dir.filePath("map.json"), QJsonDocument(map).toJson());
    const CliResult r = semhapRun({"import", recording("grasp-zstd.mcap"), "--topics",
                                   dir.filePath("map.json"), "--session", session});
    QCOMPARE(r.code, 1);
    QVERIFY2(r.err.contains("has no topic '/nope'"), r.err.constData());
    QVERIFY(!QFile::exists(session));
    // And a session is never overwritten.
    write(session, "precious");
    const CliResult again = semhapRun({"import", recording("grasp-zstd.mcap"), "--topics",
                                       recording("grasp.topics.json"), "--session", session});
    QCOMPARE(again.code, 1);
    QFile kept(session);
    QVERIFY(kept.open(QIODevice::ReadOnly));
    QCOMPARE(kept.readAll(), QByteArray("precious"));
}

void TestRecording::jsonMessagesWithoutAHeader()
{
    // A JSON topic (the operator's notes, no header) read as a signal: each note is timed by
    // its log time, and a frame carries the latest logged at or before its stamp.
    QTemporaryDir dir;
    const QJsonObject map = changed(graspMap(), {"grippers", "right", "signals", "note.i"},
                                    QJsonObject{{"topic", "/operator/note"}, {"field", "i"}});
    write(dir.filePath("map.json"), QJsonDocument(map).toJson());
    const QString session = dir.filePath("notes.db");
    const CliResult imported = semhapRun({"import", recording("grasp-zstd.mcap"), "--topics",
                                          dir.filePath("map.json"), "--session", session});
    QVERIFY2(imported.code == 0, imported.err.constData());
    QCOMPARE(semhapRun({"export", session, "--jsonl", dir.filePath("j")}).code, 0);
    const QList<QJsonObject> frames = readLines(dir.filePath("j/frames.jsonl"));
    QCOMPARE(frames.size(), 1000);
    // Its times are the recording's: an import keeps no steady clock, and cannot be put on
    // LSL's (docs/science.md).
    const CliResult lsl =
        semhapRun({"export", session, "--xdf", dir.filePath("n.xdf"), "--time", "lsl"});
    QCOMPARE(lsl.code, 1);
    QVERIFY2(lsl.err.contains("cannot be put on the LSL clock: it was imported from a "
                              "recording, whose times are the recording's"),
             lsl.err.constData());
    // Notes are logged every 100 ticks; a frame's stamp is 3 ms (1.5 ticks) before its log.
    for (int j = 0; j < frames.size(); ++j) {
        const QJsonValue note = frames[j]["signals"].toObject().value("note.i");
        if (j < 2)
            QVERIFY2(note.isUndefined(), qPrintable(QString::number(j)));
        else
            QCOMPARE(note.toDouble(), double((j - 2) / 100 * 100));
    }
}

void TestRecording::exportOpensInTheReferenceReader_data()
{
    QTest::addColumn<QStringList>("make"); // the command that makes the session, then its path
    QTest::newRow("an imported recording")
        << QStringList{"import", recording("grasp-zstd.mcap"), "--topics",
                       recording("grasp.topics.json"), "--session"};
    QTest::newRow("a simulated run, both grippers")
        << QStringList{"run",        "--scene",  "bimanual_sorting", "--router", "C3",
                       "--operator", "scripted", "--duration",       "1",        "--session"};
}

void TestRecording::exportOpensInTheReferenceReader()
{
    QFETCH(QStringList, make);
    QTemporaryDir dir;
    const QString session = dir.filePath("s.db");
    const CliResult made = semhapRun(make << session);
    QVERIFY2(made.code == 0, made.err.constData());
    const QString mcap = dir.filePath("s.mcap");
    const CliResult exported = semhapRun({"export", session, "--mcap", mcap});
    QVERIFY2(exported.code == 0, exported.err.constData());
    QCOMPARE(exported.err, QByteArray());
    const CliResult jsonl = semhapRun({"export", session, "--jsonl", dir.filePath("j")});
    QCOMPARE(jsonl.code, 0);
    const QList<QJsonObject> frames = readLines(dir.filePath("j/frames.jsonl"));
    const QList<QJsonObject> events = readLines(dir.filePath("j/events.jsonl"));
    const QList<QJsonObject> deviceFrames = readLines(dir.filePath("j/device_frames.jsonl"));

    const QJsonObject read = referenceRead(mcap);
    QCOMPARE(read["profile"].toString(), QString("ros2"));
    QVERIFY(read["chunks"].toInt() >= 1);
    QVERIFY(read["streamDone"].toBool()); // every CRC checked, start to end
    QCOMPARE(read["undecoded"].toArray(), QJsonArray());
    // Every frame, none decimated: each gripper's contact and tips, each event, each band's.
    const QJsonObject counts = read["counts"].toObject();
    int total = 0;
    for (const QJsonValue &count : counts)
        total += count.toInt();
    QCOMPARE(read["statisticsMessageCount"].toString(), QString::number(total));
    QHash<QString, int> perGripper;
    for (const QJsonObject &f : frames)
        ++perGripper[f["gripper"].toString()];
    for (auto it = perGripper.begin(); it != perGripper.end(); ++it) {
        QCOMPARE(counts[QStringLiteral("/semhap/%1/contact").arg(it.key())].toInt(), it.value());
        QCOMPARE(counts[QStringLiteral("/semhap/%1/left/wrench").arg(it.key())].toInt(),
                 it.value());
    }
    QCOMPARE(counts["/semhap/events"].toInt(), events.size());
    QHash<QString, int> perDevice;
    for (const QJsonObject &f : deviceFrames)
        ++perDevice[f["device"].toString()];
    for (auto it = perDevice.begin(); it != perDevice.end(); ++it)
        QCOMPARE(counts["/semhap/devices/" + it.key()].toInt(), it.value());
    QCOMPARE(read["schemas"]
                 .toObject()[QStringLiteral("/semhap/%1/contact")
                                 .arg(frames.first()["gripper"].toString())]
                 .toString(),
             QString("semhap_msgs/msg/ContactFrame"));
    if (!events.isEmpty())
        QCOMPARE(read["schemas"].toObject()["/semhap/events"].toString(),
                 QString("semhap_msgs/msg/SemanticEvent"));
    QVERIFY(read["metadata"].toObject()["semhap"].toObject().contains("time_origin"));
    QVERIFY(read["metadata"].toObject()["router"].toObject()["json"].toString().contains(
        "semhap.router/1"));

    // The last frame of the first gripper, as the reference decoder reads it.
    const QString gripper = frames.last()["gripper"].toString();
    QJsonObject lastFrame;
    for (const QJsonObject &f : frames) {
        if (f["gripper"].toString() == gripper)
            lastFrame = f;
    }
    const QJsonObject decoded =
        read["last"].toObject()[QStringLiteral("/semhap/%1/contact").arg(gripper)].toObject();
    QCOMPARE(decoded["header"].toObject()["frame_id"].toString(), gripper);
    for (const char *tip : {"left", "right"}) {
        const QJsonObject want = lastFrame[tip].toObject();
        const QJsonObject got = decoded[tip].toObject();
        QCOMPARE(got["f"].toDouble(), want["f"].toDouble());
        QCOMPARE(got["n"].toInt(), want["n"].toInt());
        QCOMPARE(got["actor"].toString(), want["actor"].toString());
    }
    const QJsonObject wrench =
        read["last"].toObject()[QStringLiteral("/semhap/%1/left/wrench").arg(gripper)].toObject();
    const QJsonArray fxyz = lastFrame["left"].toObject()["fxyz"].toArray();
    if (!fxyz.isEmpty())
        QCOMPARE(wrench["wrench"].toObject()["force"].toObject()["y"].toDouble(),
                 fxyz[1].toDouble());
}

void TestRecording::exportImportsBackToTheSameEvents()
{
    // Export and import are one mapping read two ways: `--topics semhap` reads an export.
    QTemporaryDir dir;
    const QString first = dir.filePath("first.db");
    QCOMPARE(semhapRun({"import", recording("grasp-none.mcap"), "--topics",
                        recording("grasp.topics.json"), "--session", first})
                 .code,
             0);
    QCOMPARE(semhapRun({"export", first, "--mcap", dir.filePath("first.mcap")}).code, 0);
    const QString second = dir.filePath("second.db");
    const CliResult back = semhapRun(
        {"import", dir.filePath("first.mcap"), "--topics", "semhap", "--session", second});
    QVERIFY2(back.code == 0, back.err.constData());
    QCOMPARE(semhapRun({"replay", first, "--events", dir.filePath("first.events")}).code, 0);
    QCOMPARE(semhapRun({"replay", second, "--events", dir.filePath("second.events")}).code, 0);
    const QList<QJsonObject> events = readLines(dir.filePath("second.events"));
    QVERIFY(events.size() > 10);
    compareLines(events, readLines(dir.filePath("first.events")));
}

QTEST_GUILESS_MAIN(TestRecording)
#include "tst_recording.moc"
