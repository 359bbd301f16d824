// SPDX-License-Identifier: MIT
// The studio's live-rig source: another program's contact frames over UDP (loopback only)
// run through detectors, router and devices like the simulation's, with the history fed,
// malformed datagrams counted and never fatal, a flood that does not stall the GUI, and
// recordings that keep each frame's arrival time; and a robot followed over the Foxglove
// WebSocket protocol (the reference server, tests/interop/foxglove-robot.mjs) through a
// topic map.
#include "contactframereader.h"
#include "devicemanager.h"
#include "engine.h"
#include "foxglovepeers.h"
#include "routergraph.h"
#include "sessionreader.h"
#include "virtualtransport.h"

#include <QElapsedTimer>
#include <QFile>
#include <QProcess>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QUdpSocket>

using namespace semhap;

class TestLiveRig : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void followsARobot();
    void aRobotNeedsItsTopicMap();
    void framesRunLikeRoute();
    void malformedDatagramsAreCounted_data();
    void malformedDatagramsAreCounted();
    void floodDoesNotStallTheGui();
    void pausedHoldsFrames();
    void offersTheSignalsItsFramesCarry();
    void recordsArrivalTimes();
    void portInUseKeepsTheRun();
    void resetAndRouterSwapKeepListening();
    void silentSenderEndsMessagesAndStopsBands();
    void silenceWaitsBehindAReplay();
};

namespace {

const QString Trace = QStringLiteral(SEMHAP_RESOURCES "/traces/demo.jsonl");

/** The trace's first `count` lines, one frame each. */
QList<QByteArray> traceLines(int count)
{
    QFile file(Trace);
    if (!file.open(QIODevice::ReadOnly))
        return {};
    QList<QByteArray> lines;
    while (!file.atEnd() && lines.size() < count)
        lines << file.readLine().trimmed();
    return lines;
}

/** Sends datagrams to the engine's rig on loopback. */
class Sender
{
public:
    explicit Sender(Engine &engine) : m_engine(engine), m_port(quint16(engine.liveStats().port)) {}

    void send(const QByteArray &datagram)
    {
        m_socket.writeDatagram(datagram, QHostAddress::LocalHost, m_port);
    }
    /**
     * `frames` in batches of `batch` (a JSON array each). Paced, it keeps at most a window
     * of datagrams unread: loopback drops what the socket's buffer cannot hold, and a busy
     * machine may hold the rig's thread back for a while. A flood is not paced. False when
     * the rig stopped reading.
     */
    [[nodiscard]] bool sendBatches(const QList<QByteArray> &frames, int batch, bool paced = true)
    {
        constexpr quint64 Window = 64;
        const quint64 base = m_engine.liveStats().datagrams;
        quint64 sent = 0;
        for (qsizetype i = 0; i < frames.size(); i += batch) {
            QByteArray datagram = "[";
            for (qsizetype k = i; k < std::min(frames.size(), i + batch); ++k)
                datagram += (k > i ? "," : "") + frames[k];
            send(datagram + "]");
            ++sent;
            const auto caughtUp = [&] {
                return m_engine.liveStats().datagrams - base + Window >= sent;
            };
            if (paced && sent % (Window / 2) == 0 && !QTest::qWaitFor(caughtUp, 10000))
                return false;
        }
        return true;
    }

private:
    Engine &m_engine;
    QUdpSocket m_socket;
    quint16 m_port;
};

/**
 * A rig on a free port. A busy machine may hold the sender back longer than the default
 * silence; the runs compared with `route` must not end their messages on such a pause.
 */
LiveRigOptions anyPort(const QString &router = "C3", double silence = 60.0)
{
    LiveRigOptions options;
    options.port = 0;
    options.router = router;
    options.silence = silence;
    return options;
}

template<typename T> qint64 count(const RunSeries<T> &series)
{
    return series.end() - series.begin();
}

/** The history's events as `route`'s reference has them: "t node phase". */
QStringList eventLines(const RunHistory &history)
{
    QStringList events;
    for (qint64 i = history.events().begin(); i < history.events().end(); ++i) {
        const SemanticEvent &event = history.events().at(i);
        events << QStringLiteral("%1 %2 %3")
                      .arg(event.t)
                      .arg(history.nodeName(event.node))
                      .arg(int(event.phase));
    }
    return events;
}

bool waitForFrames(Engine &engine, quint64 frames)
{
    // `frames` counts every valid frame received, the held ones too.
    return QTest::qWaitFor([&] { return engine.liveStats().frames >= frames; }, 10000);
}

/** What `semhap route` makes of the same frames: the events and device frames, as text. */
struct Reference
{
    QStringList events;
    std::vector<double> deviceMax; ///< by device: the largest value sent
};

Reference route(const QString &router, int frames, const QString &path = Trace)
{
    QFile file(path);
    file.open(QIODevice::ReadOnly);
    ContactFrameReader reader(&file, path);
    LoadError error;
    Pipeline pipeline(loadRouter(router, {}, &error));
    struct Collect : PipelineSink
    {
        Reference *reference;
        const Router *router;
        void onEvent(const SemanticEvent &event) override
        {
            reference->events << QStringLiteral("%1 %2 %3")
                                     .arg(event.t)
                                     .arg(router->nodeIds().at(event.node))
                                     .arg(int(event.phase));
        }
        void onDeviceFrame(const DeviceFrame &frame) override
        {
            auto &max = reference->deviceMax[size_t(frame.device)];
            for (int c = 0; c < frame.channelCount; ++c)
                max = std::max(max, double(frame.values[size_t(c)]));
        }
    } collect;
    Reference reference;
    reference.deviceMax.assign(size_t(pipeline.router().player().deviceCount()), 0.0);
    collect.reference = &reference;
    collect.router = &pipeline.router();
    ContactFrame frame;
    for (int i = 0; i < frames && reader.next(&frame); ++i)
        pipeline.process(frame, collect);
    return reference;
}

} // namespace

void TestLiveRig::initTestCase()
{
    QVERIFY(traceLines(10).size() == 10);
}

void TestLiveRig::framesRunLikeRoute()
{
    Engine engine;
    QSignalSpy loaded(&engine, &Engine::sourceChanged);
    QString error;
    QVERIFY2(engine.listen(anyPort(), &error), qPrintable(error));
    QCOMPARE(loaded.count(), 1);
    QVERIFY(engine.isLive());
    QVERIFY(!engine.world());
    QVERIFY(engine.liveUri().startsWith("udp:127.0.0.1:")); // this machine only by default
    QVERIFY(engine.liveStats().port > 0);
    engine.run();

    // Five seconds of the trace: a grasp, a break warning and a slip.
    const QList<QByteArray> lines = traceLines(2000);
    QVERIFY(Sender(engine).sendBatches(lines, 2));
    QVERIFY(waitForFrames(engine, quint64(lines.size())));
    QCOMPARE(engine.liveStats().frames, quint64(lines.size()));
    QCOMPARE(engine.liveStats().rejected, quint64(0));
    QTest::qWait(50); // one drain of the feed

    const RunHistory &history = engine.history();
    QCOMPARE(count(history.frames(Gripper::Left)) + count(history.frames(Gripper::Right)),
             qint64(lines.size()));
    QVERIFY(qAbs(engine.simTime() - 4.995) < 1e-9);

    const Reference reference = route("C3", int(lines.size()));
    const QStringList events = eventLines(history);
    QVERIFY(events.size() > 5);
    QCOMPARE(events, reference.events);
    bool anyOutput = false;
    for (size_t d = 0; d < history.devices().size(); ++d) {
        double max = 0.0;
        const RunSeries<DeviceFrame> &frames = history.deviceFrames(int(d));
        for (qint64 i = frames.begin(); i < frames.end(); ++i) {
            for (int c = 0; c < frames.at(i).channelCount; ++c)
                max = std::max(max, double(frames.at(i).values[size_t(c)]));
        }
        QCOMPARE(max, reference.deviceMax[d]);
        anyOutput = anyOutput || max > 0.0;
    }
    QVERIFY(anyOutput);
}

void TestLiveRig::followsARobot()
{
    // The robot plays its grasp (2 s at 500 Hz) once the rig has subscribed and runs.
    QProcess robot;
    const int port = startRobot(robot, {"--hold"});
    QVERIFY(port > 0);
    Engine engine;
    // The last frames wait for the silence that tells the grasp is over.
    LiveRigOptions options = anyPort("C3", 1.5);
    options.foxglove = QUrl(QStringLiteral("ws://127.0.0.1:%1").arg(port));
    options.topics = QStringLiteral(SEMHAP_INTEROP_DIR "/grasp.topics.json");
    QString error;
    QVERIFY2(engine.listen(options, &error), qPrintable(error));
    QCOMPARE(engine.liveUri(), options.foxglove.toString());
    engine.run();
    robot.write("go\n");
    QVERIFY(robot.waitForBytesWritten(10000));
    QVERIFY2(QTest::qWaitFor([&] { return engine.liveStats().frames >= 1000; }, 30000),
             qPrintable(QStringLiteral("%1 message(s), %2 frame(s); %3")
                            .arg(engine.liveStats().datagrams)
                            .arg(engine.liveStats().frames)
                            .arg(engine.liveStats().lastRejection)));
    QTest::qWait(50); // one drain of the feed
    QCOMPARE(engine.liveStats().frames, quint64(1000));
    QCOMPARE(engine.liveStats().rejected, quint64(0));

    // The events `semhap route` makes of the same grasp as JSON Lines.
    const RunHistory &history = engine.history();
    const QStringList events = eventLines(history);
    const Reference reference =
        route("C3", 1000, QStringLiteral(SEMHAP_INTEROP_DIR "/grasp.frames.jsonl"));
    QVERIFY(events.size() > 5);
    QCOMPARE(events, reference.events);
    robot.waitForFinished(10000);
}

void TestLiveRig::aRobotNeedsItsTopicMap()
{
    // A map that does not load, or a server that is not a WebSocket URL, keeps the run.
    Engine engine;
    LiveRigOptions options = anyPort();
    options.foxglove = QUrl("ws://127.0.0.1:9");
    options.topics = QStringLiteral(SEMHAP_INTEROP_DIR "/no-such.topics.json");
    QString error;
    QVERIFY(!engine.listen(options, &error));
    QVERIFY2(error.contains("no-such.topics.json"), qPrintable(error));
    QVERIFY(!engine.isLive());
    options.foxglove = QUrl("http://127.0.0.1:9");
    options.topics = QStringLiteral(SEMHAP_INTEROP_DIR "/grasp.topics.json");
    QVERIFY(!engine.listen(options, &error));
    QVERIFY2(error.contains("expected a robot's server as ws://HOST:PORT"), qPrintable(error));
}

void TestLiveRig::malformedDatagramsAreCounted_data()
{
    QTest::addColumn<QByteArray>("datagram");
    QTest::addColumn<QString>("reason");
    QTest::addColumn<bool>("oversize");
    QTest::addColumn<int>("rejections");
    QTest::newRow("garbage") << QByteArray("garbage{") << "invalid JSON" << false << 1;
    QTest::newRow("truncated") << QByteArray(R"({"t": 1.0, "gripper": "ri)") << "invalid JSON"
                               << false << 1;
    QTest::newRow("empty") << QByteArray() << "invalid JSON" << false << 1;
    QTest::newRow("number") << QByteArray("42") << "invalid JSON" << false << 1;
    QTest::newRow("array of numbers")
        << QByteArray("[1, 2]")
        << "[0]: a contact frame must be a JSON object (the batch's 1 later frame(s) dropped)"
        << false << 2;
    QTest::newRow("no gripper") << QByteArray(R"({"t": 9.0, "left": null, "right": null})")
                                << "gripper" << false << 1;
    QTest::newRow("binary") << QByteArray("\x00\xff\xfe\x01", 4) << "invalid JSON" << false << 1;
    QTest::newRow("oversize") << QByteArray(40 * 1024, ' ') << "over the limit" << true << 1;
}

void TestLiveRig::malformedDatagramsAreCounted()
{
    QFETCH(QByteArray, datagram);
    QFETCH(QString, reason);
    QFETCH(bool, oversize);
    QFETCH(int, rejections);
    Engine engine;
    QString error;
    QVERIFY2(engine.listen(anyPort(), &error), qPrintable(error));
    engine.run();
    Sender sender(engine);
    const QList<QByteArray> lines = traceLines(4);
    sender.send(lines[0]);
    sender.send(datagram);
    sender.send(lines[1]);
    QVERIFY(QTest::qWaitFor([&] { return engine.liveStats().datagrams == 3; }, 5000));
    const RunSource::LinkStats stats = engine.liveStats();
    QCOMPARE(stats.frames, quint64(2)); // the frames around the bad one went through
    QCOMPARE(stats.rejected, quint64(rejections));
    QCOMPARE(stats.oversize, quint64(oversize ? 1 : 0));
    const QString rejection = stats.lastRejection;
    QCOMPARE(stats.reasons, quint64(1)); // one message a datagram, however many frames it drops
    QVERIFY2(rejection.contains(reason), qPrintable(rejection));
    QVERIFY2(rejection.startsWith(QStringLiteral("udp:%1: ").arg(stats.port)),
             qPrintable(rejection));
}

void TestLiveRig::floodDoesNotStallTheGui()
{
    Engine engine;
    QString error;
    QVERIFY2(engine.listen(anyPort(), &error), qPrintable(error));
    engine.run();
    // The GUI thread's longest pause during a second and a half of frames sent faster than
    // the rig can parse them, with garbage between.
    QElapsedTimer clock;
    clock.start();
    qint64 last = 0;
    qint64 longest = 0;
    QTimer tick;
    tick.setInterval(5);
    connect(&tick, &QTimer::timeout, this, [&] {
        longest = std::max(longest, clock.elapsed() - last);
        last = clock.elapsed();
    });
    tick.start();
    Sender sender(engine);
    quint64 offered = 0;
    QList<QByteArray> batch;
    while (clock.elapsed() < 1500) {
        batch.clear();
        for (int k = 0; k < 20; ++k, ++offered) {
            batch << QStringLiteral(R"({"t": %1, "gripper": "right", "left": {"f": 12.5, )"
                                    R"("n": 16, "actor": "cube_0"}, "right": null})")
                         .arg(double(offered) * 0.001)
                         .toUtf8();
        }
        QVERIFY(sender.sendBatches(batch, 20, false));
        if (offered % 2000 == 0) {
            sender.send("{not json");
            QTest::qWait(1);
        }
    }
    // Loopback drops what the socket's buffer cannot hold; wait until the rest is read.
    quint64 seen = 0;
    QVERIFY(QTest::qWaitFor(
        [&] {
            const quint64 now = engine.liveStats().datagrams;
            const bool settled = now > 0 && now == seen;
            seen = now;
            QTest::qWait(100);
            return settled;
        },
        10000));
    tick.stop();
    const RunSource::LinkStats stats = engine.liveStats();
    qInfo("flood: %llu frames offered; %llu datagrams, %llu frames, %llu rejected read; the "
          "GUI's longest pause %lld ms",
          offered, stats.datagrams, stats.frames, stats.rejected, longest);
    QVERIFY(stats.frames > 0);
    QVERIFY(stats.rejected > 0);
    // Whatever the loopback buffer dropped, what arrived ran: the history has it.
    QTest::qWait(50);
    QVERIFY(count(engine.history().frames(Gripper::Right)) > 0);
    // Generous: the point is that the GUI never waits for the flood to end.
    QVERIFY2(longest < 1000, qPrintable(QString::number(longest)));
}

void TestLiveRig::pausedHoldsFrames()
{
    Engine engine;
    QString error;
    QVERIFY2(engine.listen(anyPort(), &error), qPrintable(error));
    QVERIFY(!engine.isRunning()); // listen() leaves it paused, like load()
    const QList<QByteArray> lines = traceLines(100);
    Sender sender(engine);
    QVERIFY(sender.sendBatches(lines, 10));
    QVERIFY(waitForFrames(engine, 100));
    QCOMPARE(engine.liveStats().held, quint64(100));
    QTest::qWait(50);
    QCOMPARE(count(engine.history().frames(Gripper::Right)), qint64(0));

    engine.run();
    QVERIFY(sender.sendBatches(traceLines(200).mid(100), 10));
    QVERIFY(waitForFrames(engine, 200));
    QCOMPARE(engine.liveStats().held, quint64(100));
    QTest::qWait(50);
    QCOMPARE(count(engine.history().frames(Gripper::Right)), qint64(50));
}

void TestLiveRig::offersTheSignalsItsFramesCarry()
{
    // What the router editor's signal picker offers for a rig: the names its frames carried
    // so far, per gripper, in the order first seen (held frames count: paused, the user
    // builds the router). Not checked: a rig does not say in advance what it sends.
    Engine engine;
    QString error;
    QVERIFY2(engine.listen(anyPort(), &error), qPrintable(error));
    QVERIFY(engine.routerContext().signalNames[size_t(Gripper::Right)].isEmpty());
    Sender sender(engine);
    QVERIFY(sender.sendBatches(
        {R"({"t": 0.0, "gripper": "right", "left": null, "right": null,
             "signals": {"plug.angle": 0.1, "plug.depth": 0.0}})",
         R"({"t": 0.0, "gripper": "left", "left": null, "right": null,
             "signals": {"wrist.fz": 2.0}})",
         R"({"t": 0.01, "gripper": "right", "left": null, "right": null,
             "signals": {"plug.depth": 0.001, "plug.lateral": 0.002}})"},
        1));
    QVERIFY(waitForFrames(engine, 3));
    const RouterContext context = engine.routerContext();
    QVERIFY(!context.knowsSignals);
    QCOMPARE(context.signalNames[size_t(Gripper::Right)],
             (QStringList{"plug.angle", "plug.depth", "plug.lateral"}));
    QCOMPARE(context.signalNames[size_t(Gripper::Left)], QStringList{"wrist.fz"});
}

void TestLiveRig::recordsArrivalTimes()
{
    QTemporaryDir dir;
    const QString path = dir.filePath("rig.db");
    Engine engine;
    QString error;
    QVERIFY2(engine.listen(anyPort(), &error), qPrintable(error));
    engine.run();
    QVERIFY2(engine.startRecording(path, "rig test", &error), qPrintable(error));
    const QList<QByteArray> lines = traceLines(1000);
    QVERIFY(Sender(engine).sendBatches(lines, 4));
    QVERIFY(waitForFrames(engine, 1000));
    engine.stopRecording();

    std::unique_ptr<SessionReader> reader = SessionReader::open(path, &error);
    QVERIFY2(reader, qPrintable(error));
    QCOMPARE(reader->info().source, "studio");
    QCOMPARE(reader->info().scene, QString());
    QCOMPARE(reader->info().extra.value("udp"), engine.liveUri().mid(4));
    QCOMPARE(reader->info().notes, "rig test");
    QCOMPARE(reader->contactFrameCount(), qint64(1000));
    QVERIFY(reader->eventCount() > 0);
    QVERIFY(reader->deviceFrameCount() > 0);
    double lastArrival = -1.0;
    int frames = 0;
    QVERIFY2(reader->readContactFrames(
                 [&](const ContactFrame &, double arrival) {
                     if (!(arrival >= lastArrival))
                         return false;
                     lastArrival = arrival;
                     ++frames;
                     return true;
                 },
                 &error),
             qPrintable(error));
    QCOMPARE(frames, 1000); // every frame with its arrival time, in order
    QVERIFY(reader->actors().size() > 0);
}

void TestLiveRig::portInUseKeepsTheRun()
{
    QUdpSocket taken;
    QVERIFY(taken.bind(QHostAddress::LocalHost, 0));
    Engine engine;
    QString error;
    RunOptions run;
    run.duration = 3600.0;
    QVERIFY2(engine.load(run, &error), qPrintable(error));
    engine.step();
    // A step is a display frame's batch of physics steps: wait for all of it, not the first.
    const double frame = 1.0 / 60.0 - engine.world()->timestep();
    QVERIFY(QTest::qWaitFor([&] { return engine.simTime() >= frame; }, 5000));
    const double before = engine.simTime();
    QSignalSpy loaded(&engine, &Engine::sourceChanged);

    LiveRigOptions options = anyPort();
    options.port = taken.localPort();
    QVERIFY(!engine.listen(options, &error));
    QVERIFY2(error.contains(QString::number(options.port)), qPrintable(error));
    QCOMPARE(loaded.count(), 0);
    QVERIFY(!engine.isLive());
    QVERIFY(engine.world());
    QCOMPARE(engine.simTime(), before); // the same run, not a new one

    options.address = "not-an-address";
    options.port = 0;
    QVERIFY(!engine.listen(options, &error));
    QVERIFY2(error.contains("not-an-address"), qPrintable(error));
    options = anyPort("no_such_router");
    QVERIFY(!engine.listen(options, &error));
    QVERIFY2(error.contains("no_such_router"), qPrintable(error));
    QVERIFY(engine.world());
}

void TestLiveRig::resetAndRouterSwapKeepListening()
{
    Engine engine;
    QString error;
    QVERIFY2(engine.listen(anyPort(), &error), qPrintable(error));
    engine.run();
    const int port = engine.liveStats().port;
    Sender sender(engine);
    QVERIFY(sender.sendBatches(traceLines(400), 4));
    QVERIFY(waitForFrames(engine, 400));

    // A reset starts listening afresh on the same port, running as before.
    QVERIFY2(engine.reset(&error), qPrintable(error));
    QVERIFY(engine.isLive());
    QVERIFY(engine.isRunning());
    QCOMPARE(engine.liveStats().port, port);
    QCOMPARE(engine.liveStats().frames, quint64(0));
    QTest::qWait(50);
    QCOMPARE(count(engine.history().frames(Gripper::Right)), qint64(0));

    // The router editor's Apply swaps the router while the rig goes on.
    RouterGraph c1;
    LoadError loadError;
    QVERIFY(RouterPresets::preset("C1", &c1, &loadError));
    QVERIFY2(engine.setRouter(c1, &error), qPrintable(error));
    QCOMPARE(engine.routerGraph().toJson(), c1.toJson());
    QVERIFY(sender.sendBatches(traceLines(800).mid(400), 4));
    QVERIFY(waitForFrames(engine, 400));
    QCOMPARE(engine.liveStats().port, port);
    QTest::qWait(50);
    QCOMPARE(count(engine.history().frames(Gripper::Right)), qint64(200)); // half are left's
}

void TestLiveRig::silentSenderEndsMessagesAndStopsBands()
{
    Engine engine;
    QString error;
    QVERIFY2(engine.listen(anyPort("C3", UdpFrameSource::DefaultSilence), &error),
             qPrintable(error));
    engine.run();
    // The trace's first second: a grasp begins and is held when the sender stops.
    const QList<QByteArray> lines = traceLines(400);
    QVERIFY(Sender(engine).sendBatches(lines, 4));
    QVERIFY(waitForFrames(engine, quint64(lines.size())));
    const RunHistory &history = engine.history();
    const auto lastEvent = [&] { // the feed drains on the event loop
        return history.events().end() > history.events().begin()
                   ? history.events().at(history.events().end() - 1)
                   : SemanticEvent();
    };
    QVERIFY(QTest::qWaitFor([&] { return lastEvent().phase == EventPhase::End; }, 5000));
    QCOMPARE(lastEvent().t, engine.simTime());
    // Every device was sent its idle values, and the meters show them.
    QVERIFY(!history.devices().empty());
    for (size_t d = 0; d < history.devices().size(); ++d) {
        const auto &frames = history.deviceFrames(int(d));
        QVERIFY(frames.end() > frames.begin());
        const DeviceFrame &last = frames.at(frames.end() - 1);
        for (int c = 0; c < last.channelCount; ++c)
            QCOMPARE(last.values[size_t(c)], 0.0);
    }
}

void TestLiveRig::silenceWaitsBehindAReplay()
{
    // The rig's own session, to replay in front of it.
    QTemporaryDir dir;
    const QString path = dir.filePath("rig.db");
    Engine engine;
    QString error;
    QVERIFY2(engine.listen(anyPort("C3", UdpFrameSource::DefaultSilence), &error),
             qPrintable(error));
    engine.run();
    QVERIFY2(engine.startRecording(path, QString(), &error), qPrintable(error));
    Sender sender(engine);
    QVERIFY(sender.sendBatches(traceLines(100), 4));
    QVERIFY(waitForFrames(engine, 100));
    engine.stopRecording();
    const auto stops = [&engine] {
        int count = 0;
        for (const QString &name : engine.devices().boundNames())
            count +=
                dynamic_cast<VirtualTransport &>(*engine.devices().transport(name)).stopCount();
        return count;
    };
    QTRY_VERIFY(stops() > 0); // the sender's first silence stopped the bands

    QVERIFY2(engine.openReplay(path, &error), qPrintable(error));
    const int before = stops();
    // The sender speaks to the paused rig and falls silent while the replay shows: the
    // devices are the replay's (and an audition's), the rig's silence leaves them alone.
    QVERIFY(sender.sendBatches(traceLines(100), 4));
    QVERIFY(waitForFrames(engine, 200));
    QTest::qWait(int(4000 * UdpFrameSource::DefaultSilence));
    QCOMPARE(stops(), before);
    // Closed, the rig acts on the silence it kept.
    QVERIFY2(engine.closeReplay(&error), qPrintable(error));
    QTRY_VERIFY(stops() > before);
}

QTEST_MAIN(TestLiveRig)
#include "tst_liverig.moc"
