// SPDX-License-Identifier: MIT
#include "convertcommand.h"

#include "hapticconverter.h"

namespace semhap {

QString ConvertCommand::summary() const
{
    return tr("Converts between semhap patterns (.json), Apple AHAP (.ahap) and Meta .haptic "
              "files, by extension (docs/convert.md says what maps).");
}

void ConvertCommand::configure(QCommandLineParser &parser)
{
    parser.addPositionalArgument(QStringLiteral("in"), tr("File to read."), tr("IN"));
    parser.addPositionalArgument(QStringLiteral("out"), tr("File to write."), tr("OUT"));
    parser.addOption({QStringLiteral("device"),
                      tr("Device model of an imported pattern (default lra4)."), tr("MODEL")});
    parser.addOption({QStringLiteral("channel"),
                      tr("Import: the one channel the pattern drives (default all). Export: "
                         "the channel written (default the loudest track)."),
                      tr("NAME")});
    parser.addOption({QStringLiteral("release-at"),
                      tr("Export: when the pattern ends, in seconds (default after the attack, "
                         "plus 1 s of a sustain that plays)."),
                      tr("S")});
    parser.addOption({QStringLiteral("duration"),
                      tr("Export: seconds to render (default to the end of the release)."),
                      tr("S")});
    parser.addOption({QStringLiteral("modulate"),
                      tr("Render sharpness as an amplitude modulation the device can follow "
                         "(import), and read such a modulation back as sharpness (export). "
                         "Without it the envelope is kept as it is.")});
}

int ConvertCommand::execute(const QCommandLineParser &parser)
{
    const QStringList positional = parser.positionalArguments();
    if (positional.size() != 2)
        return usageError(tr("expected IN and OUT, got %1 argument(s)").arg(positional.size()));
    const QString &in = positional[0];
    const QString &out = positional[1];
    HapticFileFormat inFormat;
    HapticFileFormat outFormat;
    LoadError error;
    if (!HapticConverter::formatOf(in, &inFormat, &error) ||
        !HapticConverter::formatOf(out, &outFormat, &error))
        return usageError(error.toString());

    ConvertOptions options;
    options.channel = parser.value(QStringLiteral("channel"));
    if (!numberOption(parser, QStringLiteral("release-at"), &options.releaseAt) ||
        !numberOption(parser, QStringLiteral("duration"), &options.duration))
        return ExitUsage;
    if (parser.isSet(QStringLiteral("release-at")) && options.releaseAt < 0)
        return usageError(tr("--release-at must not be negative"));
    if (parser.isSet(QStringLiteral("duration")) && options.duration < 0)
        return usageError(tr("--duration must not be negative"));
    const bool modulate = parser.isSet(QStringLiteral("modulate"));

    // Importing: the new pattern's model decides the channels and the modulation range.
    if (parser.isSet(QStringLiteral("device")) && inFormat == HapticFileFormat::Semhap)
        return usageError(tr("--device is for imports; %1 already names its model").arg(in));
    DeviceModelPtr model = DeviceModelLibrary::builtin(parser.isSet(QStringLiteral("device"))
                                                           ? parser.value(QStringLiteral("device"))
                                                           : QStringLiteral("lra4"));
    if (!model)
        return usageError(tr("unknown device model '%1' (built-in: %2)")
                              .arg(parser.value(QStringLiteral("device")),
                                   DeviceModelLibrary::builtinNames().join(QStringLiteral(", "))));
    if (inFormat != HapticFileFormat::Semhap && !options.channel.isEmpty() &&
        model->channelIndex(options.channel) < 0)
        return usageError(tr("model %1 has no channel '%2' (channels: %3)")
                              .arg(model->name(), options.channel,
                                   model->channelNames().join(QStringLiteral(", "))));
    options.model = model->name();
    options.modulationLimit = modulate ? model->modulationLimit() : 0.0;

    QStringList warnings;
    QJsonObject pattern;
    const bool read = HapticConverter::readPattern(in, options, &pattern, &warnings, &error);
    for (const QString &warning : warnings)
        report(warning);
    if (!read)
        return inputError(error.toString());
    keepFromOutputs(in, Kept::Input);

    // Exporting: the pattern's own model gives the modulation range back.
    warnings.clear();
    const DeviceModelPtr patternModel =
        DeviceModelLibrary::builtin(pattern.value(QLatin1String("model")).toString());
    options.modulationLimit = modulate && patternModel ? patternModel->modulationLimit() : 0.0;
    QByteArray bytes;
    const bool serialized =
        HapticConverter::serialize(pattern, outFormat, out, options, &bytes, &warnings, &error);
    for (const QString &warning : warnings)
        report(warning);
    if (!serialized)
        return inputError(error.toString());
    QIODevice *file = openOutput(out);
    if (!file)
        return ExitInvalidInput;
    file->write(bytes);
    return ExitOk;
}

} // namespace semhap
