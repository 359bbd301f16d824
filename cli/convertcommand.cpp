// SPDX-License-Identifier: MIT
#include "convertcommand.h"

#include "hapticconverter.h"
#include "hjifconverter.h"
#include "router.h"

namespace semhap {

QString ConvertCommand::summary() const
{
    return tr("Converts between semhap patterns (.json), Apple AHAP (.ahap), Meta .haptic and "
              "MPEG haptics (.hjif) files, by extension, and writes a router's patterns as an "
              "HJIF effect library (docs/convert.md says what maps).");
}

void ConvertCommand::configure(QCommandLineParser &parser)
{
    parser.addPositionalArgument(QStringLiteral("in"), tr("File to read (not with --router)."),
                                 tr("IN"));
    parser.addPositionalArgument(QStringLiteral("out"), tr("File to write."), tr("OUT"));
    parser.addOption({QStringLiteral("router"),
                      tr("Write every message this router (a preset or a file) plays as an "
                         "HJIF effect library, to OUT.hjif."),
                      tr("PRESET|FILE")});
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
    parser.addOption({QStringLiteral("perception"),
                      tr("HJIF import: the perception read, by id (default the first the device "
                         "plays)."),
                      tr("ID")});
    parser.addOption({QStringLiteral("effect"),
                      tr("HJIF import: only library effect ID, where the channels play it "
                         "(default every channel's whole content)."),
                      tr("ID")});
    parser.addOption({QStringLiteral("hand"),
                      tr("HJIF export: the hand wearing the band, left or right (default "
                         "either)."),
                      tr("HAND")});
    parser.addOption({QStringLiteral("modulate"),
                      tr("Render sharpness as an amplitude modulation the device can follow "
                         "(import), and read such a modulation back as sharpness (export). "
                         "Without it the envelope is kept as it is.")});
}

int ConvertCommand::execute(const QCommandLineParser &parser)
{
    const QStringList positional = parser.positionalArguments();
    const bool fromRouter = parser.isSet(QStringLiteral("router"));
    if (positional.size() != (fromRouter ? 1 : 2))
        return usageError(
            fromRouter
                ? tr("expected OUT after --router, got %1 argument(s)").arg(positional.size())
                : tr("expected IN and OUT, got %1 argument(s)").arg(positional.size()));
    const QString in = fromRouter ? QString() : positional[0];
    const QString &out = positional.last();
    HapticFileFormat inFormat = HapticFileFormat::Semhap;
    HapticFileFormat outFormat;
    LoadError error;
    if ((!fromRouter && !HapticConverter::formatOf(in, &inFormat, &error)) ||
        !HapticConverter::formatOf(out, &outFormat, &error))
        return usageError(error.toString());
    const bool hjifIn = inFormat == HapticFileFormat::Hjif;
    const bool hjifOut = outFormat == HapticFileFormat::Hjif;
    if (fromRouter && !hjifOut)
        return usageError(tr("--router writes an HJIF file: OUT must end in .hjif"));

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
    if ((hjifIn || hjifOut) && (!options.channel.isEmpty() || modulate))
        return usageError(tr("--channel and --modulate are for AHAP and .haptic: HJIF has a "
                             "channel per actuator and no sharpness"));
    for (const QString &option : {QStringLiteral("perception"), QStringLiteral("effect")}) {
        if (!parser.isSet(option))
            continue;
        if (!hjifIn)
            return usageError(tr("--%1 is for reading HJIF files").arg(option));
        bool ok = false;
        const int id = parser.value(option).toInt(&ok);
        if (!ok || id < 0)
            return usageError(
                tr("--%1 expects an id (0 or more), got '%2'").arg(option, parser.value(option)));
        (option == QLatin1String("effect") ? options.effect : options.perception) = id;
    }
    options.hand = parser.value(QStringLiteral("hand"));
    if (parser.isSet(QStringLiteral("hand"))) {
        if (!hjifOut)
            return usageError(tr("--hand is for writing HJIF files"));
        if (fromRouter)
            return usageError(tr("--hand is for patterns: a router's devices name their hands"));
        if (options.hand != QLatin1String("left") && options.hand != QLatin1String("right"))
            return usageError(tr("--hand expects left or right, got '%1'").arg(options.hand));
    }

    // Importing: the new pattern's model decides the channels and the modulation range.
    if (parser.isSet(QStringLiteral("device")) &&
        (fromRouter || inFormat == HapticFileFormat::Semhap))
        return usageError(tr("--device is for imports; %1 already names its model")
                              .arg(fromRouter ? parser.value(QStringLiteral("router")) : in));
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
    // Without --device an import plays on lra4, or an HJIF file on the device it names.
    options.model = parser.isSet(QStringLiteral("device")) ? model->name() : QString();
    options.modulationLimit = modulate ? model->modulationLimit() : 0.0;

    QStringList warnings;
    QByteArray bytes;
    if (fromRouter) {
        const QString router = parser.value(QStringLiteral("router"));
        const std::unique_ptr<Router> compiled = loadRouter(router, {}, &error);
        if (!compiled)
            return inputError(error.toString());
        reportWarnings(compiled->graph());
        keepFromOutputs(router, Kept::Input);
        HjifDocument document;
        const bool converted = HjifConverter::routerToDocument(*compiled, router, options,
                                                               &document, &warnings, &error);
        for (const QString &warning : warnings)
            report(warning);
        if (!converted)
            return inputError(error.toString());
        bytes = HjifConverter::serialize(document);
    } else {
        QJsonObject pattern;
        const bool read =
            hjifIn ? HjifConverter::readPattern(in, options, &pattern, &warnings, &error)
                   : HapticConverter::readPattern(in, options, &pattern, &warnings, &error);
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
        bool serialized = false;
        if (hjifOut) {
            HjifDocument document;
            serialized = HjifConverter::patternToDocument(pattern, in, options, &document,
                                                          &warnings, &error);
            bytes = HjifConverter::serialize(document);
        } else {
            serialized = HapticConverter::serialize(pattern, outFormat, out, options, &bytes,
                                                    &warnings, &error);
        }
        for (const QString &warning : warnings)
            report(warning);
        if (!serialized)
            return inputError(error.toString());
    }
    QIODevice *file = openOutput(out);
    if (!file)
        return ExitInvalidInput;
    file->write(bytes);
    return ExitOk;
}

} // namespace semhap
