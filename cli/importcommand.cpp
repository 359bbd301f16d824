// SPDX-License-Identifier: MIT
#include "importcommand.h"

#include "pipeline.h"
#include "quitsignal.h"
#include "recordingreader.h"
#include "sessionwriter.h"

namespace semhap {

QString ImportCommand::summary() const
{
    return tr("Makes a session of a robot's recording (rosbag2 in MCAP) through a topic map, "
              "routed as route routes it.");
}

void ImportCommand::configure(QCommandLineParser &parser)
{
    parser.addPositionalArgument(QStringLiteral("recording"), tr("The recording (REC.mcap)."));
    parser.addOption({QStringLiteral("topics"),
                      tr("The semhap.topics/1 map of the recording's topics to contact frames "
                         "(docs/ros.md)."),
                      tr("MAP.json")});
    parser.addOption({QStringLiteral("session"), tr("The new session database."), tr("OUT.db")});
    parser.addOption({QStringLiteral("router"),
                      tr("Router preset (%1) or router file (default C3).")
                          .arg(RouterPresets::names().join(QStringLiteral(", "))),
                      tr("PRESET|FILE")});
    parser.addOption({QStringLiteral("notes"), tr("Notes kept with the session."), tr("TEXT")});
    addRoutingOptions(parser);
}

int ImportCommand::execute(const QCommandLineParser &parser)
{
    const QStringList args = parser.positionalArguments();
    if (args.size() != 1)
        return usageError(args.isEmpty() ? tr("name the recording: semhap import REC.mcap "
                                              "--topics MAP.json --session OUT.db")
                                         : tr("unexpected argument '%1'").arg(args[1]));
    for (const QString &required : {QStringLiteral("topics"), QStringLiteral("session")}) {
        if (!parser.isSet(required))
            return usageError(tr("--%1 is required").arg(required));
    }
    if (parser.isSet(QStringLiteral("events")) || parser.isSet(QStringLiteral("device-frames")))
        return usageError(tr("import writes a session: its events and device frames are in it "
                             "(semhap export)"));
    const QString recordingPath = args[0];
    const QString topicsPath = parser.value(QStringLiteral("topics"));
    const QString sessionPath = parser.value(QStringLiteral("session"));
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
    keepFromOutputs(topicsPath, Kept::Input);
    keepFromOutputs(recordingPath, Kept::Input);
    keepFromOutputs(sessionPath, Kept::Session);

    // The recording is checked whole before the session is made.
    TopicMap map;
    if (!TopicMap::load(topicsPath, &map, &error))
        return inputError(error.toString());
    RecordingReader recording(recordingPath, map, topicsPath);
    if (!recording.open())
        return inputError(recording.error());

    SessionInfo info;
    info.source = QStringLiteral("import");
    info.routerSource = routerName;
    info.overrides = overrides;
    info.routerContext = context;
    info.notes = parser.value(QStringLiteral("notes"));
    info.extra.insert(QStringLiteral("recording"), recordingPath);
    info.extra.insert(QStringLiteral("topics"), topicsPath);
    SessionWriter::Options options;
    options.waitWhenFull = true; // a file keeps no clock: nothing may be dropped
    QString message;
    std::unique_ptr<SessionWriter> session =
        SessionWriter::create(sessionPath, info, *router, options, &message);
    if (!session)
        return inputError(message);
    session->setActorTable(&recording.actors());

    Pipeline pipeline(std::move(router));
    ContactFrame frame;
    long long frames = 0;
    while (!QuitSignal::requested() && recording.next(&frame)) {
        session->recordContactFrame(frame, qQNaN());
        pipeline.process(frame, *session);
        ++frames;
    }
    if (frames > 0)
        pipeline.flush(*session);
    reportDroppedEvents(pipeline);
    if (!finishSession(*session))
        return ExitInvalidInput;
    if (!recording.error().isEmpty())
        return inputError(recording.error()); // the file changed since it was checked
    if (QuitSignal::requested())
        report(tr("%1: interrupted after t = %2 s; the session holds what was imported")
                   .arg(recordingPath)
                   .arg(pipeline.now()));
    if (recording.skippedCount() > 0)
        report(tr("%1: %n message(s) without a header stamp skipped", nullptr,
                  int(recording.skippedCount()))
                   .arg(recordingPath));
    report(tr("%1: %2 frame(s) from %3 s (the recording's time) into %4")
               .arg(recordingPath)
               .arg(frames)
               .arg(recording.startTime(), 0, 'f', 3)
               .arg(sessionPath));
    return ExitOk;
}

} // namespace semhap
