// SPDX-License-Identifier: MIT
// Sessions from the command line: run --session records without changing the run's
// outputs, replay and re-routing give what route gives, export, listen over UDP, and a
// recording killed with SIGKILL loses at most ~100 ms and still opens.
#include "clitool.h"
#include "nametable.h"
#include "sessionblocks.h"
#include "sessionreader.h"

#include <QBuffer>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QHostAddress>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QSqlDatabase>
#include <QSqlQuery>
#include <QTemporaryDir>
#include <QTest>
#include <QUdpSocket>

#include <algorithm>

using namespace semhap;

namespace {

const QString Trace = QStringLiteral(SEMHAP_RESOURCES "/traces/demo.jsonl");

struct Result
{
    int code;
    QByteArray out;
    QByteArray err;
};

Result semhapRun(const QStringList &arguments)
{
    QByteArray in;
    QBuffer inBuffer(&in);
    inBuffer.open(QIODevice::ReadOnly);
    Result r{0, {}, {}};
    QBuffer outBuffer(&r.out);
    QBuffer errBuffer(&r.err);
    outBuffer.open(QIODevice::WriteOnly);
    errBuffer.open(QIODevice::WriteOnly);
    CliTool tool({&inBuffer, &outBuffer, &errBuffer});
    r.code = tool.run(arguments);
    return r;
}

QByteArray contents(const QString &path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray("(missing)");
}

/**
 * Copies `session` to `copy` and runs the SQL `statements` on the copy: a session as
 * another program (or a damaged file) may have written it. False when one fails.
 */
bool alteredCopy(const QString &session, const QString &copy, const QStringList &statements)
{
    if (!QFile::copy(session, copy))
        return false;
    bool ok = true;
    {
        QSqlDatabase db = QSqlDatabase::addDatabase("QSQLITE", copy);
        db.setDatabaseName(copy);
        QSqlQuery query(db);
        ok = db.open();
        for (const QString &statement : statements)
            ok = ok && query.exec(statement);
    }
    QSqlDatabase::removeDatabase(copy);
    return ok;
}

/** Starts `semhap listen` on a free port; returns the port, 0 when it did not start. */
quint16 startListen(QProcess &listen, const QStringList &arguments, QByteArray *err)
{
    listen.start(SEMHAP_CLI_BINARY, QStringList{"listen", "--udp", "0"} + arguments);
    if (!listen.waitForStarted())
        return 0;
    listen.setReadChannel(QProcess::StandardError);
    while (!err->contains('\n') && listen.waitForReadyRead(5000))
        *err += listen.readAllStandardError();
    listen.setReadChannel(QProcess::StandardOutput);
    const QByteArray first = err->left(err->indexOf('\n'));
    if (!first.startsWith("listening on udp:127.0.0.1:"))
        return 0;
    return quint16(first.mid(first.lastIndexOf(':') + 1).toInt());
}

/** A right-gripper frame pressing `force` N on a cube. */
QByteArray pressing(double t, double force)
{
    return QStringLiteral(R"({"t":%1,"gripper":"right","left":{"f":%2,"n":8,"actor":"cube"},)"
                          R"("right":{"f":%2,"n":8,"actor":"cube"}})")
        .arg(t)
        .arg(force / 2)
        .toUtf8();
}

const QStringList RunArgs{"run",        "--scene",  "bimanual_sorting", "--router", "C3",
                          "--operator", "scripted", "--duration",       "20"};

} // namespace

class TestSessionCli : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void recordingChangesNoOutput();
    void recordsSceneStates();
    void replayGivesTheRecordedStreams();
    void rerouteEqualsRoute();
    void replayKeepsTheReactionTime();
    void replayOfAFarFrameEnds();
    void exportCsv();
    void exportNestsJsonMetadata();
    void errors_data();
    void errors();
    void listenRunsLikeRoute();
    void aRigsSignalsDriveTheRouter();
    void killedRecordingOpens();
    void listenRefusesJumpsAndStopsOnTime();
    void listenEndsMessagesWhenTheSenderFallsSilent();
    void listenClosesItsSessionOnSigterm();
    void runClosesItsSessionOnSigterm();

private:
    QTemporaryDir m_dir;
    QString m_session;
};

void TestSessionCli::initTestCase()
{
    m_session = m_dir.filePath("c3.db");
    const QStringList outputs{"--events",        m_dir.filePath("with.events"),
                              "--device-frames", m_dir.filePath("with.devices"),
                              "--frames",        m_dir.filePath("with.frames")};
    const Result r = semhapRun(RunArgs + outputs + QStringList{"--session", m_session});
    QCOMPARE(r.code, 0);
    QCOMPARE(r.err, QByteArray());
}

void TestSessionCli::recordingChangesNoOutput()
{
    const Result r =
        semhapRun(RunArgs + QStringList{"--events", m_dir.filePath("without.events"),
                                        "--device-frames", m_dir.filePath("without.devices"),
                                        "--frames", m_dir.filePath("without.frames")});
    QCOMPARE(r.code, 0);
    for (const char *stream : {"events", "devices", "frames"}) {
        const QByteArray with = contents(m_dir.filePath(QString("with.") + stream));
        QVERIFY(with.count('\n') > 5); // a grasp of each hand and a slip, at least
        QCOMPARE(with, contents(m_dir.filePath(QString("without.") + stream)));
    }
}

void TestSessionCli::recordsSceneStates()
{
    QString error;
    std::unique_ptr<SessionReader> session = SessionReader::open(m_session, &error);
    QVERIFY2(session, qPrintable(error));
    QCOMPARE(session->schemaVersion(), SessionInfo::SchemaVersion);
    // 30 a simulated second, the first at the first step.
    const double seconds = session->endTime() - session->startTime();
    QVERIFY2(std::abs(double(session->sceneStateCount()) - seconds * 30) <= 2,
             qPrintable(QString::number(session->sceneStateCount())));
    SceneState first;
    SceneState last;
    QVERIFY(session->readSceneState(0.0, &first, &error));
    QVERIFY(session->readSceneState(1e9, &last, &error));
    QVERIFY(first.pose.size() > 20);
    QCOMPARE(last.pose.size(), first.pose.size());
    QVERIFY(last.pose != first.pose); // the grippers moved
}

void TestSessionCli::replayGivesTheRecordedStreams()
{
    const Result events = semhapRun({"replay", m_session, "--events", "-"});
    QCOMPARE(events.code, 0);
    QCOMPARE(events.out, contents(m_dir.filePath("with.events")));
    // Both hands took part: the slip detector's events are there too.
    QVERIFY(events.out.contains("\"left.slip\""));
    const Result devices = semhapRun({"replay", m_session, "--device-frames", "-"});
    QCOMPARE(devices.out, contents(m_dir.filePath("with.devices")));
}

void TestSessionCli::rerouteEqualsRoute()
{
    const QString jsonl = m_dir.filePath("jsonl");
    QCOMPARE(semhapRun({"export", m_session, "--jsonl", jsonl}).code, 0);
    QCOMPARE(contents(jsonl + "/frames.jsonl"), contents(m_dir.filePath("with.frames")));
    for (const char *stream : {"--events", "--device-frames"}) {
        const Result replay = semhapRun({"replay", m_session, "--router", "C1", stream, "-"});
        const Result route = semhapRun(
            {"route", "--router", "C1", "--frames", jsonl + "/frames.jsonl", stream, "-"});
        QCOMPARE(replay.code, 0);
        QCOMPARE(route.code, 0);
        QVERIFY(route.out.count('\n') > 5);
        QCOMPARE(replay.out, route.out);
    }
    // C1 confirms on the vibration band where C3 squeezes: a different design indeed.
    const Result c1 = semhapRun({"replay", m_session, "--router", "C1", "--metrics", "-"});
    const QJsonObject metrics = QJsonDocument::fromJson(c1.out).object();
    QCOMPARE(metrics.value("router").toString(), QString("C1"));
    QVERIFY(metrics.value("messages").toObject().contains("right.force.grasp"));
}

void TestSessionCli::replayKeepsTheReactionTime()
{
    // A predict node's horizon holds the person's reaction time: a session replays with the
    // one it was recorded with, and --reaction-time asks what another person would have felt.
    // A low break level makes every grasp cross it, so the horizon shows in the begin times.
    const QString session = m_dir.filePath("slow.db");
    const QString recorded = m_dir.filePath("slow.events");
    const QStringList run =
        QStringList{"run", "--scene", "box_and_block", "--router", "C3p", "--operator"} +
        QStringList{"scripted", "--duration", "10", "--reaction-time", "0.6"} +
        QStringList{"--set", "right.break.begin=30", "--set", "right.break.end=27"} +
        QStringList{"--events", recorded, "--session", session};
    QCOMPARE(semhapRun(run).code, 0);
    QVERIFY(contents(recorded).contains("\"right.break\""));
    QString error;
    std::unique_ptr<SessionReader> reader = SessionReader::open(session, &error);
    QVERIFY2(reader, qPrintable(error));
    QCOMPARE(reader->info().routerContext.reactionTime, 0.6);
    reader.reset();

    const Result same = semhapRun({"replay", session, "--events", "-"});
    QCOMPARE(same.code, 0);
    QCOMPARE(same.out, contents(recorded));
    const Result quicker =
        semhapRun({"replay", session, "--reaction-time", "0.25", "--events", "-"});
    QCOMPARE(quicker.code, 0);
    QVERIFY(quicker.out.contains("\"right.break\""));
    QVERIFY(quicker.out != same.out);
    const Result bad = semhapRun({"replay", session, "--reaction-time", "11", "--events", "-"});
    QCOMPARE(bad.code, 2);
    QVERIFY2(bad.err.contains("--reaction-time must be between 0 and 10 s"), bad.err.constData());
}

void TestSessionCli::replayOfAFarFrameEnds()
{
    // A session row a billion seconds on used to make replay render every device instant
    // in between: it never ended.
    const QString far = m_dir.filePath("far.db");
    QVERIFY(alteredCopy(m_session, far,
                        {insertBlock(SessionSchema::Stream::ContactFrames, emptyContactRow(1e9, 0),
                                     SessionSchema::ContactColumns)}));
    const Result replay = semhapRun({"replay", far, "--device-frames", "-"});
    QCOMPARE(replay.code, 0);
    QVERIFY(replay.out.count('\n') < contents(m_dir.filePath("with.devices")).count('\n') + 8000);
}

void TestSessionCli::exportCsv()
{
    const QString csv = m_dir.filePath("csv");
    QCOMPARE(semhapRun({"export", m_session, "--csv", csv}).code, 0);
    const QList<QByteArray> frames = contents(csv + "/contact_frames.csv").trimmed().split('\n');
    QCOMPARE(frames.first(), QByteArray("t,gripper,left_f,left_n,left_actor,left_fx,left_fy,"
                                        "left_fz,left_mu,right_f,right_n,right_actor,right_fx,"
                                        "right_fy,right_fz,right_mu,arrival"));
    // The simulation knows the friction coefficient of what a finger touches.
    QVERIFY(std::any_of(frames.begin() + 1, frames.end(), [](const QByteArray &row) {
        return row.split(',').at(8).toDouble() > 0;
    }));
    QCOMPARE(frames.size() - 1, contents(m_dir.filePath("with.frames")).count('\n'));
    const QList<QByteArray> devices = contents(csv + "/device_frames.csv").split('\n');
    QVERIFY(devices.first().startsWith("t,left.air.b1,"));
    QVERIFY(devices.first().contains(",right.vibro.m4"));
    QCOMPARE(devices.first().count(','), 28); // 7 devices, 28 channels
    const QJsonObject metadata =
        QJsonDocument::fromJson(contents(csv + "/metadata.json")).object();
    QCOMPARE(metadata.value("scene").toString(), QString("bimanual_sorting"));
    QCOMPARE(metadata.value("router").toObject().value("format").toString(),
             QString("semhap.router/1"));
    QVERIFY(contents(csv + "/events.csv").startsWith("t,gripper,node,detector,message,"));
    QCOMPARE(contents(csv + "/operator_input.csv"), QByteArray("t,hand,x,y,z,qw,qx,qy,qz,grip\n"));
}

void TestSessionCli::exportNestsJsonMetadata()
{
    // A studio recording started mid-grasp lists what it began with; its metadata.json held
    // that list as a string of JSON while router, bindings and overrides were nested.
    const QString session = m_dir.filePath("open.db");
    // Text that reads as JSON is still text under a key that is not JSON (notes).
    QVERIFY(alteredCopy(m_session, session,
                        {"INSERT INTO metadata (key, value) VALUES ('open_at_start', "
                         "'[{\"message\":\"grasp\",\"node\":\"right.force\"}]')",
                         "UPDATE metadata SET value = '[1]' WHERE key = 'notes'"}));
    const QString csv = m_dir.filePath("open-csv");
    QCOMPARE(semhapRun({"export", session, "--csv", csv}).code, 0);
    const QJsonObject metadata =
        QJsonDocument::fromJson(contents(csv + "/metadata.json")).object();
    const QJsonArray open = metadata.value("open_at_start").toArray();
    QCOMPARE(open.size(), 1);
    QCOMPARE(open.at(0).toObject().value("node").toString(), QString("right.force"));
    QCOMPARE(open.at(0).toObject().value("message").toString(), QString("grasp"));
    QVERIFY(metadata.value("router").isObject());
    QVERIFY(metadata.value("bindings").isObject());
    QVERIFY(metadata.value("overrides").isArray());
    QCOMPARE(metadata.value("notes").toString(), QString("[1]"));
    QCOMPARE(metadata.value("schema_version").toString(), QString("5"));
}

void TestSessionCli::errors_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<int>("code");
    QTest::addColumn<QString>("firstLine");
    QTest::newRow("replay without session")
        << QStringList{"replay"} << 2 << "semhap replay: a session file is required";
    QTest::newRow("replay of a trace")
        << QStringList{"replay", Trace} << 1
        << Trace + ": not a semhap session (not an SQLite database)";
    QTest::newRow("replay of nothing")
        << QStringList{"replay", "/nonexistent.db"} << 1
        << "/nonexistent.db: cannot read: No such file or directory";
    QTest::newRow("export without format")
        << QStringList{"export", Trace} << 2
        << "semhap export: --csv DIR, --jsonl DIR, --mcap FILE or --xdf FILE is required";
    // The export's writer runs on a thread of its own; its write errors still end it.
    QTest::newRow("export to a full disk")
        << QStringList{"export", m_session, "--mcap", "/dev/full"} << 1
        << "/dev/full: cannot write: No space left on device";
    QTest::newRow("listen without a source")
        << QStringList{"listen"} << 2
        << "semhap listen: give one source: --udp PORT or --foxglove ws://HOST:PORT";
    QTest::newRow("listen to two sources")
        << QStringList{"listen", "--udp", "0", "--foxglove", "ws://robot:8765"} << 2
        << "semhap listen: give one source: --udp PORT or --foxglove ws://HOST:PORT";
    QTest::newRow("a robot without its map")
        << QStringList{"listen", "--foxglove", "ws://robot:8765"} << 2
        << "semhap listen: --foxglove needs the map of its topics: --topics MAP.json";
    QTest::newRow("a robot that is not a WebSocket")
        << QStringList{"listen", "--foxglove", "http://robot:8765", "--topics", "map.json"} << 2
        << "semhap listen: --foxglove: expected ws://HOST:PORT, got 'http://robot:8765'";
    QTest::newRow("listen on a bad address")
        << QStringList{"listen", "--udp", "0", "--address", "localhostt"} << 1
        << "localhostt: not an IP address";
    // The 1.0 spelling of the address is still read, with a warning first.
    QTest::newRow("listen --bind ADDR, deprecated")
        << QStringList{"listen", "--udp", "0", "--bind", "localhostt"} << 1
        << "listen: --bind localhostt: deprecated: the address to listen on is --address; "
           "--bind binds a device (NAME=URI)";
}

void TestSessionCli::errors()
{
    QFETCH(QStringList, args);
    QFETCH(int, code);
    QFETCH(QString, firstLine);
    const Result r = semhapRun(args);
    QCOMPARE(r.code, code);
    QCOMPARE(QString::fromUtf8(r.err.split('\n').first()), firstLine);
}

void TestSessionCli::listenRunsLikeRoute()
{
    const QString session = m_dir.filePath("live.db");
    QProcess listen;
    QByteArray err;
    // A long --silence: a stalled test machine must not end messages route would not.
    const quint16 port = startListen(listen,
                                     {"--duration", "5", "--router", "C1", "--events", "-",
                                      "--session", session, "--silence", "60"},
                                     &err);
    QVERIFY2(port, err.constData());

    QFile trace(Trace);
    QVERIFY(trace.open(QIODevice::ReadOnly));
    const QList<QByteArray> lines = trace.readAll().trimmed().split('\n');
    QUdpSocket sender;
    const auto send = [&](const QByteArray &datagram) {
        sender.writeDatagram(datagram, QHostAddress::LocalHost, port);
    };
    send("garbage");
    // Batches of 4 frames as JSON arrays, then the rest one per datagram.
    int i = 0;
    for (; i + 4 <= lines.size() / 2; i += 4) {
        send('[' + lines.mid(i, 4).join(',') + ']');
        QThread::usleep(300);
    }
    for (; i < lines.size(); ++i) {
        send(lines[i]);
        QThread::usleep(100);
    }
    send(QByteArray(40000, '{'));
    QVERIFY(listen.waitForFinished(15000));
    QCOMPARE(listen.exitCode(), 0);
    const QByteArray events = listen.readAllStandardOutput();
    err += listen.readAllStandardError();

    const Result route =
        semhapRun({"route", "--router", "C1", "--frames", Trace, "--events", "-"});
    QCOMPARE(events, route.out);
    const QList<QByteArray> report = err.trimmed().split('\n');
    QVERIFY2(report.last().endsWith(": 2002 datagram(s), 3200 frame(s), 2 rejected (1 oversize)"),
             err.constData());

    QString error;
    auto recorded = SessionReader::open(session, &error);
    QVERIFY2(recorded, qPrintable(error));
    QCOMPARE(recorded->contactFrameCount(), qint64(3200));
    QCOMPARE(recorded->info().source, QString("listen"));
    double lastArrival = -1;
    QVERIFY(recorded->readContactFrames(
        [&](const ContactFrame &, double arrival) {
            const bool ok = arrival >= lastArrival; // received in order, stamped on arrival
            lastArrival = arrival;
            return ok;
        },
        &error));
    QVERIFY(lastArrival > 0);
}

void TestSessionCli::aRigsSignalsDriveTheRouter()
{
    // A rig sends its wrist sensor's force as a signal; a router of generic nodes warns when
    // it passes 20 N, exactly as `route` does on the same frames, and the session keeps them.
    const QString router = m_dir.filePath("wrist.json");
    QFile file(router);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(R"({"format": "semhap.router/1", "nodes": [
        {"id": "fz", "type": "signal", "params": {"gripper": "right", "quantity": "wrist.fz"}},
        {"id": "hard", "type": "threshold", "params": {"gripper": "right", "message": "hard",
         "category": "exception", "begin": 20, "end": 18, "intensity": [20, 30]}}],
        "links": [{"from": "fz", "to": "hard"}]})");
    file.close();
    QByteArray frames;
    for (int k = 0; k < 40; ++k) {
        frames += QStringLiteral(R"({"t":%1,"gripper":"right","signals":{"wrist.fz":%2}})")
                      .arg(k * 0.01)
                      .arg(k < 20 ? k * 1.5 : 30 - (k - 20) * 1.5)
                      .toUtf8() +
                  '\n';
    }
    const QString trace = m_dir.filePath("wrist.jsonl");
    QFile traceFile(trace);
    QVERIFY(traceFile.open(QIODevice::WriteOnly));
    traceFile.write(frames);
    traceFile.close();

    const QString session = m_dir.filePath("wrist.db");
    QProcess listen;
    QByteArray err;
    const quint16 port = startListen(listen,
                                     {"--duration", "3", "--router", router, "--events", "-",
                                      "--session", session, "--silence", "60"},
                                     &err);
    QVERIFY2(port, err.constData());
    QUdpSocket sender;
    for (const QByteArray &line : frames.trimmed().split('\n')) {
        sender.writeDatagram(line, QHostAddress::LocalHost, port);
        QThread::usleep(200);
    }
    QVERIFY(listen.waitForFinished(15000));
    QCOMPARE(listen.exitCode(), 0);
    const QByteArray events = listen.readAllStandardOutput();
    const Result route =
        semhapRun({"route", "--router", router, "--frames", trace, "--events", "-"});
    QCOMPARE(route.code, 0);
    QCOMPARE(events, route.out);
    QVERIFY2(events.contains(R"("message":"hard","category":"exception","phase":"begin")"),
             events.constData());
    QVERIFY(events.contains(R"("phase":"end")"));

    QString error;
    auto recorded = SessionReader::open(session, &error);
    QVERIFY2(recorded, qPrintable(error));
    const int fz = signalNames().intern("wrist.fz");
    int withSignal = 0;
    QVERIFY(recorded->readContactFrames(
        [&](const ContactFrame &frame, double) {
            withSignal += frame.signalValues.find(fz) != nullptr;
            return true;
        },
        &error));
    QCOMPARE(withSignal, 40);

    // export writes them: tidy in signals.csv, in the frames in frames.jsonl.
    const QString out = m_dir.filePath("wrist-export");
    QCOMPARE(semhapRun({"export", session, "--csv", out, "--jsonl", out}).code, 0);
    const QList<QByteArray> rows = contents(out + "/signals.csv").trimmed().split('\n');
    QCOMPARE(rows.size(), 41);
    QCOMPARE(rows[0], QByteArray("t,gripper,signal,value"));
    QCOMPARE(rows[3], QByteArray("0.02,right,wrist.fz,3"));
    QCOMPARE(contents(out + "/frames.jsonl").count(R"("signals":{"wrist.fz":)"), 40);
}

void TestSessionCli::listenRefusesJumpsAndStopsOnTime()
{
    // One datagram at t = 1e9 used to wedge listen for ever: --duration and signals ignored.
    QProcess listen;
    QByteArray err;
    const quint16 port = startListen(listen, {"--duration", "2", "--device-frames", "-"}, &err);
    QVERIFY2(port, err.constData());
    QUdpSocket sender;
    sender.writeDatagram(pressing(0, 0), QHostAddress::LocalHost, port);
    sender.writeDatagram(pressing(1e9, 0), QHostAddress::LocalHost, port);
    sender.writeDatagram(pressing(0.01, 0), QHostAddress::LocalHost, port);
    QElapsedTimer clock;
    clock.start();
    QVERIFY(listen.waitForFinished(10000));
    QVERIFY(clock.elapsed() < 4000);
    QCOMPARE(listen.exitCode(), 0);
    err += listen.readAllStandardError();
    QVERIFY2(err.contains(": \"t\" jumps by 1e+09 s, more than the 10 s allowed (--max-gap)"),
             err.constData());
    QVERIFY2(err.contains(": 3 datagram(s), 2 frame(s), 1 rejected"), err.constData());
}

void TestSessionCli::listenEndsMessagesWhenTheSenderFallsSilent()
{
    QProcess listen;
    QByteArray err;
    const quint16 port = startListen(listen, {"--duration", "3", "--events", "-"}, &err);
    QVERIFY2(port, err.constData());
    QUdpSocket sender;
    // A grasp begins (C3: 20 N) and the sender goes quiet holding it.
    for (int k = 0; k <= 50; ++k)
        sender.writeDatagram(pressing(k * 0.002, 50), QHostAddress::LocalHost, port);
    QVERIFY(listen.waitForFinished(10000));
    QCOMPARE(listen.exitCode(), 0);
    const QList<QByteArray> events = listen.readAllStandardOutput().trimmed().split('\n');
    err += listen.readAllStandardError();
    QCOMPARE(events.size(), 2);
    QVERIFY2(events[0].contains(R"("node":"right.force","detector":"force","message":"grasp")") &&
                 events[0].contains(R"("phase":"begin")"),
             events[0].constData());
    // It ends at the pipeline's clock, the last frame's time: the sender's time stood still.
    QVERIFY2(events[1].startsWith(R"({"t":0.1,)") && events[1].contains(R"("phase":"end")"),
             events[1].constData());
    QVERIFY2(err.contains(": no frame for 0.25 s: messages ended, bands stopped"),
             err.constData());
}

void TestSessionCli::listenClosesItsSessionOnSigterm()
{
    const QString session = m_dir.filePath("terminated.db");
    QProcess listen;
    QByteArray err;
    // With a band bound, a signal used to stop it and end the process there, the session
    // left unclosed.
    const quint16 port =
        startListen(listen, {"--session", session, "--bind", "right.vibro=virtual:band"}, &err);
    QVERIFY2(port, err.constData());
    QUdpSocket sender;
    for (int k = 0; k < 10; ++k)
        sender.writeDatagram(pressing(k * 0.002, 30), QHostAddress::LocalHost, port);
    QThread::msleep(300);
    listen.terminate();
    QVERIFY(listen.waitForFinished(5000));
    QCOMPARE(listen.exitStatus(), QProcess::NormalExit);
    QCOMPARE(listen.exitCode(), 0);
    QString error;
    std::unique_ptr<SessionReader> recorded = SessionReader::open(session, &error);
    QVERIFY2(recorded, qPrintable(error));
    QVERIFY(recorded->info().ended.isValid()); // closed, not abandoned
    QCOMPARE(recorded->contactFrameCount(), qint64(10));
}

void TestSessionCli::runClosesItsSessionOnSigterm()
{
    const QString session = m_dir.filePath("run-terminated.db");
    const QString frames = m_dir.filePath("run-terminated.jsonl");
    QProcess run;
    run.start(SEMHAP_CLI_BINARY,
              {"run", "--scene", "box_and_block", "--router", "C3", "--operator", "scripted",
               "--duration", "600", "--realtime", "--session", session, "--frames", frames});
    QVERIFY(run.waitForStarted());
    QTRY_VERIFY_WITH_TIMEOUT(QFileInfo::exists(session), 10000);
    QThread::msleep(1000);
    run.terminate();
    QVERIFY(run.waitForFinished(10000));
    QCOMPARE(run.exitStatus(), QProcess::NormalExit);
    QCOMPARE(run.exitCode(), 0);
    QVERIFY(run.readAllStandardError().contains("run: interrupted at t = "));
    QString error;
    std::unique_ptr<SessionReader> recorded = SessionReader::open(session, &error);
    QVERIFY2(recorded, qPrintable(error));
    QVERIFY(recorded->info().ended.isValid()); // closed, not abandoned
    QVERIFY(recorded->endTime() > 0.5);
    // The frames written through a temporary were handed over too.
    QVERIFY(contents(frames).startsWith("{\"t\":"));
}

void TestSessionCli::killedRecordingOpens()
{
    // The run paces itself to the wall clock and flushes each tick's frames: the last
    // frame on its standard output is one it had already handed to the recorder.
    const QString session = m_dir.filePath("killed.db");
    QProcess run;
    run.start(SEMHAP_CLI_BINARY,
              {"run", "--scene", "box_and_block", "--router", "C3", "--operator", "scripted",
               "--duration", "60", "--realtime", "--session", session, "--frames", "-"});
    QVERIFY(run.waitForStarted());
    QByteArray out;
    QElapsedTimer clock;
    while (out.isEmpty() && run.waitForReadyRead(10000))
        out += run.readAllStandardOutput();
    clock.start();
    while (clock.elapsed() < 1500) {
        run.waitForReadyRead(50);
        out += run.readAllStandardOutput();
    }
    run.kill(); // SIGKILL: no clean-up at all
    QVERIFY(run.waitForFinished(5000));
    out += run.readAllStandardOutput();
    QCOMPARE(run.exitStatus(), QProcess::CrashExit);

    const QList<QByteArray> lines = out.left(out.lastIndexOf('\n')).split('\n');
    const double reported = QJsonDocument::fromJson(lines.last()).object().value("t").toDouble();
    QVERIFY2(reported > 1.0, qPrintable(QString::number(reported)));

    QString error;
    auto killed = SessionReader::open(session, &error);
    QVERIFY2(killed, qPrintable(error));
    QVERIFY(!killed->info().ended.isValid()); // it never closed
    // At most ~100 ms lost (50 ms batches), plus a margin for a busy machine.
    QVERIFY2(
        killed->endTime() >= reported - 0.25,
        qPrintable(
            QString("recorded up to %1 s, reported %2 s").arg(killed->endTime()).arg(reported)));
    qInfo("killed at t = %.3f s; the session holds frames up to %.3f s", reported,
          killed->endTime());
    killed.reset();
    {
        QSqlDatabase db = QSqlDatabase::addDatabase("QSQLITE", "check");
        db.setDatabaseName(session);
        QVERIFY(db.open());
        QSqlQuery query(db);
        QVERIFY(query.exec("PRAGMA integrity_check") && query.next());
        QCOMPARE(query.value(0).toString(), QString("ok"));
    }
    QSqlDatabase::removeDatabase("check");
}

QTEST_GUILESS_MAIN(TestSessionCli)
#include "tst_sessioncli.moc"
