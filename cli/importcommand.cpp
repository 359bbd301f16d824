// SPDX-License-Identifier: MIT
#include "importcommand.h"

#include "quitsignal.h"
#include "recordingimport.h"
#include "router.h"
#include "routergraph.h"

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
                         "(docs/ros.md), or semhap for a recording semhap exported."),
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
    RoutingChoice choice;
    int exit = ExitOk;
    std::unique_ptr<Router> router =
        routerFromOptions(parser, QStringLiteral("C3"), &choice, &exit);
    if (!router)
        return exit;
    keepFromOutputs(topicsPath, Kept::Input);
    keepFromOutputs(recordingPath, Kept::Input);
    keepFromOutputs(sessionPath, Kept::Session);

    SessionInfo info;
    info.routerSource = choice.router;
    info.overrides = choice.overrides;
    info.routerContext = choice.context;
    info.notes = parser.value(QStringLiteral("notes"));
    RecordingImport::Result result;
    if (!RecordingImport::run(
            recordingPath, topicsPath, std::move(router), info, sessionPath,
            [](double) { return !QuitSignal::requested(); }, &result))
        return inputError(result.error);
    if (result.cancelled)
        report(tr("%1: interrupted; the session holds what was imported").arg(recordingPath));
    report(tr("%1: %2 frame(s) from %3 s (the recording's time) into %4")
               .arg(recordingPath)
               .arg(result.frames)
               .arg(result.startTime, 0, 'f', 3)
               .arg(sessionPath));
    return ExitOk;
}

} // namespace semhap
