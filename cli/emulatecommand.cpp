// SPDX-License-Identifier: MIT
#include "emulatecommand.h"

#include "emulator.h"
#include "quitsignal.h"

namespace semhap {

QString EmulateCommand::summary() const
{
    return tr("Emulates a wristband on a pseudo-terminal or a UDP port: speaks the wire "
              "protocol, applies the model's response, runs the watchdog, logs its state.");
}

void EmulateCommand::configure(QCommandLineParser &parser)
{
    parser.addOption({QStringLiteral("model"),
                      tr("Device model: pneumatic6, lra4, fingertips2 (or a model file)."),
                      tr("MODEL")});
    parser.addOption({QStringLiteral("pty"), tr("Listen on a new pseudo-terminal.")});
    parser.addOption({QStringLiteral("link"),
                      tr("With --pty: keep a symlink to the pty here (a stale one is replaced)."),
                      tr("PATH")});
    parser.addOption({QStringLiteral("udp"),
                      tr("Listen on this UDP port of 127.0.0.1 (0: any free port), or on "
                         "HOST:PORT."),
                      tr("[HOST:]PORT")});
    parser.addOption({QStringLiteral("log"),
                      tr("Write the state as JSON Lines at every change: "
                         "{\"t\", \"setpoint\", \"values\"}."),
                      tr("FILE")});
}

int EmulateCommand::execute(const QCommandLineParser &parser)
{
    if (!parser.positionalArguments().isEmpty())
        return usageError(
            tr("unexpected argument '%1'").arg(parser.positionalArguments().first()));
    if (!parser.isSet(QStringLiteral("model")))
        return usageError(tr("--model is required"));
    const bool pty = parser.isSet(QStringLiteral("pty"));
    const bool udp = parser.isSet(QStringLiteral("udp"));
    if (pty == udp)
        return usageError(tr("give exactly one of --pty and --udp"));
    if (udp && parser.isSet(QStringLiteral("link")))
        return usageError(tr("--link goes with --pty"));

    EmulatorOptions options;
    LoadError error;
    options.model = DeviceModelLibrary::load(parser.value(QStringLiteral("model")), &error);
    if (!options.model)
        return inputError(error.toString());
    options.udp = udp;
    options.link = parser.value(QStringLiteral("link"));
    options.logPath = parser.value(QStringLiteral("log"));
    // The live log is emptied when the band starts: never the model file it was made from.
    keepFromOutputs(parser.value(QStringLiteral("model")), Kept::Input);
    if (!options.logPath.isEmpty() && !checkOutputPath(options.logPath))
        return ExitInvalidInput;
    if (udp) {
        const QString value = parser.value(QStringLiteral("udp"));
        const qsizetype colon = value.lastIndexOf(QLatin1Char(':'));
        if (colon >= 0)
            options.host = value.left(colon);
        bool ok = false;
        options.port = value.mid(colon + 1).toInt(&ok);
        if (!ok || options.port < 0 || options.port > 65535 || options.host.isEmpty())
            return usageError(
                tr("--udp expects [HOST:]PORT with a port 0-65535, got '%1'").arg(value));
    }

    Emulator emulator(options);
    QString reason;
    if (!emulator.open(&reason))
        return inputError(reason);
    QuitSignal::install();
    m_out << emulator.address() << '\n';
    flushOutputs(); // whoever started it waits for this line
    if (!emulator.run([] { return QuitSignal::requested(); }))
        return inputError(emulator.logError());
    return ExitOk;
}

} // namespace semhap
