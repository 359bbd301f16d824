// SPDX-License-Identifier: MIT
#include "rendercommand.h"

#include "jsonlineswriter.h"

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
    addPatternArguments(parser);
    parser.addOption({QStringLiteral("duration"), tr("Length to render, in seconds."), tr("S")});
    parser.addOption({QStringLiteral("rate"), tr("Samples per second."), tr("HZ")});
    parser.addOption({QStringLiteral("out"),
                      tr("Where to write the CSV, or - for standard output (default)."),
                      tr("FILE|-")});
}

int RenderCommand::execute(const QCommandLineParser &parser)
{
    QString pattern;
    RenderOptions options;
    if (!patternArguments(parser, &pattern, &options))
        return ExitUsage;
    for (const QString &required : {QStringLiteral("duration"), QStringLiteral("rate")}) {
        if (!parser.isSet(required))
            return usageError(tr("--%1 is required").arg(required));
    }
    if (!numberOption(parser, QStringLiteral("duration"), &options.duration) ||
        !numberOption(parser, QStringLiteral("rate"), &options.rate))
        return ExitUsage;
    if (options.duration < 0)
        return usageError(tr("--duration must not be negative"));
    if (options.rate <= 0)
        return usageError(tr("--rate must be positive"));
    if (options.duration * options.rate > MaxSamples)
        return usageError(tr("--duration × --rate is more than %1 samples").arg(MaxSamples));

    RenderedPattern rendered;
    DeviceModelPtr model;
    if (!renderNamedPattern(pattern, options, &rendered, &model))
        return ExitInvalidInput;
    keepFromOutputs(pattern, Kept::Input);

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
