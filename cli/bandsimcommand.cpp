// SPDX-License-Identifier: MIT
#include "bandsimcommand.h"

#include "bandsimulator.h"
#include "quitsignal.h"

namespace semhap {

namespace {

/** Passes each stretch the chip fell behind the wall clock on to a report line. */
class LagReport : public BandSimObserver
{
public:
    explicit LagReport(std::function<void(const QString &)> report) : m_report(std::move(report))
    {}
    void fellBehind(double t, double behind, double skipped) override
    {
        m_report(BandSimCommand::tr("at %1 s the chip was %2 s behind the wall clock; %3 s of "
                                    "wall time is not simulated there")
                     .arg(t, 0, 'f', 4)
                     .arg(behind, 0, 'f', 4)
                     .arg(skipped, 0, 'f', 4));
    }

private:
    std::function<void(const QString &)> m_report;
};

} // namespace

QString BandSimCommand::summary() const
{
    return tr("Runs a reference band's firmware image on a simulated ATmega328P, its UART on "
              "a pseudo-terminal; logs what the chip drives.");
}

void BandSimCommand::configure(QCommandLineParser &parser)
{
    parser.addPositionalArgument(QStringLiteral("model"),
                                 tr("The reference band: lra4 or "
                                    "pneumatic6."),
                                 tr("MODEL"));
    parser.addOption({QStringLiteral("pty"), tr("Serve the chip's UART on a new "
                                                "pseudo-terminal (required).")});
    parser.addOption({QStringLiteral("link"),
                      tr("Keep a symlink to the pty here (a stale one is replaced)."),
                      tr("PATH")});
    parser.addOption({QStringLiteral("log"),
                      tr("Write what the chip drives as JSON Lines at every change: "
                         "{\"t\", \"setpoint\", \"values\"}, t in simulated seconds."),
                      tr("FILE")});
    parser.addOption({QStringLiteral("firmware"),
                      tr("Run this Intel HEX image instead of the built-in one."), tr("FILE")});
}

int BandSimCommand::execute(const QCommandLineParser &parser)
{
    const QStringList positional = parser.positionalArguments();
    if (positional.isEmpty())
        return usageError(
            tr("MODEL is required (%1)").arg(BandSimulator::models().join(QStringLiteral(", "))));
    if (positional.size() > 1)
        return usageError(tr("unexpected argument '%1'").arg(positional[1]));
    if (!BandSimulator::models().contains(positional.first()))
        return usageError(
            tr("no reference board '%1' (boards: %2)")
                .arg(positional.first(), BandSimulator::models().join(QStringLiteral(", "))));
    if (!parser.isSet(QStringLiteral("pty")))
        return usageError(tr("--pty is required (the simulated band's only link for now)"));

    BandSimOptions options;
    options.model = DeviceModelLibrary::builtin(positional.first());
    options.firmware = parser.value(QStringLiteral("firmware"));
    options.link = parser.value(QStringLiteral("link"));
    options.logPath = parser.value(QStringLiteral("log"));
    // The live log is emptied when the band starts: never the image it runs.
    keepFromOutputs(options.firmware, Kept::Input);
    if (!options.logPath.isEmpty() && !checkOutputPath(options.logPath))
        return ExitInvalidInput;

    BandSimulator band(options);
    QString reason;
    if (!band.open(&reason))
        return inputError(reason);
    LagReport lag([this](const QString &line) { report(line); });
    band.setObserver(&lag);
    QuitSignal::install();
    m_out << band.address() << '\n';
    flushOutputs(); // whoever started it waits for this line
    if (!band.run([] { return QuitSignal::requested(); }))
        return inputError(band.error());
    return ExitOk;
}

} // namespace semhap
