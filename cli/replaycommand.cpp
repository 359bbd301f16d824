// SPDX-License-Identifier: MIT
#include "replaycommand.h"

#include "sessionreader.h"
#include "sinklist.h"
#include "streamsink.h"

#include <QJsonDocument>
#include <QJsonObject>

#include <map>

namespace semhap {

namespace {

/** Tallies each message's begins and active time: the numbers an A/B compares. */
class MessageTally : public PipelineSink
{
public:
    explicit MessageTally(const QStringList &nodes) : m_nodes(nodes) {}

    void onEvent(const SemanticEvent &event) override
    {
        ++m_events;
        const QString key =
            m_nodes.value(event.node) + QLatin1Char('.') + messageName(event.message);
        Tally &tally = m_tallies[key];
        if (event.phase == EventPhase::Begin) {
            ++tally.begins;
            tally.since = event.t;
        } else if (event.phase == EventPhase::End && tally.since >= 0) {
            tally.active += event.t - tally.since;
            tally.since = -1;
        }
    }
    void onDeviceFrame(const DeviceFrame &) override { ++m_deviceFrames; }

    /** The metrics, messages still active counted up to `end`. */
    QJsonObject metrics(double end) const
    {
        QJsonObject messages;
        for (const auto &[key, tally] : m_tallies) {
            const double open = tally.since >= 0 ? end - tally.since : 0.0;
            messages.insert(key,
                            QJsonObject{{QStringLiteral("begins"), tally.begins},
                                        {QStringLiteral("active_seconds"), tally.active + open}});
        }
        return {{QStringLiteral("events"), double(m_events)},
                {QStringLiteral("device_frames"), double(m_deviceFrames)},
                {QStringLiteral("messages"), messages}};
    }

private:
    struct Tally
    {
        int begins = 0;
        double active = 0.0;
        double since = -1.0;
    };
    QStringList m_nodes;
    std::map<QString, Tally> m_tallies;
    qint64 m_events = 0;
    qint64 m_deviceFrames = 0;
};

} // namespace

QString ReplayCommand::summary() const
{
    return tr("Runs a recorded session's contact frames through its own router or another "
              "and writes the semantic events and device frames as JSON Lines.");
}

void ReplayCommand::configure(QCommandLineParser &parser)
{
    parser.addPositionalArgument(QStringLiteral("session"), tr("The session database."),
                                 tr("SESSION"));
    parser.addOption({QStringLiteral("router"),
                      tr("Router preset or file (default: the router the session recorded)."),
                      tr("PRESET|FILE")});
    addRoutingOptions(parser);
    parser.addOption({QStringLiteral("metrics"),
                      tr("Where to write counts and each message's begins and active time "
                         "(JSON), or - for standard output."),
                      tr("FILE|-")});
}

int ReplayCommand::execute(const QCommandLineParser &parser)
{
    const QStringList positional = parser.positionalArguments();
    if (positional.isEmpty())
        return usageError(tr("a session file is required"));
    if (positional.size() > 1)
        return usageError(tr("unexpected argument '%1'").arg(positional.at(1)));
    const QString eventsPath = parser.value(QStringLiteral("events"));
    const QString framesPath = parser.value(QStringLiteral("device-frames"));
    const QString metricsPath = parser.value(QStringLiteral("metrics"));
    if (!checkSingleStdout({eventsPath, framesPath, metricsPath}))
        return ExitUsage;

    QString message;
    std::unique_ptr<SessionReader> session = SessionReader::open(positional.first(), &message);
    if (!session)
        return inputError(message);
    session->setRowErrorHandler([this](const QString &line) { report(line); });
    keepFromOutputs(session->path(), Kept::Input);
    const QStringList overrides = parser.values(QStringLiteral("set"));
    // The person of the session, unless the command line asks what another would have felt.
    RouterContext context = session->info().routerContext;
    if (!routerContextOption(parser, &context))
        return ExitUsage;
    LoadError error;
    std::unique_ptr<Router> router;
    if (parser.isSet(QStringLiteral("router"))) {
        router = loadRouter(parser.value(QStringLiteral("router")), overrides, &error, context);
    } else {
        RouterGraph graph;
        if (session->routerGraph(&graph, &error))
            router = compileWithOverrides(graph, overrides, &error, context);
    }
    if (!router)
        return inputError(error.toString());
    reportWarnings(router->graph());
    keepFromOutputs(parser.value(QStringLiteral("router")), Kept::Input);

    QIODevice *events = eventsPath.isEmpty() ? nullptr : openOutput(eventsPath);
    QIODevice *deviceFrames = framesPath.isEmpty() ? nullptr : openOutput(framesPath);
    QIODevice *metricsOut = metricsPath.isEmpty() ? nullptr : openOutput(metricsPath);
    if ((!eventsPath.isEmpty() && !events) || (!framesPath.isEmpty() && !deviceFrames) ||
        (!metricsPath.isEmpty() && !metricsOut))
        return ExitInvalidInput;

    Pipeline pipeline(std::move(router));
    MessageTally tally(pipeline.router().nodeIds());
    StreamSink streams(pipeline.router(), events, deviceFrames);
    SinkList sink{&streams, &tally};
    qint64 frames = 0;
    const bool read = session->readContactFrames(
        [&](const ContactFrame &frame, double) {
            pipeline.process(frame, sink);
            ++frames;
            return true;
        },
        &message);
    if (!read)
        return inputError(message);
    pipeline.flush(sink);
    reportSkippedRows(*session);
    reportDroppedEvents(pipeline);

    if (metricsOut) {
        QJsonObject metrics = tally.metrics(pipeline.now());
        metrics.insert(QStringLiteral("session"), session->path());
        metrics.insert(QStringLiteral("router"), parser.isSet(QStringLiteral("router"))
                                                     ? parser.value(QStringLiteral("router"))
                                                     : session->info().routerSource);
        metrics.insert(QStringLiteral("frames"), double(frames));
        metrics.insert(QStringLiteral("t_start"), session->startTime());
        metrics.insert(QStringLiteral("t_end"), session->endTime());
        metricsOut->write(QJsonDocument(metrics).toJson(QJsonDocument::Indented));
    }
    return ExitOk;
}

} // namespace semhap
