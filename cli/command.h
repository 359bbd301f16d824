// SPDX-License-Identifier: MIT
#pragma once

#include "sceneoptions.h"

#include "contactframeparser.h"
#include "devicemodel.h"
#include "outputfile.h"
#include "patternrender.h"
#include "routercontext.h"
#include "shard.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QIODevice>
#include <QString>
#include <QStringList>
#include <QTextStream>

#include <memory>
#include <vector>

namespace semhap {

class FoxgloveServer;

struct PersonParameters;
struct RunOptions;

class Pipeline;
class Router;
class RouterGraph;
class SessionReader;
class SessionWriter;

/** Exit codes shared by every command (spec section 5). */
enum ExitCode
{
    ExitOk = 0,
    ExitInvalidInput = 1,
    ExitUsage = 2
};

/** The standard streams a command uses; tests pass buffers, main passes the real ones. */
struct CommandIo
{
    QIODevice *in = nullptr;  ///< what `-` reads
    QIODevice *out = nullptr; ///< what `-` writes, and help text
    QIODevice *err = nullptr; ///< error messages, one line each
    /** `out` when it is the process's standard output: flushed live, its failures seen. */
    OutputFile *outFile = nullptr;
};

/**
 * One `semhap` subcommand: parses its own options and returns an exit code, so tests run
 * commands in-process with buffers for the standard streams.
 */
class Command
{
    Q_DECLARE_TR_FUNCTIONS(semhap::Command)

public:
    explicit Command(const CommandIo &io);
    virtual ~Command();

    virtual QString name() const = 0;
    virtual QString summary() const = 0;
    /** Runs with the arguments after the command name. */
    int run(const QStringList &arguments);

protected:
    /** Declares the options and positional arguments on the parser. */
    virtual void configure(QCommandLineParser &parser) = 0;
    /** Runs once the arguments parsed; report usage errors with usageError(). */
    virtual int execute(const QCommandLineParser &parser) = 0;
    /** After a successful execute(), once every output is whole in its place. */
    virtual void committed() {}

    int usageError(const QString &message);
    /** Prints `WHERE: reason` on the error stream; returns ExitInvalidInput. */
    int inputError(const QString &line);
    /** Prints a line on the error stream without failing (rejected stream lines, counts). */
    void report(const QString &line);

    /** Parses a number option; false (after a usage message) when it is not one. */
    bool numberOption(const QCommandLineParser &parser, const QString &option, double *value);
    /** Reads `--shard I/N|auto` into `shard` when given; false after a usage error. */
    bool shardOption(const QCommandLineParser &parser, Shard *shard);

    /**
     * Opens FILE, or standard output for `-`, for writing (OutputFile: a regular file
     * appears, whole, only when the command succeeds). Refuses a file that is one of the
     * inputs or the session given so far, or another output. Null after printing why.
     */
    QIODevice *openOutput(const QString &path);
    /** Opens `name` in the folder `dir` (made when missing) as openOutput() does. */
    QIODevice *openOutputIn(const QString &dir, const QString &name);
    /**
     * Opens a stream, FILE (a regular file or a pipe) or standard input for `-`, for
     * reading, and keeps it from being an output. Null after printing why.
     */
    QIODevice *openInput(const QString &path);
    /**
     * Whether `path` may be written: not an input or session kept so far, nor another
     * output. False after printing why. openOutput checks this; a command that writes a
     * file of its own kind (emulate's live log) asks it first.
     */
    bool checkOutputPath(const QString &path);
    /** What a file kept from the outputs is to the command. */
    enum class Kept
    {
        Input,  ///< read: kept when it exists (a preset's name is no file)
        Session ///< recorded into: kept even before it exists
    };
    /** Notes a file the command reads or records into, so that no output replaces it. */
    void keepFromOutputs(const QString &path, Kept role);
    /** The first output whose writes failed so far, for a long loop to stop on; or null. */
    const OutputFile *failedOutput() const;
    /** Hands what every output (m_out too) holds to the system, so pipes see it live. */
    void flushOutputs();
    /**
     * Declares --events, --device-frames, --set and --reaction-time: the outputs, overrides
     * and router context of every command that routes frames (route, replay, listen).
     */
    void addRoutingOptions(QCommandLineParser &parser);
    /**
     * Reads --reaction-time, when it is set, into `context`; false after a usage message
     * when it is not a number of seconds within SessionInfo::MaxReactionTime.
     */
    bool routerContextOption(const QCommandLineParser &parser, RouterContext *context);
    /** What the routing options chose: the router's name or file, its overrides, its context. */
    struct RoutingChoice
    {
        QString router;
        QStringList overrides;
        RouterContext context;
    };
    /**
     * The router the routing options name: --router (`fallback` when it is not given),
     * --set and --reaction-time; its warnings reported, its file kept from the outputs.
     * Null after the usage or input message, with the exit code in `exit`.
     */
    std::unique_ptr<Router> routerFromOptions(const QCommandLineParser &parser,
                                              const QString &fallback, RoutingChoice *choice,
                                              int *exit);
    /**
     * Reads --duration (more than 0, at most MaxDuration s), --cubes (a whole number >= 0;
     * absent: -1, the scene's own), --gripper and --horizon into `options`: what run and
     * compare share. False after a usage message.
     */
    bool simulationOptions(const QCommandLineParser &parser, RunOptions *options);
    /**
     * Applies each --person NAME=VALUE to `person`; false after a usage error naming the
     * parameter or its range.
     */
    bool personOptions(const QCommandLineParser &parser, PersonParameters *person);
    /** Adds --cubes, --gripper and --horizon, which simulationOptions() reads. */
    static void addSceneOptions(QCommandLineParser &parser);
    /** The longest simulated run (s): about eleven days. */
    static constexpr double MaxDuration = 1e6;
    /** Declares --foxglove-server [ADDRESS:]PORT (run, listen). */
    void addFoxgloveServerOption(QCommandLineParser &parser);
    /**
     * The Foxglove server --foxglove-server asks for, listening (on 127.0.0.1 when no
     * address is given), its URL reported; null when the option is not set. Null after a
     * usage or input message, with the exit code in `exit`.
     */
    std::unique_ptr<FoxgloveServer> foxgloveServerFromOptions(const QCommandLineParser &parser,
                                                              int *exit);
    /** Closes `server` (when there is one), its viewers served, and reports what it sent. */
    void finishFoxgloveServer(FoxgloveServer *server);
    /** Declares --max-gap: how far a frame's `t` may jump (route, listen). */
    void addMaxGapOption(QCommandLineParser &parser);
    /** Reads --max-gap into `parser`'s rule; false after a usage message. */
    bool maxGapOption(const QCommandLineParser &options, ContactFrameParser *parser);
    /** Declares PATTERN|FILE, --intensity and --release-at: what render and play share. */
    void addPatternArguments(QCommandLineParser &parser);
    /**
     * Reads the one pattern argument, --intensity and --release-at into `pattern` and
     * `options`; false after a usage message.
     */
    bool patternArguments(const QCommandLineParser &parser, QString *pattern,
                          RenderOptions *options);
    /**
     * Loads a pattern (a library name or a file) and its built-in model; false after an
     * error line (exit code 1).
     */
    bool loadNamedPattern(const QString &pattern, PatternPtr *loaded, DeviceModelPtr *model);
    /**
     * Loads a pattern and renders it on its built-in model (at the model's rate when
     * `options.rate` is 0); false after an error line (exit code 1).
     */
    bool renderNamedPattern(const QString &pattern, RenderOptions options,
                            RenderedPattern *rendered, DeviceModelPtr *model);

    /** Reports what loading `graph` found old but readable (a deprecated spelling). */
    void reportWarnings(const RouterGraph &graph);
    /** Says how many events the pipeline dropped, when it dropped any. */
    void reportDroppedEvents(const Pipeline &pipeline);
    /** Closes a recording, reporting dropped values and errors; false after an error line. */
    bool finishSession(SessionWriter &session);
    /** Says how many rows a session read skipped (each was reported as it came). */
    void reportSkippedRows(const SessionReader &session);

    /** Usage check of the spec: at most one of the outputs may be `-`. */
    bool checkSingleStdout(const QStringList &outputs);

    CommandIo m_io;
    QTextStream m_out;

private:
    /** Hands each output its data (renames the temporaries); false after printing why. */
    bool commitOutputs();

    struct KeptFile
    {
        QString path;
        Kept role;
    };
    std::vector<KeptFile> m_kept;
    std::vector<std::unique_ptr<QIODevice>> m_inputs;
    std::vector<std::unique_ptr<OutputFile>> m_outputs;
};

} // namespace semhap
