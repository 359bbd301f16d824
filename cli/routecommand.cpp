// SPDX-License-Identifier: MIT
#include "routecommand.h"

#include "contactframereader.h"
#include "jsonlineswriter.h"
#include "pipeline.h"

namespace semhap {

namespace {

/** Writes what the pipeline produces as JSON Lines, each stream to its own device. */
class StreamSink : public PipelineSink
{
public:
    StreamSink(const Router &router, QIODevice *events, QIODevice *deviceFrames)
        : m_writeEvents(events), m_writeFrames(deviceFrames), m_events(events),
          m_deviceFrames(deviceFrames)
    {
        QStringList devices;
        for (int d = 0; d < router.player().deviceCount(); ++d)
            devices.append(router.player().deviceName(d));
        m_events.setNodeNames(router.nodeIds());
        m_deviceFrames.setDeviceNames(devices);
    }

    void onEvent(const SemanticEvent &event) override
    {
        if (m_writeEvents)
            m_events.write(event);
    }
    void onDeviceFrame(const DeviceFrame &frame) override
    {
        if (m_writeFrames)
            m_deviceFrames.write(frame);
    }

private:
    bool m_writeEvents;
    bool m_writeFrames;
    JsonLinesWriter m_events;
    JsonLinesWriter m_deviceFrames;
};

} // namespace

QString RouteCommand::summary() const
{
    return tr("Runs contact frames through detectors, router and player on a virtual clock "
              "and writes the semantic events and device frames as JSON Lines.");
}

void RouteCommand::configure(QCommandLineParser &parser)
{
    parser.addOption({QStringLiteral("router"),
                      tr("Router preset (none, visual, sensory, C1-C4) or router file."),
                      tr("PRESET|FILE")});
    parser.addOption({QStringLiteral("frames"),
                      tr("Contact frames to read (JSON Lines), or - for standard input."),
                      tr("FILE|-")});
    parser.addOption({QStringLiteral("events"),
                      tr("Where to write the semantic events, or - for standard output."),
                      tr("FILE|-")});
    parser.addOption({QStringLiteral("device-frames"),
                      tr("Where to write the device frames, or - for standard output."),
                      tr("FILE|-")});
    parser.addOption({QStringLiteral("set"),
                      tr("Override a node parameter, e.g. right.force.break=90 (repeatable)."),
                      tr("NODE.PARAM=VALUE")});
}

int RouteCommand::execute(const QCommandLineParser &parser)
{
    if (!parser.positionalArguments().isEmpty())
        return usageError(
            tr("unexpected argument '%1'").arg(parser.positionalArguments().first()));
    for (const QString &required : {QStringLiteral("router"), QStringLiteral("frames")}) {
        if (!parser.isSet(required))
            return usageError(tr("--%1 is required").arg(required));
    }
    const QString eventsPath = parser.value(QStringLiteral("events"));
    const QString framesOutPath = parser.value(QStringLiteral("device-frames"));
    if (!checkSingleStdout({eventsPath, framesOutPath}))
        return ExitUsage;

    LoadError error;
    std::unique_ptr<Router> router = loadRouter(parser.value(QStringLiteral("router")),
                                                parser.values(QStringLiteral("set")), &error);
    if (!router)
        return inputError(error.toString());

    const QString framesPath = parser.value(QStringLiteral("frames"));
    QIODevice *frames = openInput(framesPath);
    if (!frames)
        return ExitInvalidInput;
    QIODevice *events = eventsPath.isEmpty() ? nullptr : openOutput(eventsPath);
    QIODevice *deviceFrames = framesOutPath.isEmpty() ? nullptr : openOutput(framesOutPath);
    if ((!eventsPath.isEmpty() && !events) || (!framesOutPath.isEmpty() && !deviceFrames))
        return ExitInvalidInput;

    ContactFrameReader reader(frames, framesPath);
    reader.setErrorHandler([this](const LoadError &e) { report(e.toString()); });
    Pipeline pipeline(std::move(router));
    StreamSink sink(pipeline.router(), events, deviceFrames);
    ContactFrame frame;
    while (reader.next(&frame))
        pipeline.process(frame, sink);
    pipeline.flush(sink);

    if (reader.rejectedCount() > 0)
        report(tr("%1: %n line(s) rejected", nullptr, reader.rejectedCount()).arg(framesPath));
    return ExitOk;
}

} // namespace semhap
