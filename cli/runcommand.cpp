// SPDX-License-Identifier: MIT
#include "runcommand.h"

#include "devicebindings.h"
#include "devicemanager.h"
#include "deviceoutputsink.h"
#include "emergencystop.h"
#include "foxglovepublisher.h"
#include "foxgloveserver.h"
#include "jsonlineswriter.h"
#include "operator.h"
#include "quitsignal.h"
#include "sessionwriter.h"
#include "simrun.h"
#include "sinklist.h"

#include <QDateTime>
#include <QElapsedTimer>
#include <QJsonDocument>
#include <QThread>

#include <cstdio>
#include <unistd.h>

namespace semhap {

namespace {

/**
 * Writes the run's requested streams as JSON Lines, records them into a session and serves
 * them to Foxglove.
 */
class StreamWriter : public RunSink
{
public:
    StreamWriter(const SimRun &run, QIODevice *frames, QIODevice *events, QIODevice *devices,
                 SessionWriter *session, FoxglovePublisher *live)
        : m_frames(frames), m_events(events), m_devices(devices), m_session(session), m_live(live),
          m_frameWriter(frames), m_eventWriter(events), m_deviceWriter(devices)
    {
        const Router &router = const_cast<SimRun &>(run).pipeline().router();
        QStringList names;
        for (int d = 0; d < router.player().deviceCount(); ++d)
            names.append(router.player().deviceName(d));
        m_eventWriter.setNodeNames(router.nodeIds());
        m_deviceWriter.setDeviceNames(names);
        m_frameWriter.setActorTable(&const_cast<SimRun &>(run).world().actors());
    }
    void onContactFrame(const ContactFrame &frame) override
    {
        if (m_session)
            m_session->recordContactFrame(frame, qQNaN());
        if (m_frames)
            m_frameWriter.write(frame);
        if (m_live)
            m_live->onContactFrame(frame);
    }
    void onEvent(const SemanticEvent &event) override
    {
        if (m_session)
            m_session->onEvent(event);
        if (m_events)
            m_eventWriter.write(event);
        if (m_live)
            m_live->onEvent(event);
    }
    void onDeviceFrame(const DeviceFrame &frame) override
    {
        if (m_session)
            m_session->onDeviceFrame(frame);
        if (m_devices)
            m_deviceWriter.write(frame);
        if (m_live)
            m_live->onDeviceFrame(frame);
    }

private:
    QIODevice *m_frames;
    QIODevice *m_events;
    QIODevice *m_devices;
    SessionWriter *m_session;
    FoxglovePublisher *m_live;
    JsonLinesWriter m_frameWriter;
    JsonLinesWriter m_eventWriter;
    JsonLinesWriter m_deviceWriter;
};

/** Sends the run's device frames to bound bands and everything to the writer. */
class BoundSink : public RunSink
{
public:
    BoundSink(DeviceOutputSink &devices, StreamWriter &writer)
        : m_writer(writer), m_sinks{&devices, &writer}
    {}
    void onContactFrame(const ContactFrame &frame) override { m_writer.onContactFrame(frame); }
    void onEvent(const SemanticEvent &event) override { m_sinks.onEvent(event); }
    void onDeviceFrame(const DeviceFrame &frame) override { m_sinks.onDeviceFrame(frame); }

private:
    StreamWriter &m_writer;
    SinkList m_sinks;
};

} // namespace

QString RunCommand::summary() const
{
    return tr("Runs the pipeline on a simulated scene with a scripted or reactive operator, "
              "as fast as possible (or in real time), and reports the task metrics.");
}

void RunCommand::configure(QCommandLineParser &parser)
{
    parser.addOption(
        {QStringLiteral("scene"),
         tr("Scene: %1, or an MJCF file.").arg(World::builtinScenes().join(QStringLiteral(", "))),
         tr("NAME|FILE")});
    parser.addOption(
        {QStringLiteral("router"), tr("Router preset or router file."), tr("PRESET|FILE")});
    parser.addOption(
        {QStringLiteral("operator"),
         tr("Who drives the grippers: %1.").arg(operatorNames().join(QStringLiteral(", "))),
         tr("NAME")});
    parser.addOption({QStringLiteral("seed"),
                      tr("Seed of the operator and of a laid-out scene (default 1)."), tr("N")});
    parser.addOption({QStringLiteral("duration"), tr("Simulated seconds."), tr("S")});
    addSceneOptions(parser);
    parser.addOption({QStringLiteral("reaction-time"),
                      tr("Reaction time in seconds of the reactive operator, and of the person "
                         "the router's predict nodes warn (default 0.25)."),
                      tr("S")});
    parser.addOption({QStringLiteral("set"), tr("Override a router node parameter (repeatable)."),
                      tr("NODE.PARAM=VALUE")});
    parser.addOption({QStringLiteral("metrics"),
                      tr("Where to write the metrics (JSON), or - for standard output."),
                      tr("FILE|-")});
    parser.addOption(
        {QStringLiteral("frames"), tr("Where to write the contact frames."), tr("FILE|-")});
    parser.addOption(
        {QStringLiteral("events"), tr("Where to write the semantic events."), tr("FILE|-")});
    parser.addOption(
        {QStringLiteral("device-frames"), tr("Where to write the device frames."), tr("FILE|-")});
    parser.addOption({QStringLiteral("realtime"), tr("Run at the speed of the wall clock.")});
    parser.addOption({QStringLiteral("bind"),
                      tr("Send a device's output to a band, e.g. right.vibro=serial:/dev/ttyACM0 "
                         "(repeatable); implies --realtime."),
                      tr("NAME=URI")});
    addFoxgloveServerOption(parser); // implies --realtime
    parser.addOption({QStringLiteral("session"),
                      tr("Record the run into a new session database (docs/sessions.md)."),
                      tr("FILE")});
    parser.addOption({QStringLiteral("notes"), tr("Notes kept with the session."), tr("TEXT")});
}

int RunCommand::execute(const QCommandLineParser &parser)
{
    if (!parser.positionalArguments().isEmpty())
        return usageError(
            tr("unexpected argument '%1'").arg(parser.positionalArguments().first()));
    for (const QString &required : {QStringLiteral("scene"), QStringLiteral("router"),
                                    QStringLiteral("operator"), QStringLiteral("duration")}) {
        if (!parser.isSet(required))
            return usageError(tr("--%1 is required").arg(required));
    }
    RunOptions options;
    options.scene = parser.value(QStringLiteral("scene"));
    options.router = parser.value(QStringLiteral("router"));
    options.operatorName = parser.value(QStringLiteral("operator"));
    options.overrides = parser.values(QStringLiteral("set"));
    double seed = 1;
    if (!simulationOptions(parser, &options) ||
        !numberOption(parser, QStringLiteral("seed"), &seed))
        return ExitUsage;
    RouterContext context;
    context.reactionTime = options.reactionTime;
    if (!routerContextOption(parser, &context))
        return ExitUsage;
    options.reactionTime = context.reactionTime;
    if (seed < 0 || seed != std::floor(seed) || seed > RunOptions::MaxSeed)
        return usageError(tr("--seed must be a whole number >= 0"));
    options.seed = std::uint64_t(seed);

    const QStringList outputs{
        parser.value(QStringLiteral("metrics")), parser.value(QStringLiteral("frames")),
        parser.value(QStringLiteral("events")), parser.value(QStringLiteral("device-frames"))};
    if (!checkSingleStdout(outputs))
        return ExitUsage;

    QString error;
    std::unique_ptr<SimRun> run = SimRun::create(options, &error);
    if (!run)
        return inputError(error);
    reportWarnings(run->pipeline().router().graph());
    keepFromOutputs(options.scene, Kept::Input);
    keepFromOutputs(options.router, Kept::Input);
    keepFromOutputs(parser.value(QStringLiteral("session")), Kept::Session);
    std::array<QIODevice *, 4> devices{};
    for (size_t i = 0; i < devices.size(); ++i) {
        if (outputs[int(i)].isEmpty())
            continue;
        devices[i] = openOutput(outputs[int(i)]);
        if (!devices[i])
            return ExitInvalidInput;
    }
    DeviceManager bands;
    QString message;
    bool usage = false;
    const QStringList bindings = parser.values(QStringLiteral("bind"));
    if (!bindDevices(bindings, run->pipeline().router().player(), bands, &message, &usage))
        return usage ? usageError(message) : inputError(message);
    std::unique_ptr<SessionWriter> session;
    if (parser.isSet(QStringLiteral("session"))) {
        SessionInfo info = run->sessionInfo();
        info.source = QStringLiteral("run");
        info.addBindings(bindings);
        info.notes = parser.value(QStringLiteral("notes"));
        session = SessionWriter::create(parser.value(QStringLiteral("session")), info,
                                        run->pipeline().router(), &message);
        if (!session)
            return inputError(message);
        session->setActorTable(&run->world().actors());
    }
    int exit = ExitOk;
    const std::unique_ptr<FoxgloveServer> server = foxgloveServerFromOptions(parser, &exit);
    if (!server && exit != ExitOk)
        return exit;
    std::unique_ptr<FoxglovePublisher> live;
    if (server) {
        live = std::make_unique<FoxglovePublisher>(*server, run->pipeline().router(),
                                                   run->world().actors(),
                                                   QDateTime::currentMSecsSinceEpoch() * 1000000);
        for (const Gripper g : {Gripper::Left, Gripper::Right}) {
            if (run->world().hasGripper(g))
                live->advertise(g);
        }
    }
    StreamWriter writer(*run, devices[1], devices[2], devices[3], session.get(), live.get());
    const bool bound = !bands.boundNames().isEmpty();
    // A signal stops the bands at once and ends the run, which still closes the session and
    // hands the outputs over with what was simulated.
    EmergencyStop::installGraceful();
    if (bound)
        bands.armAll(true);
    DeviceOutputSink output(run->pipeline().router().player(), bands);
    BoundSink sink(output, writer);

    const bool progress = isatty(fileno(stderr)) && m_io.err != nullptr;
    QElapsedTimer wall;
    wall.start();
    qint64 lastDraw = -1000;
    // Bands and viewers are served as things happen.
    const bool realtime = parser.isSet(QStringLiteral("realtime")) || bound || server;
    while (!QuitSignal::requested() && run->step(sink)) {
        if (const OutputFile *failed = failedOutput()) {
            bands.stopAll();
            return inputError(failed->writeError().toString());
        }
        if (session)
            run->recordSceneState(*session);
        if (realtime) {
            const qint64 ahead = qint64(run->time() * 1000) - wall.elapsed();
            if (ahead > 1)
                QThread::msleep(quint64(ahead));
            flushOutputs(); // a consumer of a real-time run sees it live
        }
        if (progress && wall.elapsed() - lastDraw >= 200) {
            lastDraw = wall.elapsed();
            const double done = run->time() / options.duration;
            const int bar = int(done * 30);
            m_io.err->write(
                QStringLiteral("\r[%1%2] %3% %4/%5 s  %6x real time ")
                    .arg(QString(bar, QLatin1Char('#')), QString(30 - bar, QLatin1Char(' ')))
                    .arg(int(done * 100), 3)
                    .arg(run->time(), 0, 'f', 1)
                    .arg(options.duration)
                    .arg(run->time() / std::max(1e-3, double(wall.elapsed()) / 1000), 0, 'f', 1)
                    .toUtf8());
        }
    }
    if (progress)
        m_io.err->write("\r\033[K");
    bands.stopAll();
    finishFoxgloveServer(server.get());
    reportDroppedEvents(run->pipeline());
    if (QuitSignal::requested())
        report(tr("run: interrupted at t = %1 s; the session and the outputs hold what was "
                  "simulated")
                   .arg(run->time()));
    if (session && !finishSession(*session))
        return ExitInvalidInput;

    const double wallSeconds = double(wall.elapsed()) / 1000;
    const QJsonObject metrics = run->report(wallSeconds);
    if (devices[0])
        devices[0]->write(QJsonDocument(metrics).toJson(QJsonDocument::Indented));
    return ExitOk;
}

} // namespace semhap
