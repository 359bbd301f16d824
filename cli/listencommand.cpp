// SPDX-License-Identifier: MIT
#include "listencommand.h"

#include "devicebindings.h"
#include "devicemanager.h"
#include "deviceoutputsink.h"
#include "emergencystop.h"
#include "foxglovepublisher.h"
#include "foxgloveserver.h"
#include "foxglovesource.h"
#include "quitsignal.h"
#include "sessionwriter.h"
#include "sinklist.h"
#include "streamsink.h"
#include "udpframesource.h"

#include <QDateTime>
#include <QElapsedTimer>

#include <functional>

namespace semhap {

namespace {

/**
 * Lets a few rejection lines a second through and counts the rest, so a sender gone wrong
 * cannot flood the terminal or slow the loop down.
 */
class Throttle
{
public:
    static constexpr int LinesPerSecond = 5;

    explicit Throttle(std::function<void(const QString &)> print) : m_print(std::move(print))
    {
        m_clock.start();
    }

    void report(const QString &line)
    {
        roll();
        if (m_printed < LinesPerSecond) {
            ++m_printed;
            m_print(line);
        } else {
            ++m_suppressed;
        }
    }
    /** Says how many lines were held back, once their second is over. */
    void roll()
    {
        if (m_clock.elapsed() < 1000)
            return;
        if (m_suppressed > 0)
            m_print(ListenCommand::tr("… and %n more rejected in the last second", nullptr,
                                      m_suppressed));
        m_clock.restart();
        m_printed = 0;
        m_suppressed = 0;
    }

private:
    std::function<void(const QString &)> m_print;
    QElapsedTimer m_clock;
    int m_printed = 0;
    int m_suppressed = 0;
};

} // namespace

QString ListenCommand::summary() const
{
    return tr("Receives contact frames over UDP from another program and runs them through "
              "detectors, router and devices live, optionally recording a session.");
}

void ListenCommand::configure(QCommandLineParser &parser)
{
    parser.addOption({QStringLiteral("udp"),
                      tr("UDP port to listen on (0: any free port, printed at start)."),
                      tr("PORT")});
    parser.addOption({QStringLiteral("foxglove"),
                      tr("Follow a robot's Foxglove WebSocket server (foxglove_bridge) instead: "
                         "its topics through --topics (docs/ros.md)."),
                      tr("ws://HOST:PORT")});
    parser.addOption({QStringLiteral("topics"),
                      tr("With --foxglove: the semhap.topics/1 map of the robot's topics to "
                         "contact frames."),
                      tr("MAP.json")});
    parser.addOption({QStringLiteral("address"),
                      tr("Address to listen on (default 127.0.0.1, this machine only; 0.0.0.0 "
                         "for every network)."),
                      tr("ADDR")});
    parser.addOption({QStringLiteral("router"), tr("Router preset or router file (default C3)."),
                      tr("PRESET|FILE")});
    addRoutingOptions(parser);
    addFoxgloveServerOption(parser);
    parser.addOption({QStringLiteral("session"),
                      tr("Record into a new session database, with each frame's arrival time."),
                      tr("FILE")});
    parser.addOption({QStringLiteral("notes"), tr("Notes kept with the session."), tr("TEXT")});
    parser.addOption({QStringLiteral("bind"),
                      tr("Send a device's output to a band, e.g. "
                         "right.vibro=serial:/dev/ttyACM0 (repeatable)."),
                      tr("NAME=URI")});
    // Spellings of semhap 1.0, where --bind was the address: read, with a warning.
    QCommandLineOption oldBinding(QStringLiteral("bind-device"), tr("Old name of --bind."),
                                  tr("NAME=URI"));
    oldBinding.setFlags(QCommandLineOption::HiddenFromHelp);
    parser.addOption(oldBinding);
    parser.addOption({QStringLiteral("duration"),
                      tr("Stop after this many seconds (default: until interrupted)."), tr("S")});
    addMaxGapOption(parser);
    parser.addOption({QStringLiteral("silence"),
                      tr("After this many seconds without a valid frame, end every message and "
                         "stop the bands (default 0.25)."),
                      tr("S")});
}

int ListenCommand::execute(const QCommandLineParser &parser)
{
    if (!parser.positionalArguments().isEmpty())
        return usageError(
            tr("unexpected argument '%1'").arg(parser.positionalArguments().first()));
    const bool foxglove = parser.isSet(QStringLiteral("foxglove"));
    if (foxglove == parser.isSet(QStringLiteral("udp")))
        return usageError(tr("give one source: --udp PORT or --foxglove ws://HOST:PORT"));
    if (foxglove != parser.isSet(QStringLiteral("topics")))
        return usageError(foxglove ? tr("--foxglove needs the map of its topics: --topics "
                                        "MAP.json")
                                   : tr("--topics: only with --foxglove"));
    const QUrl url(parser.value(QStringLiteral("foxglove")));
    if (foxglove && (!url.isValid() || (url.scheme() != QLatin1String("ws") &&
                                        url.scheme() != QLatin1String("wss"))))
        return usageError(tr("--foxglove: expected ws://HOST:PORT, got '%1'")
                              .arg(parser.value(QStringLiteral("foxglove"))));
    double port = 0;
    double duration = 0;
    double silence = UdpFrameSource::DefaultSilence;
    if (!numberOption(parser, QStringLiteral("udp"), &port) ||
        !numberOption(parser, QStringLiteral("duration"), &duration) ||
        !numberOption(parser, QStringLiteral("silence"), &silence))
        return ExitUsage;
    if (!(silence > 0.0 && silence <= 3600.0))
        return usageError(tr("--silence must be between 0 and 3600 s"));

    if (!foxglove && (port < 0 || port > 65535 || port != std::floor(port)))
        return usageError(tr("--udp must be a port number (0 to 65535)"));
    if (duration < 0)
        return usageError(tr("--duration must not be negative"));
    const QString eventsPath = parser.value(QStringLiteral("events"));
    const QString framesPath = parser.value(QStringLiteral("device-frames"));
    if (!checkSingleStdout({eventsPath, framesPath}))
        return ExitUsage;

    RoutingChoice choice;
    int exit = ExitOk;
    std::unique_ptr<Router> router =
        routerFromOptions(parser, QStringLiteral("C3"), &choice, &exit);
    if (!router)
        return exit;
    keepFromOutputs(parser.value(QStringLiteral("session")), Kept::Session);
    QIODevice *events = eventsPath.isEmpty() ? nullptr : openOutput(eventsPath);
    QIODevice *deviceFrames = framesPath.isEmpty() ? nullptr : openOutput(framesPath);
    if ((!eventsPath.isEmpty() && !events) || (!framesPath.isEmpty() && !deviceFrames))
        return ExitInvalidInput;

    DeviceManager devices;
    QString message;
    bool usage = false;
    // --bind is a device binding, as in route and run; a value without '=' is an address
    // given the 1.0 way.
    QStringList bindings;
    QString address = parser.isSet(QStringLiteral("address"))
                          ? parser.value(QStringLiteral("address"))
                          : QStringLiteral("127.0.0.1");
    for (const QString &value : parser.values(QStringLiteral("bind"))) {
        if (value.contains(QLatin1Char('='))) {
            bindings.append(value);
        } else {
            report(tr("listen: --bind %1: deprecated: the address to listen on is --address; "
                      "--bind binds a device (NAME=URI)")
                       .arg(value));
            address = value;
        }
    }
    if (parser.isSet(QStringLiteral("bind-device"))) {
        report(tr("listen: --bind-device is deprecated: use --bind NAME=URI"));
        bindings += parser.values(QStringLiteral("bind-device"));
    }
    if (!bindDevices(bindings, router->player(), devices, &message, &usage))
        return usage ? usageError(message) : inputError(message);
    // The source: a sender's UDP datagrams, or a robot's Foxglove WebSocket server. The loop
    // below asks it the same few things either way.
    UdpFrameSource udp;
    std::unique_ptr<FoxgloveSource> robot;
    std::function<int(const std::function<void(const ContactFrame &, double)> &, int)> poll;
    std::function<qint64()> msecsToSilence;
    std::function<bool()> fellSilent;
    std::function<QString()> fatal = [] { return QString(); };
    QString name;
    const ActorTable *actors = nullptr;
    TopicMap robotMap;
    if (foxglove) {
        LoadError mapError;
        const QString mapPath = parser.value(QStringLiteral("topics"));
        if (!TopicMap::load(mapPath, &robotMap, &mapError))
            return inputError(mapError.toString());
        robot = std::make_unique<FoxgloveSource>(url, robotMap, mapPath);
        robot->setSilence(silence);
        name = robot->describe();
        actors = &robot->actors();
        poll = [&](const auto &process, int ms) { return robot->poll(process, ms); };
        msecsToSilence = [&] { return robot->msecsToSilence(); };
        fellSilent = [&] { return robot->fellSilent(); };
        fatal = [&] { return robot->fatalError(); };
    } else {
        if (!maxGapOption(parser, &udp.parser()))
            return ExitUsage;
        udp.setSilence(silence);
        if (!udp.bind(address, int(port), &message))
            return inputError(message);
        name = QStringLiteral("udp:%1").arg(udp.port());
        actors = &udp.actors();
        poll = [&](const auto &process, int ms) {
            return udp.waitForDatagrams(ms) ? udp.poll(process) : 0;
        };
        msecsToSilence = [&] { return udp.msecsToSilence(); };
        fellSilent = [&] { return udp.fellSilent(); };
    }

    std::unique_ptr<SessionWriter> session;
    if (parser.isSet(QStringLiteral("session"))) {
        SessionInfo info;
        info.source = QStringLiteral("listen");
        info.routerSource = choice.router;
        info.overrides = choice.overrides;
        info.routerContext = choice.context;
        info.addBindings(bindings);
        info.notes = parser.value(QStringLiteral("notes"));
        if (foxglove) {
            info.extra.insert(QStringLiteral("foxglove"), url.toString());
            info.extra.insert(QStringLiteral("topics"), parser.value(QStringLiteral("topics")));
        } else {
            info.extra.insert(QStringLiteral("udp"),
                              QStringLiteral("%1:%2").arg(address).arg(udp.port()));
        }
        session = SessionWriter::create(parser.value(QStringLiteral("session")), info, *router,
                                        &message);
        if (!session)
            return inputError(message);
        session->setActorTable(actors);
    }

    const std::unique_ptr<FoxgloveServer> server = foxgloveServerFromOptions(parser, &exit);
    if (!server && exit != ExitOk)
        return exit;

    // A signal lets the loop close the session and the outputs; bands stop at once.
    EmergencyStop::installGraceful();
    if (!devices.boundNames().isEmpty())
        devices.armAll(true);
    Throttle throttle([this](const QString &line) { report(line); });
    const auto throttled = [&throttle](const QString &line) { throttle.report(line); };
    if (robot) {
        robot->setErrorHandler(throttled);
        robot->start();
        report(tr("following %1").arg(name));
    } else {
        udp.setErrorHandler(throttled);
        report(tr("listening on udp:%1:%2").arg(address).arg(udp.port()));
    }

    Pipeline pipeline(std::move(router));
    StreamSink streams(pipeline.router(), events, deviceFrames);
    DeviceOutputSink output(pipeline.router().player(), devices);
    std::unique_ptr<FoxglovePublisher> live;
    if (server) {
        live = std::make_unique<FoxglovePublisher>(*server, pipeline.router(), *actors, 0);
        // A robot's grippers are its map's; a UDP sender's show with their first frame.
        for (const Gripper g : {Gripper::Left, Gripper::Right}) {
            if (robot && robotMap.grippers[size_t(g)].present)
                live->advertise(g);
        }
    }
    SinkList sink{&output, &streams, session.get(), live.get()};
    long long frames = 0;
    const auto process = [&](const ContactFrame &frame, double arrival) {
        if (session)
            session->recordContactFrame(frame, arrival);
        if (live) {
            // A robot's frames are on its own clock, so its viewer shows semhap's topics
            // beside the robot's; a UDP sender's t is put on the wall clock at its first frame.
            if (frames == 0)
                live->setOrigin(robot ? robot->epoch() * 1000000000
                                      : QDateTime::currentMSecsSinceEpoch() * 1000000 -
                                            std::llround(frame.t * 1e9));
            live->onContactFrame(frame);
        }
        pipeline.process(frame, sink);
        ++frames;
    };
    QElapsedTimer wall;
    wall.start();
    const qint64 limit = duration > 0 ? qint64(duration * 1000) : -1;
    while (!QuitSignal::requested() && (limit < 0 || wall.elapsed() < limit)) {
        qint64 wait = limit < 0 ? 100 : limit - wall.elapsed();
        if (msecsToSilence() >= 0)
            wait = std::min(wait, msecsToSilence());
        if (poll(process, int(std::clamp<qint64>(wait, 0, 100))) > 0)
            flushOutputs();
        if (!fatal().isEmpty()) {
            devices.stopAll();
            if (session)
                finishSession(*session);
            return inputError(fatal());
        }
        if (fellSilent()) {
            // A silent sender must not hold the bands where it left them. The frames that
            // waited for the silent source are routed first.
            poll(process, 0);
            pipeline.endAll(sink);
            devices.stopAll();
            flushOutputs();
            throttle.report(
                tr("%1: no frame for %2 s: messages ended, bands stopped").arg(name).arg(silence));
        }
        throttle.roll();
        if (const OutputFile *failed = failedOutput()) {
            devices.stopAll();
            if (session)
                finishSession(*session);
            return inputError(failed->writeError().toString());
        }
    }
    if (frames > 0)
        pipeline.flush(sink);
    devices.stopAll();
    finishFoxgloveServer(server.get());
    reportDroppedEvents(pipeline);
    if (session && !finishSession(*session))
        return ExitInvalidInput;
    if (QuitSignal::requested())
        report(tr("%1: interrupted after t = %2 s; the outputs hold what was routed")
                   .arg(name)
                   .arg(pipeline.now()));

    if (robot) {
        const FoxgloveSource::Stats &stats = robot->stats();
        report(tr("%1: %2 connection(s), %3 message(s), %4 frame(s), %5 rejected")
                   .arg(name)
                   .arg(stats.connections)
                   .arg(stats.messages)
                   .arg(stats.frames)
                   .arg(stats.rejected));
    } else {
        const UdpFrameSource::Stats &stats = udp.stats();
        report(tr("udp:%1: %2 datagram(s), %3 frame(s), %4 rejected (%5 oversize)")
                   .arg(udp.port())
                   .arg(stats.datagrams)
                   .arg(stats.frames)
                   .arg(stats.rejected)
                   .arg(stats.oversize));
    }
    return ExitOk;
}

} // namespace semhap
