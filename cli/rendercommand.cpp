// SPDX-License-Identifier: MIT
#include "rendercommand.h"

#include "jsonlineswriter.h"
#include "patternlibrary.h"
#include "patternrender.h"

namespace semhap {

namespace {

// Above this the CSV would be gigabytes: almost certainly a typo in --duration or --rate.
constexpr double MaxSamples = 1e8;

} // namespace

QString RenderCommand::summary() const
{
    return tr("Renders a pattern from a begin at t = 0 (and an end at --release-at) to CSV: a "
              "header t,<model channels>, then one row per sample at t = k / rate.");
}

void RenderCommand::configure(QCommandLineParser &parser)
{
    parser.addPositionalArgument(QStringLiteral("pattern"),
                                 tr("Built-in pattern name or pattern file."), tr("PATTERN|FILE"));
    parser.addOption({QStringLiteral("intensity"), tr("Intensity 0..1 (default 1)."), tr("X")});
    parser.addOption(
        {QStringLiteral("release-at"), tr("Time of the end (release), in seconds."), tr("S")});
    parser.addOption({QStringLiteral("duration"), tr("Length to render, in seconds."), tr("S")});
    parser.addOption({QStringLiteral("rate"), tr("Samples per second."), tr("HZ")});
    parser.addOption({QStringLiteral("out"),
                      tr("Where to write the CSV, or - for standard output (default)."),
                      tr("FILE|-")});
}

int RenderCommand::execute(const QCommandLineParser &parser)
{
    const QStringList positional = parser.positionalArguments();
    if (positional.size() != 1)
        return usageError(positional.isEmpty()
                              ? tr("a pattern name or file is required")
                              : tr("exactly one pattern, got %1").arg(positional.size()));
    for (const QString &required : {QStringLiteral("duration"), QStringLiteral("rate")}) {
        if (!parser.isSet(required))
            return usageError(tr("--%1 is required").arg(required));
    }
    RenderOptions options;
    if (!numberOption(parser, QStringLiteral("intensity"), &options.intensity) ||
        !numberOption(parser, QStringLiteral("release-at"), &options.releaseAt) ||
        !numberOption(parser, QStringLiteral("duration"), &options.duration) ||
        !numberOption(parser, QStringLiteral("rate"), &options.rate))
        return ExitUsage;
    if (options.intensity < 0 || options.intensity > 1)
        return usageError(tr("--intensity must be within [0, 1]"));
    if (options.duration < 0)
        return usageError(tr("--duration must not be negative"));
    if (options.rate <= 0)
        return usageError(tr("--rate must be positive"));
    if (options.releaseAt < 0)
        return usageError(tr("--release-at must not be negative"));
    if (options.duration * options.rate > MaxSamples)
        return usageError(tr("--duration × --rate is more than %1 samples").arg(MaxSamples));

    LoadError error;
    PatternPtr pattern = PatternLibrary::load(positional.first(), &error);
    if (!pattern)
        return inputError(error.toString());
    DeviceModelPtr model = DeviceModelLibrary::builtin(pattern->model());
    if (!model)
        return inputError(
            LoadError::at(positional.first(), QStringLiteral("/model"),
                          tr("unknown device model '%1' (built-in: %2)")
                              .arg(pattern->model(),
                                   DeviceModelLibrary::builtinNames().join(QStringLiteral(", "))))
                .toString());
    RenderedPattern rendered;
    QString reason;
    if (!renderPattern(pattern, *model, options, &rendered, &reason))
        return inputError(positional.first() + QStringLiteral(": ") + reason);

    QIODevice *out = openOutput(parser.value(QStringLiteral("out")).isEmpty()
                                    ? QStringLiteral("-")
                                    : parser.value(QStringLiteral("out")));
    if (!out)
        return ExitInvalidInput;
    QByteArray line = "t";
    for (const QString &channel : rendered.channels)
        line += ',' + channel.toUtf8();
    line += '\n';
    out->write(line);
    for (size_t k = 0; k < rendered.t.size(); ++k) {
        line.clear();
        JsonLinesWriter::appendNumber(line, rendered.t[k]);
        for (const std::vector<double> &column : rendered.values) {
            line += ',';
            JsonLinesWriter::appendNumber(line, column[k]);
        }
        line += '\n';
        out->write(line);
    }
    return ExitOk;
}

} // namespace semhap
