// SPDX-License-Identifier: MIT
// Sessions: what is recorded reads back bit for bit, damaged files are refused with a clear
// reason, and the UDP frame source survives garbage, oversize datagrams and floods.
#include "actortable.h"
#include "nametable.h"
#include "pipeline.h"
#include "router.h"
#include "sessionblocks.h"
#include "sessionclock.h"
#include "sessionreader.h"
#include "sessionwriter.h"
#include "slipdetector.h"
#include "udpframesource.h"

#include <QFile>
#include <QHostAddress>
#include <QSqlDatabase>
#include <QSqlQuery>
#include <QTemporaryDir>
#include <QTest>
#include <QUdpSocket>

#include <atomic>
#include <cmath>
#include <cstring>
#include <random>
#include <thread>

using namespace semhap;

namespace {

bool sameBits(double a, double b)
{
    return std::memcmp(&a, &b, sizeof a) == 0;
}

/** A double from anywhere in the range: tiny, huge, subnormal, many digits. */
double anyDouble(std::mt19937_64 &random)
{
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::uniform_int_distribution<int> exponent(-1070, 300);
    return unit(random) * std::pow(2.0, exponent(random));
}

struct Recording
{
    std::vector<ContactFrame> frames;
    std::vector<double> arrivals;
    std::vector<SemanticEvent> events;
    std::vector<DeviceFrame> deviceFrames;
    std::vector<HandCommand> inputs;
    ActorTable actors;
};

Recording synthetic(const Router &router, int ticks)
{
    std::mt19937_64 random(7);
    Recording r;
    const QStringList names{"cube_1", "container", "cube, \"odd\" name"};
    for (int k = 0; k < ticks; ++k) {
        for (Gripper g : {Gripper::Left, Gripper::Right}) {
            ContactFrame frame;
            frame.t = k * 0.001 + anyDouble(random) * 1e-300;
            frame.gripper = g;
            for (Fingertip *tip : {&frame.left, &frame.right}) {
                tip->f = anyDouble(random);
                tip->n = int(random() % 40);
                tip->actor = k % 5 == 0 ? -1 : r.actors.intern(names[int(random() % 3)]);
                tip->hasFxyz = k % 3 != 0;
                if (tip->hasFxyz) {
                    for (double &c : tip->fxyz)
                        c = (random() % 2 ? -1 : 1) * anyDouble(random);
                }
                tip->mu = k % 4 == 0 ? 0.0 : anyDouble(random) + 1e-9;
            }
            if (k % 2 == 0) {
                frame.signalValues.set(signalNames().intern("wrist.fz"), anyDouble(random));
                frame.signalValues.set(signalNames().intern("plug.depth"), -anyDouble(random));
            }
            r.frames.push_back(frame);
            r.arrivals.push_back(k % 2 ? qQNaN() : 1000.0 + anyDouble(random));
        }
        SemanticEvent event;
        event.t = k * 0.001;
        event.gripper = Gripper(k % 2);
        event.node = int(router.nodeIds().indexOf(k % 2 ? "right.force" : "left.slip"));
        event.detector = k % 2 ? DetectorKind::Force : DetectorKind::Slip;
        event.message = Message(k % 3);
        event.category = categoryOf(event.message);
        event.phase = EventPhase(k % 3);
        event.intensity = 1.0 / (1.0 + anyDouble(random)); // in (0, 1], as events carry
        r.events.push_back(event);
        DeviceFrame device;
        device.t = k * 0.001;
        device.device = k % router.player().deviceCount();
        device.channelCount = router.player().deviceModel(device.device).channelCount();
        for (int c = 0; c < device.channelCount; ++c)
            device.values[size_t(c)] = anyDouble(random);
        r.deviceFrames.push_back(device);
        HandCommand input;
        input.t = k * 0.001;
        input.hand = Gripper(k % 2);
        for (double &v : input.target.pos)
            v = anyDouble(random);
        for (double &v : input.target.quat)
            v = anyDouble(random);
        input.grip = -anyDouble(random);
        r.inputs.push_back(input);
    }
    return r;
}

void record(const QString &path, const Router &router, const Recording &r)
{
    QString error;
    SessionInfo info;
    info.source = "test";
    info.notes = "notes, with \"quotes\"";
    info.routerContext.reactionTime = 0.4;
    std::unique_ptr<SessionWriter> writer = SessionWriter::create(path, info, router, &error);
    QVERIFY2(writer, qPrintable(error));
    writer->setActorTable(&r.actors);
    for (size_t i = 0; i < r.frames.size(); ++i) {
        writer->recordContactFrame(r.frames[i], r.arrivals[i]);
        if (i % 2 == 1) {
            writer->onEvent(r.events[i / 2]);
            writer->onDeviceFrame(r.deviceFrames[i / 2]);
            writer->recordHandCommand(r.inputs[i / 2]);
        }
    }
    QVERIFY2(writer->finish(&error), qPrintable(error));
    QCOMPARE(writer->dropped(), quint64(0));
}

std::unique_ptr<Router> c3()
{
    LoadError error;
    std::unique_ptr<Router> router = loadRouter("C3", {}, &error);
    if (!router)
        qFatal("%s", qPrintable(error.toString()));
    return router;
}

/** Runs `statements` on a copy of a good session: the ways a file can be wrong. */
void damage(const QString &path, const QStringList &statements)
{
    {
        QSqlDatabase db = QSqlDatabase::addDatabase("QSQLITE", "damage");
        db.setDatabaseName(path);
        QVERIFY(db.open());
        QSqlQuery query(db);
        for (const QString &statement : statements)
            QVERIFY2(query.exec(statement), qPrintable(statement));
        db.close();
    }
    QSqlDatabase::removeDatabase("damage");
}

/**
 * Reads every stream of `session` and compares it with `r`, bit for bit; `exactZero`:
 * -0 too (schema 5 keeps it, older schemas read it as 0).
 */
void readsBack(SessionReader &reader, const Recording &r, bool exactZero = true)
{
    QString error;
    QCOMPARE(reader.contactFrameCount(), qint64(r.frames.size()));

    size_t i = 0;
    QVERIFY(reader.readContactFrames(
        [&](const ContactFrame &frame, double arrival) {
            const ContactFrame &want = r.frames[i];
            bool same = sameBits(frame.t, want.t) && frame.gripper == want.gripper &&
                        frame.signalValues.size() == want.signalValues.size() &&
                        (std::isnan(arrival) ? std::isnan(r.arrivals[i])
                                             : sameBits(arrival, r.arrivals[i]));
            for (auto [got, expected] :
                 {std::pair(&frame.left, &want.left), std::pair(&frame.right, &want.right)}) {
                same = same && sameBits(got->f, expected->f) && got->n == expected->n &&
                       got->hasFxyz == expected->hasFxyz && sameBits(got->mu, expected->mu) &&
                       reader.actors().name(got->actor) == r.actors.name(expected->actor);
                for (size_t c = 0; c < 3 && expected->hasFxyz; ++c)
                    same = same && sameBits(got->fxyz[c], expected->fxyz[c]);
            }
            for (const SignalValue &signal : want.signalValues) {
                const double *value = frame.signalValues.find(signal.id);
                // Bit for bit but for -0, which schema 4 reads back as 0 (docs/sessions.md).
                same = same && value &&
                       (*value == 0.0 && !exactZero ? signal.value == 0.0
                                                    : sameBits(*value, signal.value));
            }
            if (!same)
                qWarning("contact frame %zu differs", i);
            ++i;
            return same;
        },
        &error));
    QCOMPARE(i, r.frames.size());

    i = 0;
    QVERIFY(reader.readEvents(
        [&](const SemanticEvent &e) {
            const SemanticEvent &want = r.events[i++];
            return sameBits(e.t, want.t) && e.gripper == want.gripper && e.node == want.node &&
                   e.detector == want.detector && e.message == want.message &&
                   e.category == want.category && e.phase == want.phase &&
                   sameBits(e.intensity, want.intensity);
        },
        &error));
    QCOMPARE(i, r.events.size());

    i = 0;
    QVERIFY(reader.readDeviceFrames(
        [&](const DeviceFrame &f) {
            const DeviceFrame &want = r.deviceFrames[i++];
            bool same = sameBits(f.t, want.t) && f.device == want.device &&
                        f.channelCount == want.channelCount;
            for (int c = 0; same && c < f.channelCount; ++c)
                same = sameBits(f.values[size_t(c)], want.values[size_t(c)]);
            return same;
        },
        &error));
    QCOMPARE(i, r.deviceFrames.size());

    i = 0;
    QVERIFY(reader.readHandCommands(
        [&](const HandCommand &in) {
            const HandCommand &want = r.inputs[i++];
            bool same =
                sameBits(in.t, want.t) && in.hand == want.hand && sameBits(in.grip, want.grip);
            for (size_t c = 0; c < 3; ++c)
                same = same && sameBits(in.target.pos[c], want.target.pos[c]);
            for (size_t c = 0; c < 4; ++c)
                same = same && sameBits(in.target.quat[c], want.target.quat[c]);
            return same;
        },
        &error));
    QCOMPARE(i, r.inputs.size());
}

/** The scene states the schema 4 fixture holds, made as they were made for it. */
std::vector<SceneState> fixtureSceneStates(const Recording &r)
{
    std::mt19937_64 random(11);
    std::vector<SceneState> states;
    for (size_t i = 0; i < r.frames.size(); i += 40) {
        SceneState state;
        state.t = r.frames[i].t;
        for (int k = 0; k < 37; ++k)
            state.pose.push_back((random() % 2 ? -1 : 1) * anyDouble(random));
        state.overlay = {0.0, 0.25, anyDouble(random), 1.0};
        states.push_back(state);
    }
    return states;
}

/** A writable copy of the schema 4 fixture in `dir`, named `name`. */
QString schemaFour(const QTemporaryDir &dir, const QString &name)
{
    const QString path = dir.filePath(name);
    QFile::remove(path);
    if (!QFile::copy(QFINDTESTDATA("data/schema4.db"), path) ||
        !QFile::setPermissions(path, QFile::ReadOwner | QFile::WriteOwner))
        qFatal("cannot copy the schema 4 fixture");
    return path;
}

/** What reading every stream of the session at `path` gives: counts and rejected rows. */
struct ReadBack
{
    qint64 frames = 0;
    qint64 events = 0;
    qint64 deviceFrames = 0;
    qint64 inputs = 0;
    qint64 rejectedRows = 0;
    QStringList rejected;
};

ReadBack readAll(const QString &path)
{
    ReadBack got;
    QString error;
    std::unique_ptr<SessionReader> reader = SessionReader::open(path, &error);
    if (!reader)
        qFatal("%s", qPrintable(error));
    reader->setRowErrorHandler([&](const QString &line) { got.rejected.append(line); });
    const bool read =
        reader->readContactFrames([&](const ContactFrame &, double) { return ++got.frames; },
                                  &error) &&
        reader->readEvents([&](const SemanticEvent &) { return ++got.events; }, &error) &&
        reader->readDeviceFrames([&](const DeviceFrame &) { return ++got.deviceFrames; },
                                 &error) &&
        reader->readHandCommands([&](const HandCommand &) { return ++got.inputs; }, &error);
    if (!read)
        qFatal("%s", qPrintable(error));
    got.rejectedRows = reader->rejectedRows();
    return got;
}

} // namespace

class TestSessions : public QObject
{
    Q_OBJECT

private slots:
    void roundTripIsBitForBit();
    void schemaFourStillReads();
    void negativeZeroReadsAsZero();
    void metadataAndRouter();
    void gripperTraitsReplay();
    void recordingMidGraspBeginsWhatIsOpen();
    void timeWindow();
    void neverOverwrites();
    void anOfflineProducerWaitsInsteadOfDropping();
    void finishedSessionIsOneFile();
    void sceneStates();
    void schemaOneStillOpens();
    void damagedFiles_data();
    void damagedFiles();
    void rowsAreCheckedAsStreamsAre();
    void blocksAreCheckedAsStreamsAre();
    void blocksAreSealedBySecond();
    void keepsTheSteadyClock();
    void steadyClockPairs_data();
    void steadyClockPairs();
    void aSceneTooWideIsRefused();
    void udpGarbageOversizeAndBatch();
    void udpFlood();

private:
    QTemporaryDir m_dir;
};

void TestSessions::roundTripIsBitForBit()
{
    const auto router = c3();
    const Recording r = synthetic(*router, 3000);
    const QString path = m_dir.filePath("roundtrip.db");
    record(path, *router, r);

    QString error;
    std::unique_ptr<SessionReader> session = SessionReader::open(path, &error);
    QVERIFY2(session, qPrintable(error));
    QCOMPARE(session->schemaVersion(), SessionInfo::SchemaVersion);
    QCOMPARE(session->nodeNames(), router->nodeIds());
    readsBack(*session, r);
}

void TestSessions::schemaFourStillReads()
{
    // Written by semhap before blocks (tests/sessions/data/schema4.db): synthetic(C3, 200)
    // as record() writes it, and fixtureSceneStates().
    const auto router = c3();
    const QString path = schemaFour(m_dir, "schema4.db");
    QString error;
    std::unique_ptr<SessionReader> session = SessionReader::open(path, &error);
    QVERIFY2(session, qPrintable(error));
    QCOMPARE(session->schemaVersion(), 4);
    QCOMPARE(session->info().notes, QString("notes, with \"quotes\""));
    readsBack(*session, synthetic(*router, 200), false);
    const std::vector<SceneState> states = fixtureSceneStates(synthetic(*router, 200));
    QCOMPARE(session->sceneStateCount(), qint64(states.size()));
    for (const SceneState &want : states) {
        SceneState state;
        QVERIFY2(session->readSceneState(want.t, &state, &error), qPrintable(error));
        QVERIFY(sameBits(state.t, want.t));
        QCOMPARE(state.pose.size(), want.pose.size());
        for (size_t i = 0; i < want.pose.size(); ++i)
            QVERIFY(sameBits(state.pose[i], want.pose[i]));
        for (size_t i = 0; i < 4; ++i)
            QVERIFY(sameBits(state.overlay[i], want.overlay[i]));
    }
}

void TestSessions::negativeZeroReadsAsZero()
{
    // SQLite stores integral reals as integers, so -0 comes back as 0 (equal, not the same
    // bits); docs/sessions.md says so.
    const auto router = c3();
    Recording r;
    ContactFrame frame;
    frame.left.hasFxyz = true;
    frame.left.fxyz = {-0.0, 1.0, -2.0};
    r.frames.push_back(frame);
    r.arrivals.push_back(qQNaN());
    const QString path = m_dir.filePath("zero.db");
    record(path, *router, r);
    QString error;
    auto session = SessionReader::open(path, &error);
    QVERIFY(session);
    QVERIFY(session->readContactFrames(
        [](const ContactFrame &f, double) {
            return f.left.fxyz[0] == 0.0 && f.left.fxyz[2] == -2.0;
        },
        &error));
}

void TestSessions::metadataAndRouter()
{
    const auto router = c3();
    const QString path = m_dir.filePath("meta.db");
    record(path, *router, Recording());
    QString error;
    auto session = SessionReader::open(path, &error);
    QVERIFY(session);
    QCOMPARE(session->info().source, QString("test"));
    QCOMPARE(session->info().notes, QString("notes, with \"quotes\""));
    QCOMPARE(session->info().semhapVersion, QString(SEMHAP_VERSION_STRING));
    QVERIFY(session->info().started.isValid());
    QVERIFY(session->info().ended >= session->info().started);
    QCOMPARE(session->info().routerContext.reactionTime, 0.4);
    QVERIFY(!session->info().extra.contains("reaction_time"));
    QVERIFY(!session->info().extra.contains("open_at_start")); // nothing was active
    QCOMPARE(session->deviceNames().size(), router->player().deviceCount());
    QCOMPARE(session->channelNames(int(session->deviceNames().indexOf("right.vibro"))),
             QStringList({"m1", "m2", "m3", "m4"}));
    // The router replays without the presets: every pattern and model is embedded.
    RouterGraph graph;
    LoadError loadError;
    QVERIFY(session->routerGraph(&graph, &loadError));
    QCOMPARE(graph.models.size(), size_t(4));
    QVERIFY(graph.patterns.size() >= 2);
    auto again = Router::compile(graph, &loadError);
    QVERIFY2(again, qPrintable(loadError.toString()));
    QCOMPARE(again->nodeIds(), router->nodeIds());
}

void TestSessions::gripperTraitsReplay()
{
    // A run on another gripper compiled its detectors fitted to it: its session says so, and
    // the router read back compiles as it ran, to the last bit of the ripple.
    const auto router = c3();
    const QString path = m_dir.filePath("traits.db");
    SessionInfo info;
    info.routerContext.grippers[size_t(Gripper::Left)] = {4, 0.0};
    info.routerContext.grippers[size_t(Gripper::Right)] = {8, 0.1 + 0.2};
    info.routerContext.reactionTime = 0.1 + 0.2;
    QString error;
    {
        auto writer = SessionWriter::create(path, info, *router, &error);
        QVERIFY2(writer, qPrintable(error));
        QVERIFY2(writer->finish(&error), qPrintable(error));
    }
    auto reader = SessionReader::open(path, &error);
    QVERIFY2(reader, qPrintable(error));
    const RouterContext &context = reader->info().routerContext;
    QCOMPARE(context.grippers[0].fullContacts, 4);
    QCOMPARE(context.grippers[0].forceRipple, 0.0);
    QCOMPARE(context.grippers[1].fullContacts, 8);
    QVERIFY(sameBits(context.grippers[1].forceRipple, 0.1 + 0.2));
    QVERIFY(sameBits(context.reactionTime, 0.1 + 0.2));
    QVERIFY(!reader->info().extra.contains("left_full_contacts"));
    RouterGraph graph;
    LoadError loadError;
    QVERIFY(reader->routerGraph(&graph, &loadError));
    const auto replayed = Router::compile(graph, &loadError, context);
    QVERIFY2(replayed, qPrintable(loadError.toString()));
    const auto *slip = dynamic_cast<const SlipDetector *>(replayed->detectors()[1]);
    QVERIFY(slip && slip->gripper() == Gripper::Left);
    QCOMPARE(slip->params().loss, 4.0);

    // One recorded before the router knew its grippers ran it for the bundled ones.
    reader.reset();
    damage(path, {"DELETE FROM metadata WHERE key LIKE '%_full_contacts' "
                  "OR key LIKE '%_force_ripple'"});
    reader = SessionReader::open(path, &error);
    QVERIFY2(reader, qPrintable(error));
    for (const GripperTraits &traits : reader->info().routerContext.grippers) {
        QCOMPARE(traits.fullContacts, ReferenceFullContacts);
        QCOMPARE(traits.forceRipple, 0.0);
    }
}

void TestSessions::recordingMidGraspBeginsWhatIsOpen()
{
    // A recording that starts while the right hand grasps holds the grasp's begin, at its
    // first frame and before that tick's events, and says so in its metadata.
    struct : PipelineSink
    {
        void onEvent(const SemanticEvent &event) override { events.push_back(event); }
        std::vector<SemanticEvent> events;
    } before;
    Pipeline pipeline(c3());
    const auto frame = [](int k, double force) {
        ContactFrame f;
        f.t = k * 0.001;
        f.gripper = Gripper::Right;
        f.left.f = f.right.f = force / 2.0;
        f.left.n = f.right.n = 1;
        return f;
    };
    int k = 0;
    for (; k < 300; ++k)
        pipeline.process(frame(k, 40.0), before);
    QVERIFY(std::any_of(before.events.begin(), before.events.end(), [](const SemanticEvent &e) {
        return e.message == Message::Grasp && e.phase == EventPhase::Begin;
    }));

    const QString path = m_dir.filePath("mid-grasp.db");
    QString error;
    std::unique_ptr<SessionWriter> writer =
        SessionWriter::create(path, SessionInfo(), pipeline.router(), &error);
    QVERIFY2(writer, qPrintable(error));
    const double first = frame(k, 0.0).t;
    for (const int end = k + 100; k < end; ++k) {
        const ContactFrame f = frame(k, k < end - 50 ? 40.0 : 0.0);
        writer->recordContactFrame(f, qQNaN());
        pipeline.process(f, *writer);
    }
    QVERIFY2(writer->finish(&error), qPrintable(error));

    auto session = SessionReader::open(path, &error);
    QVERIFY2(session, qPrintable(error));
    QCOMPARE(session->startTime(), first);
    QCOMPARE(session->info().extra.value("open_at_start"),
             QString(R"([{"message":"grasp","node":"right.force"}])"));
    std::vector<SemanticEvent> events;
    QVERIFY(session->readEvents(
        [&](const SemanticEvent &event) {
            events.push_back(event);
            return true;
        },
        &error));
    QCOMPARE(events.size(), size_t(2));
    QCOMPARE(events[0].phase, EventPhase::Begin);
    QCOMPARE(events[0].message, Message::Grasp);
    QCOMPARE(events[0].t, first);
    QCOMPARE(session->nodeNames().at(events[0].node), QString("right.force"));
    QCOMPARE(events[1].phase, EventPhase::End);
}

void TestSessions::timeWindow()
{
    const auto router = c3();
    const Recording r = synthetic(*router, 1000);
    const QString path = m_dir.filePath("window.db");
    record(path, *router, r);
    QString error;
    auto session = SessionReader::open(path, &error);
    QVERIFY(session);
    int count = 0;
    double first = -1;
    QVERIFY(session->readEvents(
        [&](const SemanticEvent &e) {
            if (count++ == 0)
                first = e.t;
            return true;
        },
        &error, 0.5, 0.6));
    QCOMPARE(count, 100);
    QCOMPARE(first, 0.5);
}

void TestSessions::neverOverwrites()
{
    const auto router = c3();
    const QString path = m_dir.filePath("exists.db");
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("precious");
    file.close();
    QString error;
    QVERIFY(!SessionWriter::create(path, SessionInfo(), *router, &error));
    QCOMPARE(error, path + ": already exists (a session is never overwritten)");
    QVERIFY(file.open(QIODevice::ReadOnly));
    QCOMPARE(file.readAll(), QByteArray("precious"));
}

void TestSessions::anOfflineProducerWaitsInsteadOfDropping()
{
    // A batch of 16 that the writer would commit only once a minute: every frame past the
    // 16th finds it full. With waitWhenFull the producer waits for the writer each time.
    const auto router = c3();
    const QString path = m_dir.filePath("import.db");
    SessionWriter::Options options;
    options.capacity = 16;
    options.commitMs = 60000;
    options.waitWhenFull = true;
    QString error;
    std::unique_ptr<SessionWriter> writer =
        SessionWriter::create(path, SessionInfo(), *router, options, &error);
    QVERIFY2(writer, qPrintable(error));
    const int frames = 2000;
    for (int k = 0; k < frames; ++k) {
        ContactFrame frame;
        frame.t = k * 0.001;
        frame.left.f = k;
        writer->recordContactFrame(frame, qQNaN());
    }
    QVERIFY2(writer->finish(&error), qPrintable(error));
    QCOMPARE(writer->dropped(), quint64(0));
    auto session = SessionReader::open(path, &error);
    QVERIFY2(session, qPrintable(error));
    int read = 0;
    QVERIFY(session->readContactFrames(
        [&](const ContactFrame &frame, double) {
            if (frame.left.f != read)
                return false;
            ++read;
            return true;
        },
        &error));
    QCOMPARE(read, frames);
}

void TestSessions::finishedSessionIsOneFile()
{
    // Recorded in WAL mode, a finished session is one file again, and reading it (as the
    // studio's replay does, read-only) leaves no -wal or -shm beside it.
    const auto router = c3();
    QTemporaryDir dir;
    const QString path = dir.filePath("one.db");
    QString error;
    std::unique_ptr<SessionWriter> writer =
        SessionWriter::create(path, SessionInfo(), *router, &error);
    QVERIFY2(writer, qPrintable(error));
    ContactFrame frame;
    frame.t = 1.0;
    writer->recordContactFrame(frame, qQNaN());
    QVERIFY2(writer->finish(&error), qPrintable(error));
    writer.reset();
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files), QStringList{"one.db"});
    {
        std::unique_ptr<SessionReader> reader = SessionReader::open(path, &error);
        QVERIFY2(reader, qPrintable(error));
        QCOMPARE(reader->contactFrameCount(), qint64(1));
    }
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files), QStringList{"one.db"});
}

void TestSessions::sceneStates()
{
    const auto router = c3();
    const QString path = m_dir.filePath("scene.db");
    QString error;
    std::unique_ptr<SessionWriter> writer =
        SessionWriter::create(path, SessionInfo(), *router, &error);
    QVERIFY2(writer, qPrintable(error));
    std::mt19937_64 random(11);
    std::vector<SceneState> states;
    for (int k = 0; k < 90; ++k) {
        SceneState state;
        state.t = 0.5 + k / 30.0;
        for (int i = 0; i < 37; ++i)
            state.pose.push_back((random() % 2 ? -1 : 1) * anyDouble(random));
        state.pose.push_back(-0.0);
        state.overlay = {k % 2 * 1.0, 0.25, anyDouble(random), 1.0};
        states.push_back(state);
        writer->recordSceneState(state);
    }
    QVERIFY2(writer->finish(&error), qPrintable(error));

    std::unique_ptr<SessionReader> reader = SessionReader::open(path, &error);
    QVERIFY2(reader, qPrintable(error));
    QCOMPARE(reader->schemaVersion(), SessionInfo::SchemaVersion);
    QCOMPARE(reader->sceneStateCount(), qint64(states.size()));
    const auto check = [&](double t, size_t expected) {
        SceneState state;
        QString why;
        QVERIFY2(reader->readSceneState(t, &state, &why), qPrintable(why));
        const SceneState &want = states[expected];
        QCOMPARE(state.t, want.t);
        QCOMPARE(state.pose.size(), want.pose.size());
        for (size_t i = 0; i < want.pose.size(); ++i)
            QVERIFY2(sameBits(state.pose[i], want.pose[i]), qPrintable(QString::number(i)));
        for (size_t i = 0; i < 4; ++i)
            QVERIFY(sameBits(state.overlay[i], want.overlay[i]));
    };
    check(0.0, 0); // before the first: the first
    for (size_t k = 0; k < states.size(); ++k) {
        check(states[k].t, k);        // exactly on one, in every block
        check(states[k].t + 0.01, k); // between two: the one before
    }
    check(1e9, states.size() - 1); // after the last: the last
}

void TestSessions::schemaOneStillOpens()
{
    // A session from before scene states: no table, version 1.
    const auto router = c3();
    const QString path = schemaFour(m_dir, "schema1.db");
    const Recording r = synthetic(*router, 200);
    damage(path, {"DROP TABLE scene_states",
                  "UPDATE metadata SET value = '1' WHERE key = 'schema_version'",
                  "DELETE FROM metadata WHERE key = 'reaction_time'"});
    QString error;
    std::unique_ptr<SessionReader> reader = SessionReader::open(path, &error);
    QVERIFY2(reader, qPrintable(error));
    QCOMPARE(reader->schemaVersion(), 1);
    QCOMPARE(reader->sceneStateCount(), qint64(0));
    // It ran its router before routers had a context: with the default reaction time.
    QCOMPARE(reader->info().routerContext.reactionTime, DefaultReactionTime);
    QCOMPARE(reader->contactFrameCount(), qint64(r.frames.size()));
    SceneState state;
    QVERIFY(!reader->readSceneState(0.0, &state, &error));
}

void TestSessions::damagedFiles_data()
{
    QTest::addColumn<QStringList>("statements");
    QTest::addColumn<QByteArray>("replace"); // the file's bytes instead, when set
    QTest::addColumn<int>("truncateTo");     // bytes to keep, when > 0
    QTest::addColumn<QString>("reason");

    QTest::newRow("text file") << QStringList() << QByteArray("{\"t\": 0}\n") << 0
                               << "not a semhap session (not an SQLite database)";
    QTest::newRow("empty file") << QStringList() << QByteArray("") << 0
                                << "not a semhap session (not an SQLite database)";
    QTest::newRow("other database") << QStringList{"DROP TABLE metadata"} << QByteArray() << 0
                                    << "not a semhap session (no metadata table)";
    QTest::newRow("no schema version")
        << QStringList{"DELETE FROM metadata WHERE key = 'schema_version'"} << QByteArray() << 0
        << "not a semhap session (no schema_version in its metadata)";
    QTest::newRow("newer schema")
        << QStringList{"UPDATE metadata SET value = '7' WHERE key = 'schema_version'"}
        << QByteArray() << 0
        << "session schema version 7 is not supported (this semhap reads 1 to 5)";
    QTest::newRow("schema not a number")
        << QStringList{"UPDATE metadata SET value = 'two' WHERE key = 'schema_version'"}
        << QByteArray() << 0
        << "session schema version two is not supported (this semhap reads 1 to 5)";
    QTest::newRow("reaction time not a number")
        << QStringList{"UPDATE metadata SET value = 'slow' WHERE key = 'reaction_time'"}
        << QByteArray() << 0
        << "damaged session: metadata reaction_time: expected seconds from 0 to 10, got 'slow'";
    QTest::newRow("reaction time negative")
        << QStringList{"UPDATE metadata SET value = '-0.1' WHERE key = 'reaction_time'"}
        << QByteArray() << 0
        << "damaged session: metadata reaction_time: expected seconds from 0 to 10, got '-0.1'";
    QTest::newRow("full contacts not a number")
        << QStringList{"UPDATE metadata SET value = 'four' WHERE key = 'left_full_contacts'"}
        << QByteArray() << 0
        << "damaged session: metadata left_full_contacts: expected a whole number of contacts, "
           "got 'four'";
    QTest::newRow("full contacts a fraction")
        << QStringList{"UPDATE metadata SET value = '2.5' WHERE key = 'right_full_contacts'"}
        << QByteArray() << 0
        << "damaged session: metadata right_full_contacts: expected a whole number of contacts, "
           "got '2.5'";
    QTest::newRow("full contacts negative")
        << QStringList{"UPDATE metadata SET value = '-1' WHERE key = 'left_full_contacts'"}
        << QByteArray() << 0
        << "damaged session: metadata left_full_contacts: expected a whole number of contacts, "
           "got '-1'";
    QTest::newRow("force ripple negative")
        << QStringList{"UPDATE metadata SET value = '-2' WHERE key = 'right_force_ripple'"}
        << QByteArray() << 0
        << "damaged session: metadata right_force_ripple: expected newtons, 0 or more, got '-2'";
    QTest::newRow("force ripple infinite")
        << QStringList{"UPDATE metadata SET value = 'inf' WHERE key = 'left_force_ripple'"}
        << QByteArray() << 0
        << "damaged session: metadata left_force_ripple: expected newtons, 0 or more, got 'inf'";
    QTest::newRow("missing blocks") << QStringList{"DROP TABLE blocks"} << QByteArray() << 0
                                    << "damaged session: table 'blocks' is missing";
    QTest::newRow("missing names") << QStringList{"DROP TABLE names"} << QByteArray() << 0
                                   << "damaged session: table 'names' is missing";
    QTest::newRow("missing table") << QStringList{"DROP TABLE events"} << QByteArray() << 0
                                   << "damaged session: table 'events' is missing";
    QTest::newRow("truncated") << QStringList() << QByteArray() << 40000
                               << "damaged session: database disk image is malformed";
}

void TestSessions::damagedFiles()
{
    QFETCH(QStringList, statements);
    QFETCH(QByteArray, replace);
    QFETCH(int, truncateTo);
    QFETCH(QString, reason);
    const auto router = c3();
    const QString path = m_dir.filePath(QString("damaged-%1.db").arg(QTest::currentDataTag()));
    record(path, *router, synthetic(*router, 2000));
    if (!statements.isEmpty())
        damage(path, statements);
    QFile file(path);
    if (!replace.isNull()) {
        QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
        file.write(replace);
        file.close();
    }
    if (truncateTo > 0) {
        QVERIFY(file.size() > truncateTo * 2);
        QVERIFY(file.resize(truncateTo));
    }
    QString error;
    QVERIFY(!SessionReader::open(path, &error));
    QCOMPARE(error, path + ": " + reason);
}

void TestSessions::rowsAreCheckedAsStreamsAre()
{
    // Rows a program (or a bit flip) wrote wrong used to replay and export without a word.
    const auto router = c3();
    const QString path = schemaFour(m_dir, "bad-rows.db");
    const Recording good = synthetic(*router, 200);
    damage(path, {"UPDATE contact_frames SET left_f = 'abc' WHERE rowid = 3",
                  "UPDATE contact_frames SET gripper = 'middle' WHERE rowid = 5",
                  "UPDATE contact_frames SET right_n = -3 WHERE rowid = 7",
                  "UPDATE contact_frames SET t = 0 WHERE rowid = 9",
                  "UPDATE contact_frames SET left_fy = 'up' WHERE rowid = 11",
                  "UPDATE events SET message = 'Shout!' WHERE rowid = 2",
                  "UPDATE events SET intensity = 2 WHERE rowid = 4",
                  "UPDATE device_frames SET v0 = 'x' WHERE rowid = 4",
                  "UPDATE operator_input SET hand = 'middle' WHERE rowid = 6"});
    const ReadBack got = readAll(path);
    QCOMPARE(got.frames, qint64(good.frames.size()) - 5);
    QCOMPARE(got.events, qint64(good.events.size()) - 2);
    QCOMPARE(got.deviceFrames, qint64(good.deviceFrames.size()) - 1);
    QCOMPARE(got.inputs, qint64(good.inputs.size()) - 1);
    QCOMPARE(got.rejectedRows, qint64(9));
    const QStringList &rejected = got.rejected;
    const QString at = path + ": ";
    const QStringList expected{
        at + "contact_frames row 3: \"left.f\" must be a finite non-negative number, got \"abc\"",
        at + "contact_frames row 5: \"gripper\" must be \"left\" or \"right\", got \"middle\"",
        at + "contact_frames row 7: \"right.n\" must be a non-negative integer, got -3",
        at + "contact_frames row 9: \"t\" must increase per gripper, got 0 after 0.003 for "
             "\"left\"",
        at + "contact_frames row 11: \"left.fxyz\" must be an array of 3 finite numbers, got "
             "an array",
        at + "events row 2: \"message\" is not valid, got \"Shout!\"",
        at + "events row 4: \"intensity\" is not valid, got 2",
        at + "device_frames row 4: \"t\", \"device\" and the values must be finite numbers "
             "and a name",
        at + "operator_input row 6: \"t\", the pose and the grip must be finite numbers and "
             "\"hand\" left or right"};
    QCOMPARE(rejected.size(), expected.size());
    for (int i = 0; i < expected.size(); ++i) {
        if (expected[i].contains("row 9:")) // the t before it carries a tiny offset
            QVERIFY2(rejected[i].startsWith(expected[i].left(expected[i].indexOf(" after"))),
                     qPrintable(rejected[i]));
        else
            QCOMPARE(rejected[i], expected[i]);
    }
}

void TestSessions::blocksAreCheckedAsStreamsAre()
{
    // Schema 5: a block that does not unpack is skipped whole; a row in one that breaks its
    // stream's rules is skipped as a stream line would be.
    const auto router = c3();
    const QString path = m_dir.filePath("bad-blocks.db");
    const Recording good = synthetic(*router, 200);
    record(path, *router, good);
    const auto contact = [](double t, double gripper, double f, double n, double actor) {
        std::vector<double> row = emptyContactRow(t, gripper);
        row[3] = f;
        row[4] = n;
        row[5] = actor;
        return row;
    };
    std::vector<double> rows;
    for (const auto &row :
         {contact(10, 0, 1, 1, -1), contact(10.1, 0, -1, 1, -1), contact(10.2, 2, 1, 1, -1),
          contact(10.3, 0, 1, 1.5, -1), contact(10.4, 0, 1, 1, 99), contact(5, 0, 1, 1, -1)})
        rows.insert(rows.end(), row.begin(), row.end());
    std::vector<double> device{11, 99};
    device.resize(SessionSchema::DeviceColumns, qQNaN());
    const std::vector<double> input{12, 3, 0, 0, 0, 1, 0, 0, 0, 0.5};
    qint64 last = 0; // the blocks added below are last + 1 to last + 4
    {
        QSqlDatabase db = QSqlDatabase::addDatabase("QSQLITE", "last");
        db.setDatabaseName(path);
        QVERIFY(db.open());
        QSqlQuery query("SELECT max(rowid) FROM blocks", db);
        QVERIFY(query.next());
        last = query.value(0).toLongLong();
    }
    QSqlDatabase::removeDatabase("last");
    using S = SessionSchema::Stream;
    damage(path, {insertBlock(S::ContactFrames, rows, SessionSchema::ContactColumns),
                  "INSERT INTO blocks VALUES ('contact_frames', 20, 21, 3, 17, 'not zstd')",
                  insertBlock(S::DeviceFrames, device, SessionSchema::DeviceColumns),
                  insertBlock(S::OperatorInput, input, SessionSchema::InputColumns)});
    const ReadBack got = readAll(path);
    QCOMPARE(got.frames, qint64(good.frames.size()) + 1);
    QCOMPARE(got.deviceFrames, qint64(good.deviceFrames.size()));
    QCOMPARE(got.inputs, qint64(good.inputs.size()));
    const auto at = [&](const char *stream, int block) {
        return QStringLiteral("%1: %2 block %3").arg(path, stream).arg(last + block);
    };
    const QStringList expected{
        at("contact_frames", 1) + " row 2: \"left.f\" must be a finite non-negative number, "
                                  "got -1",
        at("contact_frames", 1) + " row 3: \"gripper\" must be 0 (left) or 1 (right), got 2",
        at("contact_frames", 1) + " row 4: \"left.n\" must be a non-negative integer, got 1.5",
        at("contact_frames", 1) + " row 5: \"left.actor\" names no actor of the session",
        at("contact_frames", 1) + " row 6: \"t\" must increase per gripper, got 5 after 10 for "
                                  "\"left\"",
        at("contact_frames", 2) + ": a block is not zstd data",
        at("device_frames", 3) + " row 1: \"t\", \"device\" and the values must be finite "
                                 "numbers and a device of the session",
        at("operator_input", 4) + " row 1: \"t\", the pose and the grip must be finite "
                                  "numbers and \"hand\" left or right"};
    QCOMPARE(got.rejected, expected);
    QCOMPARE(got.rejectedRows, qint64(5 + 3 + 1 + 1));
}

void TestSessions::blocksAreSealedBySecond()
{
    // Each commit writes its rows as a tail block, which a reader sees at once (what a crash
    // leaves); a second's tail blocks become one sealed block, which packs several times
    // smaller. A finished session holds one block per stream and second.
    const auto router = c3();
    const QString path = m_dir.filePath("sealed.db");
    const Recording r = synthetic(*router, 3500); // 3.5 s
    QString error;
    std::unique_ptr<SessionWriter> writer =
        SessionWriter::create(path, SessionInfo(), *router, &error);
    QVERIFY2(writer, qPrintable(error));
    writer->setActorTable(&r.actors);
    const auto write = [&](size_t from, size_t to) {
        for (size_t i = from; i < to; ++i)
            writer->recordContactFrame(r.frames[i], r.arrivals[i]);
    };
    write(0, 1000); // half a second: no block sealed yet
    QTRY_COMPARE_WITH_TIMEOUT(writer->committed(), quint64(1000), 30000);
    {
        std::unique_ptr<SessionReader> reader = SessionReader::open(path, &error);
        QVERIFY2(reader, qPrintable(error));
        QCOMPARE(reader->contactFrameCount(), qint64(1000));
        size_t i = 0;
        QVERIFY(reader->readContactFrames(
            [&](const ContactFrame &frame, double) {
                return sameBits(frame.t, r.frames[i++].t) &&
                       frame.left.n == r.frames[i - 1].left.n;
            },
            &error));
        QCOMPARE(i, size_t(1000));
    }
    write(1000, r.frames.size());
    QVERIFY2(writer->finish(&error), qPrintable(error));
    QSqlDatabase db = QSqlDatabase::addDatabase("QSQLITE", "sealed");
    db.setDatabaseName(path);
    QVERIFY(db.open());
    {
        QSqlQuery query(db);
        QVERIFY(query.exec("SELECT stream, count(*), sum(rows) FROM blocks GROUP BY stream"));
        QVERIFY(query.next());
        QCOMPARE(query.value(0).toString(), QString("contact_frames"));
        QCOMPARE(query.value(1).toInt(), 4);
        QCOMPARE(query.value(2).toInt(), 7000);
        QVERIFY(!query.next());
    }
    db.close();
    db = QSqlDatabase();
    QSqlDatabase::removeDatabase("sealed");
}

void TestSessions::keepsTheSteadyClock()
{
    // The steady clock beside the session's time (docs/science.md): a pair at the first
    // frame and one at the last, each taken while the frame was recorded.
    const auto router = c3();
    const QString path = m_dir.filePath("clock.db");
    const Recording r = synthetic(*router, 200);
    QString error;
    const double before = SessionClock::now();
    std::unique_ptr<SessionWriter> writer =
        SessionWriter::create(path, SessionInfo(), *router, &error);
    QVERIFY2(writer, qPrintable(error));
    writer->setActorTable(&r.actors);
    for (size_t i = 0; i < r.frames.size(); ++i)
        writer->recordContactFrame(r.frames[i], r.arrivals[i]);
    QVERIFY2(writer->finish(&error), qPrintable(error));
    QCOMPARE(writer->committed(), quint64(r.frames.size())); // the pairs are not values
    const double after = SessionClock::now();
    std::unique_ptr<SessionReader> reader = SessionReader::open(path, &error);
    QVERIFY2(reader, qPrintable(error));
    SessionClock clock;
    QVERIFY2(SessionClock::fromInfo(reader->info(), &clock, &error), qPrintable(error));
    QCOMPARE(clock.samples().size(), size_t(2));
    QCOMPARE(clock.samples().front().t, r.frames.front().t);
    QCOMPARE(clock.samples().back().t, r.frames.back().t);
    for (const SessionClock::Sample &s : clock.samples())
        QVERIFY(s.steady >= before && s.steady <= after);
    // 0.1 s of frames in far less than a second: faster than the clock, not lined up.
    QVERIFY(clock.rate() > 1.0 + SessionClock::MaxRateError);
    QVERIFY(!clock.followsClock());
    // The metadata export nests the pairs.
    QVERIFY(reader->info().toJson().value("steady_clock").isArray());
}

void TestSessions::steadyClockPairs_data()
{
    QTest::addColumn<QString>("pairs");
    QTest::addColumn<QString>("error");
    QTest::newRow("real time") << "[[0, 100], [10, 110.5], [20, 120.5]]"
                               << "";
    QTest::newRow("not an array") << "{\"t\": 0}"
                                  << "steady_clock: not a JSON array of [t, steady] pairs";
    QTest::newRow("not a pair") << "[[0, 100], [1]]"
                                << "steady_clock: pair 2 is not two numbers";
    QTest::newRow("not numbers") << "[[\"0\", 100]]"
                                 << "steady_clock: pair 1 is not two numbers";
    QTest::newRow("back in time") << "[[0, 100], [1, 99]]"
                                  << "steady_clock: pair 2 goes back in time";
}

void TestSessions::steadyClockPairs()
{
    QFETCH(QString, pairs);
    QFETCH(QString, error);
    SessionInfo info;
    info.extra.insert(SessionClock::MetadataKey, pairs);
    SessionClock clock;
    QString reason;
    QCOMPARE(SessionClock::fromInfo(info, &clock, &reason), error.isEmpty());
    QCOMPARE(reason, error);
    if (!error.isEmpty())
        return;
    // Between pairs, interpolated; beyond them, at the rate of real time. A pause (10.5 s
    // of clock for 10 s of session) slows the rate below 1: still on the clock.
    QCOMPARE(clock.toSteady(5.0), 105.25);
    QCOMPARE(clock.toSteady(15.0), 115.5);
    QCOMPARE(clock.toSteady(-1.0), 99.0);
    QCOMPARE(clock.toSteady(21.0), 121.5);
    QCOMPARE(clock.rate(), 20.0 / 20.5);
    QVERIFY(clock.followsClock());
}

void TestSessions::aSceneTooWideIsRefused()
{
    // A block's row holds at most SessionBlock::MaxWidth numbers: a wider scene state is
    // refused when written, never written to be refused when read.
    const auto router = c3();
    const QString path = m_dir.filePath("wide.db");
    QString error;
    std::unique_ptr<SessionWriter> writer =
        SessionWriter::create(path, SessionInfo(), *router, &error);
    QVERIFY2(writer, qPrintable(error));
    SceneState state;
    state.pose.assign(size_t(SessionBlock::MaxWidth), 0.5);
    writer->recordSceneState(state);
    QVERIFY(!writer->finish(&error));
    QCOMPARE(error, path + ": cannot write: a scene state of 65536 numbers is more than a "
                           "block's row holds (65531)");
}

void TestSessions::udpGarbageOversizeAndBatch()
{
    UdpFrameSource source;
    QString error;
    QVERIFY2(source.bind("127.0.0.1", 0, &error), qPrintable(error));
    QStringList rejections;
    source.setErrorHandler([&](const QString &line) { rejections.append(line); });
    QUdpSocket sender;
    const auto send = [&](const QByteArray &datagram) {
        QCOMPARE(sender.writeDatagram(datagram, QHostAddress::LocalHost, quint16(source.port())),
                 qint64(datagram.size()));
    };
    send("not json at all");
    send(QByteArray(UdpFrameSource::MaxDatagramSize + 1, ' '));
    send(
        "{\"t\": 0, \"gripper\": \"right\", \"left\": {\"f\": 3, \"n\": 2, \"actor\": \"cube\"}}");
    // A batch stops at its first invalid frame: 5 is none, and the two after it are dropped.
    send("[{\"t\": 0.1, \"gripper\": \"right\"}, 5, {\"t\": 0, \"gripper\": \"left\"},"
         " {\"t\": 0.05, \"gripper\": \"right\"}]");
    send("[{\"t\": 0, \"gripper\": \"left\"}, {\"t\": 0.05, \"gripper\": \"right\"}]");
    send("{\"t\": 1, \"gripper\": \"middle\"}");
    std::vector<ContactFrame> frames;
    for (int waited = 0; source.stats().datagrams < 6 && waited < 50; ++waited) {
        source.waitForDatagrams(100);
        source.poll([&](const ContactFrame &f, double arrival) {
            QVERIFY(arrival >= 0);
            frames.push_back(f);
        });
    }
    QCOMPARE(source.stats().datagrams, quint64(6));
    QCOMPARE(source.stats().frames, quint64(3));
    QCOMPARE(source.stats().oversize, quint64(1));
    QCOMPARE(source.stats().rejected, quint64(7)); // the batch's bad frame and the two after it
    QCOMPARE(frames.size(), size_t(3));
    QCOMPARE(frames[0].left.f, 3.0);
    QCOMPARE(source.actors().name(frames[0].left.actor), QString("cube"));
    QCOMPARE(frames[1].t, 0.1);
    QCOMPARE(frames[2].gripper, Gripper::Left);
    const QString prefix = QString("udp:%1: ").arg(source.port());
    QCOMPARE(rejections.size(), 5);
    QVERIFY2(rejections[0].startsWith(prefix + "invalid JSON at byte "),
             qPrintable(rejections[0]));
    QCOMPARE(rejections[1], prefix + "datagram of 32769 bytes is over the limit of 32768");
    QCOMPARE(rejections[2], prefix + "[1]: a contact frame must be a JSON object (the batch's 2 "
                                     "later frame(s) dropped)");
    QVERIFY2(rejections[3].startsWith(prefix + "[1]: \"t\" must increase per gripper"),
             qPrintable(rejections[3]));
    QVERIFY(rejections[4].startsWith(prefix + "\"gripper\" must be"));
}

void TestSessions::udpFlood()
{
    // 20 000 datagrams as fast as the receiver drains them: it reads in batches, so each
    // poll returns promptly however many wait, and every datagram is processed once.
    constexpr int Total = 20000;
    std::atomic<int> port{0};
    std::atomic<quint64> received{0};
    std::atomic<bool> stop{false};
    std::atomic<qint64> longestPollNs{0};
    quint64 frames = 0;
    quint64 garbage = 0;
    std::thread receiver([&] {
        UdpFrameSource source; // lives on this thread, as the docs ask
        QString error;
        if (!source.bind("127.0.0.1", 0, &error))
            return;
        port = source.port();
        QElapsedTimer poll;
        while (!stop.load() || source.waitForDatagrams(200)) {
            source.waitForDatagrams(20);
            poll.start();
            source.poll([](const ContactFrame &, double) {}, 256);
            longestPollNs = std::max(longestPollNs.load(), poll.nsecsElapsed());
            received = source.stats().datagrams;
        }
        frames = source.stats().frames;
        garbage = source.stats().rejected;
    });
    while (port.load() == 0)
        QThread::msleep(1);
    QUdpSocket sender;
    for (int i = 0; i < Total; ++i) {
        const QByteArray datagram =
            i % 10 == 9 ? QByteArray("\x01\x02garbage")
                        : QStringLiteral("{\"t\": %1, \"gripper\": \"right\"}").arg(i).toUtf8();
        sender.writeDatagram(datagram, QHostAddress::LocalHost, quint16(port.load()));
        // Flow control, so the kernel's buffer never overflows: at most 200 in flight.
        for (int waited = 0; quint64(i) >= received.load() + 200 && waited < 5000; ++waited)
            QThread::usleep(200);
    }
    for (int waited = 0; received.load() < Total && waited < 500; ++waited)
        QThread::msleep(10);
    stop = true;
    receiver.join();
    QCOMPARE(received.load(), quint64(Total));
    QCOMPARE(frames, quint64(Total - Total / 10));
    QCOMPARE(garbage, quint64(Total / 10));
    QVERIFY2(longestPollNs.load() < 500'000'000, "a poll of 256 datagrams took over 0.5 s");
}

QTEST_GUILESS_MAIN(TestSessions)
#include "tst_sessions.moc"
