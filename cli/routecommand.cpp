// SPDX-License-Identifier: MIT
#include "routecommand.h"

#include "contactframereader.h"
#include "devicebindings.h"
#include "devicemanager.h"
#include "deviceoutputsink.h"
#include "emergencystop.h"
#include "pipeline.h"
#include "quitsignal.h"
#include "recordingreader.h"
#include "routergraph.h"
#include "sinklist.h"
#include "streamsink.h"

#include <chrono>
#include <thread>

namespace semhap {

QString RouteCommand::summary() const
{
    return tr("Runs contact frames through detectors, router and player on a virtual clock "
              "and writes the semantic events and device frames as JSON Lines.");
}

void RouteCommand::configure(QCommandLineParser &parser)
{
    parser.addOption({QStringLiteral("router"),
                      tr("Router preset (%1) or router file.")
                          .arg(RouterPresets::names().join(QStringLiteral(", "))),
                      tr("PRESET|FILE")});
    parser.addOption({QStringLiteral("frames"),
                      tr("Contact frames to read (JSON Lines), - for standard input, or a "
                         "robot's recording (rosbag2 in MCAP) with --topics."),
                      tr("FILE|-|REC.mcap")});
    parser.addOption({QStringLiteral("topics"),
                      tr("With an MCAP recording: the semhap.topics/1 map of its topics to "
                         "contact frames (docs/ros.md)."),
                      tr("MAP.json")});
    addRoutingOptions(parser);
    addMaxGapOption(parser);
    parser.addOption({QStringLiteral("bind"),
                      tr("Send a device's output to a transport, e.g. "
                         "right.vibro=serial:/dev/ttyACM0 (repeatable). With --bind the run "
                         "is paced in real time."),
                      tr("NAME=URI")});
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

    RoutingChoice choice;
    int exit = ExitOk;
    std::unique_ptr<Router> router = routerFromOptions(parser, QString(), &choice, &exit);
    if (!router)
        return exit;
    LoadError error;

    const QString framesPath = parser.value(QStringLiteral("frames"));
    const QString topicsPath = parser.value(QStringLiteral("topics"));
    const bool recording = framesPath.endsWith(QLatin1String(".mcap"), Qt::CaseInsensitive);
    if (recording && topicsPath.isEmpty())
        return usageError(
            tr("--frames %1: a recording needs its topic map: --topics MAP.json").arg(framesPath));
    if (!recording && !topicsPath.isEmpty())
        return usageError(tr("--topics: only with a recording (--frames FILE.mcap)"));
    // A recording is checked whole (records, CRCs, topics, fields) before any output.
    std::unique_ptr<RecordingReader> recordingReader;
    QIODevice *frames = nullptr;
    if (recording) {
        TopicMap map;
        if (!TopicMap::load(topicsPath, &map, &error))
            return inputError(error.toString());
        keepFromOutputs(topicsPath, Kept::Input);
        keepFromOutputs(framesPath, Kept::Input);
        recordingReader = std::make_unique<RecordingReader>(framesPath, map, topicsPath);
        if (!recordingReader->open())
            return inputError(recordingReader->error());
    } else {
        frames = openInput(framesPath);
        if (!frames)
            return ExitInvalidInput;
    }
    QIODevice *events = eventsPath.isEmpty() ? nullptr : openOutput(eventsPath);
    QIODevice *deviceFrames = framesOutPath.isEmpty() ? nullptr : openOutput(framesOutPath);
    if ((!eventsPath.isEmpty() && !events) || (!framesOutPath.isEmpty() && !deviceFrames))
        return ExitInvalidInput;

    DeviceManager devices;
    QString message;
    bool usage = false;
    if (!bindDevices(parser.values(QStringLiteral("bind")), router->player(), devices, &message,
                     &usage))
        return usage ? usageError(message) : inputError(message);
    const bool realTime = !devices.boundNames().isEmpty();
    // A signal stops the bands at once and ends the loop, so the outputs are handed over
    // with what was routed (a stream from a pipe may never end by itself).
    EmergencyStop::installGraceful();
    if (realTime)
        devices.armAll(true);

    std::unique_ptr<ContactFrameReader> reader;
    if (!recording) {
        reader = std::make_unique<ContactFrameReader>(frames, framesPath);
        if (!maxGapOption(parser, &reader->parser()))
            return ExitUsage;
        reader->setErrorHandler([this](const LoadError &e) { report(e.toString()); });
    }
    const auto nextFrame = [&](ContactFrame *frame) {
        return recording ? recordingReader->next(frame) : reader->next(frame);
    };
    Pipeline pipeline(std::move(router));
    StreamSink streams(pipeline.router(), events, deviceFrames);
    DeviceOutputSink output(pipeline.router().player(), devices);
    SinkList sink{&output, &streams};
    using Clock = std::chrono::steady_clock;
    Clock::time_point start;
    double t0 = 0.0;
    bool first = true;
    ContactFrame frame;
    while (!QuitSignal::requested() && nextFrame(&frame)) {
        // Bound bands feel the session as it happened: wait for each frame's time.
        if (realTime) {
            if (first) {
                start = Clock::now();
                t0 = frame.t;
                first = false;
            }
            const Clock::time_point due = start + std::chrono::duration_cast<Clock::duration>(
                                                      std::chrono::duration<double>(frame.t - t0));
            while (!QuitSignal::requested() && Clock::now() < due)
                std::this_thread::sleep_until(
                    std::min(due, Clock::now() + std::chrono::milliseconds(50)));
        }
        pipeline.process(frame, sink);
    }
    pipeline.flush(sink);
    devices.stopAll();
    if (recordingReader && !recordingReader->error().isEmpty())
        return inputError(recordingReader->error()); // the file changed since it was checked
    reportDroppedEvents(pipeline);
    if (QuitSignal::requested())
        report(tr("%1: interrupted after t = %2 s; the outputs hold what was routed")
                   .arg(framesPath)
                   .arg(pipeline.now()));

    if (reader && reader->rejectedCount() > 0)
        report(tr("%1: %n line(s) rejected", nullptr, reader->rejectedCount()).arg(framesPath));
    return ExitOk;
}

} // namespace semhap
