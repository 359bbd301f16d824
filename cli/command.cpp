// SPDX-License-Identifier: MIT
#include "command.h"

#include "foxgloveserver.h"

#include "gripperlibrary.h"

#include "inputfile.h"
#include "patternlibrary.h"
#include "pipeline.h"
#include "sessioninfo.h"
#include "sessionreader.h"
#include "sessionwriter.h"
#include "simrun.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QHostAddress>
#include <QProcessEnvironment>

#include <algorithm>
#include <climits>
#include <cmath>

namespace semhap {

Command::Command(const CommandIo &io) : m_io(io), m_out(io.out) {}

Command::~Command()
{
    m_out.flush();
}

int Command::run(const QStringList &arguments)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(summary());
    const QCommandLineOption help({QStringLiteral("h"), QStringLiteral("help")},
                                  tr("Show this help."));
    parser.addOption(help);
    configure(parser);

    if (!parser.parse(QStringList{QStringLiteral("semhap")} + arguments))
        return usageError(parser.errorText());
    if (parser.isSet(help)) {
        // Qt names the program after argv[0]; users call it `semhap COMMAND`.
        QString text = parser.helpText();
        const int programEnd = int(text.indexOf(QLatin1Char(' '), 7));
        if (text.startsWith(QLatin1String("Usage: ")) && programEnd > 0)
            text.replace(7, programEnd - 7, QStringLiteral("semhap ") + name());
        m_out << text;
        m_out.flush();
        return ExitOk;
    }
    int code = execute(parser);
    m_out.flush();
    // A failed command replaces nothing: its temporaries go with it.
    if (code == ExitOk && !commitOutputs())
        code = ExitInvalidInput;
    else if (code == ExitOk)
        committed();
    m_outputs.clear();
    return code;
}

bool Command::commitOutputs()
{
    bool ok = true;
    for (const std::unique_ptr<OutputFile> &output : m_outputs) {
        LoadError error;
        if (!output->commit(&error)) {
            report(error.toString());
            ok = false;
        }
    }
    return ok;
}

int Command::usageError(const QString &message)
{
    report(QStringLiteral("semhap %1: %2").arg(name(), message));
    report(tr("Try 'semhap %1 --help'.").arg(name()));
    return ExitUsage;
}

int Command::inputError(const QString &line)
{
    report(line);
    return ExitInvalidInput;
}

void Command::report(const QString &line)
{
    m_io.err->write(line.toUtf8() + '\n');
}

bool Command::numberOption(const QCommandLineParser &parser, const QString &option, double *value)
{
    if (!parser.isSet(option))
        return true;
    bool ok = false;
    const double parsed = parser.value(option).toDouble(&ok);
    if (!ok || !std::isfinite(parsed)) {
        usageError(tr("--%1 expects a number, got '%2'").arg(option, parser.value(option)));
        return false;
    }
    *value = parsed;
    return true;
}

bool Command::shardOption(const QCommandLineParser &parser, Shard *shard)
{
    if (!parser.isSet(QStringLiteral("shard")))
        return true;
    QString error;
    const std::optional<Shard> given = Shard::parse(
        parser.value(QStringLiteral("shard")), QProcessEnvironment::systemEnvironment(), &error);
    if (!given) {
        usageError(error);
        return false;
    }
    *shard = *given;
    return true;
}

bool Command::checkOutputPath(const QString &path)
{
    const auto refuse = [&](const QString &role, const QString &other) {
        inputError(tr("%1: cannot write: it is the same file as the %2 %3; nothing was written")
                       .arg(path, role, other));
        return false;
    };
    for (const KeptFile &kept : m_kept) {
        if (OutputFile::sameFile(path, kept.path))
            return refuse(kept.role == Kept::Session ? tr("session") : tr("input"), kept.path);
    }
    for (const std::unique_ptr<OutputFile> &output : m_outputs) {
        if (OutputFile::sameFile(path, output->path()))
            return refuse(tr("output"), output->path());
    }
    return true;
}

QIODevice *Command::openOutput(const QString &path)
{
    if (path == QLatin1String("-"))
        return m_io.out;
    if (!checkOutputPath(path))
        return nullptr;
    auto file = std::make_unique<OutputFile>(path);
    LoadError error;
    if (!file->open(&error)) {
        inputError(error.toString());
        return nullptr;
    }
    m_outputs.push_back(std::move(file));
    return m_outputs.back()->device();
}

const OutputFile *Command::failedOutput() const
{
    for (const std::unique_ptr<OutputFile> &output : m_outputs) {
        if (output->failed())
            return output.get();
    }
    return m_io.outFile && m_io.outFile->failed() ? m_io.outFile : nullptr;
}

void Command::flushOutputs()
{
    m_out.flush();
    for (const std::unique_ptr<OutputFile> &output : m_outputs)
        output->flush();
    if (m_io.outFile)
        m_io.outFile->flush();
}

QIODevice *Command::openOutputIn(const QString &dir, const QString &name)
{
    if (!QDir().mkpath(dir)) {
        inputError(tr("%1: cannot create the folder").arg(dir));
        return nullptr;
    }
    return openOutput(QDir(dir).filePath(name));
}

QIODevice *Command::openInput(const QString &path)
{
    if (path == QLatin1String("-"))
        return m_io.in;
    QString reason;
    if (!InputFile::checkStream(path, &reason)) {
        inputError(tr("%1: cannot read: %2").arg(path, reason));
        return nullptr;
    }
    auto file = std::make_unique<QFile>(path);
    if (!file->open(QIODevice::ReadOnly)) {
        inputError(tr("%1: cannot read: %2").arg(path, file->errorString()));
        return nullptr;
    }
    keepFromOutputs(path, Kept::Input);
    m_inputs.push_back(std::move(file));
    return m_inputs.back().get();
}

void Command::keepFromOutputs(const QString &path, Kept role)
{
    if (path.isEmpty() || path == QLatin1String("-"))
        return;
    if (role == Kept::Session || QFileInfo::exists(path))
        m_kept.push_back({path, role});
}

void Command::addRoutingOptions(QCommandLineParser &parser)
{
    parser.addOption({QStringLiteral("events"),
                      tr("Where to write the semantic events, or - for standard output."),
                      tr("FILE|-")});
    parser.addOption({QStringLiteral("device-frames"),
                      tr("Where to write the device frames, or - for standard output."),
                      tr("FILE|-")});
    parser.addOption({QStringLiteral("set"),
                      tr("Override a node parameter, e.g. right.force.break=90 (repeatable)."),
                      tr("NODE.PARAM=VALUE")});
    parser.addOption({QStringLiteral("reaction-time"),
                      tr("Reaction time in seconds of the person the router warns: part of a "
                         "predict node's horizon (default 0.25)."),
                      tr("S")});
}

bool Command::simulationOptions(const QCommandLineParser &parser, RunOptions *options)
{
    double count = -1;
    double *duration = &options->duration;
    SceneOptions *scene = &options->sceneOptions;
    if (!numberOption(parser, QStringLiteral("duration"), duration) ||
        !numberOption(parser, QStringLiteral("cubes"), &count) ||
        !numberOption(parser, QStringLiteral("horizon"), &options->horizon))
        return false;
    if (!(options->horizon > 0 && options->horizon <= RunOptions::MaxHorizon)) {
        usageError(tr("--horizon must be above 0 and at most %1 s").arg(RunOptions::MaxHorizon));
        return false;
    }
    if (!(*duration > 0 && *duration <= MaxDuration)) {
        usageError(tr("--duration must be between 0 and %1 s").arg(MaxDuration, 0, 'f', 0));
        return false;
    }
    if (parser.isSet(QStringLiteral("cubes")) &&
        (count < 0 || count != std::floor(count) || count > RunOptions::MaxCubes)) {
        usageError(tr("--cubes must be a whole number from 0 to %1").arg(RunOptions::MaxCubes));
        return false;
    }
    scene->cubes = int(count);
    scene->gripper = parser.value(QStringLiteral("gripper"));
    return personOptions(parser, &options->person);
}

bool Command::personOptions(const QCommandLineParser &parser, PersonParameters *person)
{
    for (const QString &assignment : parser.values(QStringLiteral("person"))) {
        QString reason;
        if (!person->set(assignment, &reason)) {
            usageError(QStringLiteral("--person ") + reason);
            return false;
        }
    }
    return true;
}

void Command::addSceneOptions(QCommandLineParser &parser)
{
    parser.addOption(
        {QStringLiteral("cubes"), tr("Cubes in play (default: the scene's)."), tr("N")});
    parser.addOption({QStringLiteral("gripper"),
                      tr("A gripper adapter (docs/grippers.md) whose model replaces the "
                         "scene's grippers: %1, or a file.")
                          .arg(GripperLibrary::names().join(QStringLiteral(", "))),
                      tr("NAME|FILE")});
    parser.addOption({QStringLiteral("horizon"),
                      tr("How long before a failure a warning's onset may lie and still count "
                         "as its warning, in seconds (default 3; docs/metrics.md)."),
                      tr("S")});
    parser.addOption({QStringLiteral("person"),
                      tr("Set a parameter of the perceiving operator's person, within its "
                         "range (repeatable; docs/operator.md)."),
                      tr("NAME=VALUE")});
}

void Command::reportWarnings(const RouterGraph &graph)
{
    for (const LoadError &warning : graph.warnings)
        report(warning.toString());
}

void Command::reportDroppedEvents(const Pipeline &pipeline)
{
    if (pipeline.droppedEvents() > 0)
        report(tr("%1 event(s) dropped: a tick made more than %2 (too many detectors on one "
                  "gripper)")
                   .arg(pipeline.droppedEvents())
                   .arg(EventBuffer::Capacity));
}

void Command::addMaxGapOption(QCommandLineParser &parser)
{
    parser.addOption({QStringLiteral("max-gap"),
                      tr("Refuse a frame whose t jumps more than this many seconds past the "
                         "stream's latest (default 10)."),
                      tr("S")});
}

bool Command::maxGapOption(const QCommandLineParser &options, ContactFrameParser *parser)
{
    const QString option = QStringLiteral("max-gap");
    double seconds = parser->maxGap();
    if (!numberOption(options, option, &seconds))
        return false;
    if (!(seconds > 0.0 && seconds <= ContactFrameParser::MaxTime)) {
        usageError(tr("--%1 must be more than 0 s and at most %2 s")
                       .arg(option)
                       .arg(ContactFrameParser::MaxTime, 0, 'g'));
        return false;
    }
    parser->setMaxGap(seconds);
    return true;
}

bool Command::routerContextOption(const QCommandLineParser &parser, RouterContext *context)
{
    const QString option = QStringLiteral("reaction-time");
    double seconds = context->reactionTime;
    if (!numberOption(parser, option, &seconds))
        return false;
    if (!(seconds >= 0.0 && seconds <= SessionInfo::MaxReactionTime)) {
        usageError(
            tr("--%1 must be between 0 and %2 s").arg(option).arg(SessionInfo::MaxReactionTime));
        return false;
    }
    context->reactionTime = seconds;
    return true;
}

void Command::addFoxgloveServerOption(QCommandLineParser &parser)
{
    parser.addOption({QStringLiteral("foxglove-server"),
                      tr("Serve the streams live to Foxglove (its WebSocket protocol) on PORT, "
                         "at 127.0.0.1 unless an ADDRESS is given; a run goes in real time."),
                      tr("[ADDRESS:]PORT")});
}

std::unique_ptr<FoxgloveServer>
Command::foxgloveServerFromOptions(const QCommandLineParser &parser, int *exit)
{
    const QString name = QStringLiteral("foxglove-server");
    if (!parser.isSet(name))
        return nullptr;
    const QString value = parser.value(name);
    // The port is after the last colon; an IPv6 address is in brackets.
    const qsizetype colon = value.lastIndexOf(QLatin1Char(':'));
    QString host = colon < 0 ? QStringLiteral("127.0.0.1") : value.left(colon);
    if (host.startsWith(QLatin1Char('[')) && host.endsWith(QLatin1Char(']')))
        host = host.mid(1, host.size() - 2);
    bool ok = false;
    const uint port = value.mid(colon + 1).toUInt(&ok);
    const QHostAddress address(host);
    if (!ok || port > 65535 || address.isNull()) {
        *exit = usageError(tr("--foxglove-server: expected [ADDRESS:]PORT, got '%1'").arg(value));
        return nullptr;
    }
    auto server = std::make_unique<FoxgloveServer>(QStringLiteral("semhap"));
    QString error;
    if (!server->listen(address, quint16(port), &error)) {
        *exit = inputError(tr("--foxglove-server %1: %2").arg(value, error));
        return nullptr;
    }
    report(tr("serving Foxglove on %1").arg(server->url()));
    return server;
}

void Command::finishFoxgloveServer(FoxgloveServer *server)
{
    if (!server)
        return;
    server->close();
    const FoxgloveServer::Stats stats = server->stats();
    report(tr("foxglove: %1 message(s) sent to %2 viewer(s), %3 dropped")
               .arg(stats.sent)
               .arg(stats.connections)
               .arg(stats.dropped));
}

std::unique_ptr<Router> Command::routerFromOptions(const QCommandLineParser &parser,
                                                   const QString &fallback, RoutingChoice *choice,
                                                   int *exit)
{
    choice->router =
        parser.isSet(QStringLiteral("router")) ? parser.value(QStringLiteral("router")) : fallback;
    choice->overrides = parser.values(QStringLiteral("set"));
    if (!routerContextOption(parser, &choice->context)) {
        *exit = ExitUsage;
        return nullptr;
    }
    LoadError error;
    std::unique_ptr<Router> router =
        loadRouter(choice->router, choice->overrides, &error, choice->context);
    if (!router) {
        *exit = inputError(error.toString());
        return nullptr;
    }
    reportWarnings(router->graph());
    keepFromOutputs(choice->router, Kept::Input);
    return router;
}

void Command::addPatternArguments(QCommandLineParser &parser)
{
    parser.addPositionalArgument(QStringLiteral("pattern"),
                                 tr("Built-in pattern name or pattern file."), tr("PATTERN|FILE"));
    parser.addOption({QStringLiteral("intensity"), tr("Intensity 0..1 (default 1)."), tr("X")});
    parser.addOption(
        {QStringLiteral("release-at"), tr("Time of the end (release), in seconds."), tr("S")});
}

bool Command::patternArguments(const QCommandLineParser &parser, QString *pattern,
                               RenderOptions *options)
{
    const QStringList positional = parser.positionalArguments();
    if (positional.size() != 1) {
        usageError(positional.isEmpty()
                       ? tr("a pattern name or file is required")
                       : tr("exactly one pattern, got %1").arg(positional.size()));
        return false;
    }
    *pattern = positional.first();
    if (!numberOption(parser, QStringLiteral("intensity"), &options->intensity) ||
        !numberOption(parser, QStringLiteral("release-at"), &options->releaseAt))
        return false;
    if (options->intensity < 0 || options->intensity > 1) {
        usageError(tr("--intensity must be within [0, 1]"));
        return false;
    }
    if (options->releaseAt < 0) {
        usageError(tr("--release-at must not be negative"));
        return false;
    }
    return true;
}

bool Command::loadNamedPattern(const QString &pattern, PatternPtr *loaded,
                               DeviceModelPtr *model)
{
    LoadError error;
    *loaded = PatternLibrary::load(pattern, &error);
    if (!*loaded) {
        inputError(error.toString());
        return false;
    }
    *model = DeviceModelLibrary::builtin((*loaded)->model());
    if (!*model) {
        inputError(LoadError::at(pattern, QStringLiteral("/model"),
                                 tr("unknown device model '%1' (built-in: %2)")
                                     .arg((*loaded)->model(),
                                          DeviceModelLibrary::builtinNames().join(
                                              QStringLiteral(", "))))
                       .toString());
        return false;
    }
    return true;
}

bool Command::renderNamedPattern(const QString &pattern, RenderOptions options,
                                 RenderedPattern *rendered, DeviceModelPtr *model)
{
    PatternPtr loaded;
    if (!loadNamedPattern(pattern, &loaded, model))
        return false;
    if (options.rate <= 0)
        options.rate = (*model)->rate();
    QString reason;
    if (!renderPattern(loaded, **model, options, rendered, &reason)) {
        inputError(pattern + QStringLiteral(": ") + reason);
        return false;
    }
    return true;
}

bool Command::checkSingleStdout(const QStringList &outputs)
{
    if (outputs.count(QStringLiteral("-")) <= 1)
        return true;
    usageError(tr("at most one output may be '-' (standard output)"));
    return false;
}

void Command::reportSkippedRows(const SessionReader &session)
{
    if (session.rejectedRows() > 0)
        report(tr("%1: %n row(s) skipped", nullptr,
                  int(std::min<qint64>(session.rejectedRows(), INT_MAX)))
                   .arg(session.path()));
}

bool Command::finishSession(SessionWriter &session)
{
    QString error;
    if (session.dropped() > 0)
        report(tr("%1: %n value(s) dropped: the disk fell behind", nullptr,
                  int(std::min<quint64>(session.dropped(), INT_MAX)))
                   .arg(session.path()));
    if (session.finish(&error))
        return true;
    inputError(error);
    return false;
}

} // namespace semhap
