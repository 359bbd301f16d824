// SPDX-License-Identifier: MIT
#include "listencommand.h"

#include "devicebindings.h"
#include "devicemanager.h"
#include "deviceoutputsink.h"
#include "emergencystop.h"
#include "quitsignal.h"
#include "sessionwriter.h"
#include "sinklist.h"
#include "streamsink.h"
#include "udpframesource.h"

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
    parser.addOption({QStringLiteral("address"),
                      tr("Address to listen on (default 127.0.0.1, this machine only; 0.0.0.0 "
                         "for every network)."),
                      tr("ADDR")});
    parser.addOption({QStringLiteral("router"), tr("Router preset or router file (default C3)."),
                      tr("PRESET|FILE")});
    addRoutingOptions(parser);
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
    if (!parser.isSet(QStringLiteral("udp")))
        return usageError(tr("--udp is required"));
    double port = 0;
    double duration = 0;
    double silence = UdpFrameSource::DefaultSilence;
    if (!numberOption(parser, QStringLiteral("udp"), &port) ||
        !numberOption(parser, QStringLiteral("duration"), &duration) ||
        !numberOption(parser, QStringLiteral("silence"), &silence))
        return ExitUsage;
    if (!(silence > 0.0 && silence <= 3600.0))
        return usageError(tr("--silence must be between 0 and 3600 s"));

    if (port < 0 || port > 65535 || port != std::floor(port))
        return usageError(tr("--udp must be a port number (0 to 65535)"));
    if (duration < 0)
        return usageError(tr("--duration must not be negative"));
    const QString eventsPath = parser.value(QStringLiteral("events"));
    const QString framesPath = parser.value(QStringLiteral("device-frames"));
    if (!checkSingleStdout({eventsPath, framesPath}))
        return ExitUsage;

    const QString routerName = parser.isSet(QStringLiteral("router"))
                                   ? parser.value(QStringLiteral("router"))
                                   : QStringLiteral("C3");
    const QStringList overrides = parser.values(QStringLiteral("set"));
    RouterContext context;
    if (!routerContextOption(parser, &context))
        return ExitUsage;
    LoadError error;
    std::unique_ptr<Router> router = loadRouter(routerName, overrides, &error, context);
    if (!router)
        return inputError(error.toString());
    reportWarnings(router->graph());
    keepFromOutputs(routerName, Kept::Input);
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
    UdpFrameSource source;
    if (!maxGapOption(parser, &source.parser()))
        return ExitUsage;
    source.setSilence(silence);
    if (!source.bind(address, int(port), &message))
        return inputError(message);

    std::unique_ptr<SessionWriter> session;
    if (parser.isSet(QStringLiteral("session"))) {
        SessionInfo info;
        info.source = QStringLiteral("listen");
        info.routerSource = routerName;
        info.overrides = overrides;
        info.routerContext = context;
        info.addBindings(bindings);
        info.notes = parser.value(QStringLiteral("notes"));
        info.extra.insert(QStringLiteral("udp"),
                          QStringLiteral("%1:%2").arg(address).arg(source.port()));
        session = SessionWriter::create(parser.value(QStringLiteral("session")), info, *router,
                                        &message);
        if (!session)
            return inputError(message);
        session->setActorTable(&source.actors());
    }

    // A signal lets the loop close the session and the outputs; bands stop at once.
    EmergencyStop::installGraceful();
    if (!devices.boundNames().isEmpty())
        devices.armAll(true);
    Throttle throttle([this](const QString &line) { report(line); });
    source.setErrorHandler([&throttle](const QString &line) { throttle.report(line); });
    report(tr("listening on udp:%1:%2").arg(address).arg(source.port()));

    Pipeline pipeline(std::move(router));
    StreamSink streams(pipeline.router(), events, deviceFrames);
    DeviceOutputSink output(pipeline.router().player(), devices);
    SinkList sink{&output, &streams, session.get()};
    const auto process = [&](const ContactFrame &frame, double arrival) {
        if (session)
            session->recordContactFrame(frame, arrival);
        pipeline.process(frame, sink);
    };
    QElapsedTimer wall;
    wall.start();
    const qint64 limit = duration > 0 ? qint64(duration * 1000) : -1;
    while (!QuitSignal::requested() && (limit < 0 || wall.elapsed() < limit)) {
        qint64 wait = limit < 0 ? 100 : limit - wall.elapsed();
        if (source.msecsToSilence() >= 0)
            wait = std::min(wait, source.msecsToSilence());
        if (source.waitForDatagrams(int(std::clamp<qint64>(wait, 0, 100))) &&
            source.poll(process) > 0)
            flushOutputs();
        if (source.fellSilent()) {
            // A silent sender must not hold the bands where it left them.
            pipeline.endAll(sink);
            devices.stopAll();
            flushOutputs();
            throttle.report(tr("udp:%1: no frame for %2 s: messages ended, bands stopped")
                                .arg(source.port())
                                .arg(source.silence()));
        }
        throttle.roll();
        if (const OutputFile *failed = failedOutput()) {
            devices.stopAll();
            if (session)
                finishSession(*session);
            return inputError(failed->writeError().toString());
        }
    }
    if (source.stats().frames > 0)
        pipeline.flush(sink);
    devices.stopAll();
    reportDroppedEvents(pipeline);
    if (session && !finishSession(*session))
        return ExitInvalidInput;
    if (QuitSignal::requested())
        report(tr("udp:%1: interrupted after t = %2 s; the outputs hold what was routed")
                   .arg(source.port())
                   .arg(pipeline.now()));

    const UdpFrameSource::Stats &stats = source.stats();
    report(tr("udp:%1: %2 datagram(s), %3 frame(s), %4 rejected (%5 oversize)")
               .arg(source.port())
               .arg(stats.datagrams)
               .arg(stats.frames)
               .arg(stats.rejected)
               .arg(stats.oversize));
    return ExitOk;
}

} // namespace semhap
