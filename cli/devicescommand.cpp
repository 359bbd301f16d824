// SPDX-License-Identifier: MIT
#include "devicescommand.h"

#include "bandprobe.h"
#include "devicemanager.h"
#include "deviceuri.h"
#include "transportscheme.h"

namespace semhap {

namespace {

/** How long --probe waits for a band's two replies. */
constexpr double ProbeTimeout = 2.5; // a Nano's boot loader holds the line for up to 2 s
/** The columns of the transports' listing: their syntax, and the whole line. */
constexpr int SyntaxWidth = 24;
constexpr int LineWidth = 80;

} // namespace

QString DevicesCommand::summary() const
{
    return tr("Lists the device transports and the serial ports, HID bands and sound outputs "
              "present, or asks one band who it is.");
}

void DevicesCommand::configure(QCommandLineParser &parser)
{
    parser.addOption({QStringLiteral("probe"),
                      tr("Ask the band at URI for its model, firmware and channels and for its "
                         "link counters, instead of listing."),
                      tr("URI")});
}

int DevicesCommand::execute(const QCommandLineParser &parser)
{
    if (!parser.positionalArguments().isEmpty())
        return usageError(
            tr("unexpected argument '%1'").arg(parser.positionalArguments().first()));
    if (parser.isSet(QStringLiteral("probe")))
        return probe(parser.value(QStringLiteral("probe")));
    m_out << tr("Transports (URIs for --device and --bind):\n");
    for (const TransportScheme &scheme : TransportScheme::all()) {
        const QString syntax = QString::fromUtf8(scheme.syntax);
        // A syntax wider than its column puts its help on the next line; the help wraps
        // at the terminal's usual width.
        QString line = syntax.size() < SyntaxWidth
                           ? QStringLiteral("  %1").arg(syntax, -SyntaxWidth)
                           : QStringLiteral("  %1\n%2")
                                 .arg(syntax, QString(SyntaxWidth + 2, QLatin1Char(' ')));
        qsizetype lineStart = line.lastIndexOf(QLatin1Char('\n')) + 1;
        for (const QString &word : QString::fromUtf8(scheme.help).split(QLatin1Char(' '))) {
            if (line.size() - lineStart + 1 + word.size() > LineWidth) {
                line += QLatin1Char('\n') + QString(SyntaxWidth + 2, QLatin1Char(' '));
                lineStart = line.size() - SyntaxWidth - 2;
            }
            line += QLatin1Char(' ') + word;
        }
        m_out << line << '\n';
    }
    m_out << '\n';
    DeviceManager manager;
    const std::vector<PortInfo> ports = manager.present();
    m_out << tr("Present:\n");
    if (ports.empty())
        m_out << tr("  (no serial ports, HID bands or sound outputs found)\n");
    for (const PortInfo &port : ports) {
        QString description = port.description;
        if (port.vendorId >= 0)
            description += QStringLiteral(" [%1:%2]")
                               .arg(port.vendorId, 4, 16, QLatin1Char('0'))
                               .arg(port.productId, 4, 16, QLatin1Char('0'));
        if (port.outputChannels >= 0)
            description = tr("%1 ch, %2 Hz (%3)")
                              .arg(port.outputChannels)
                              .arg(port.sampleRate)
                              .arg(port.description);
        m_out << QStringLiteral("  %1  %2\n").arg(port.uri, -24).arg(description);
    }
    return ExitOk;
}

int DevicesCommand::probe(const QString &uri)
{
    DeviceUri parsed;
    QString reason;
    if (!DeviceUri::parse(uri, &parsed, &reason))
        return usageError(reason);
    BandReport report;
    if (!BandProbe::probe(uri, ProbeTimeout, &report, &reason))
        return inputError(reason);
    const protocol::Identity &id = report.identity;
    m_out << tr("%1: %2, firmware %3.%4.%5, channels:\n")
                 .arg(uri, id.model)
                 .arg(id.firmwareMajor)
                 .arg(id.firmwareMinor)
                 .arg(id.firmwarePatch);
    for (const protocol::WireChannel &channel : id.channels)
        m_out << QStringLiteral("  %1  %2 … %3\n")
                     .arg(channel.name, -8)
                     .arg(double(channel.min))
                     .arg(double(channel.max));
    const protocol::DeviceStatus &status = report.status;
    QStringList flags;
    if (status.flags & protocol::WatchdogTripped)
        flags << tr("watchdog tripped");
    if (status.flags & protocol::ChannelCountMismatch)
        flags << tr("channel count mismatch");
    if (status.flags & protocol::Overpressure)
        flags << tr("overpressure");
    m_out << tr("status: %1 frames received, %2 dropped, %3 garbled; flags: %4\n")
                 .arg(status.framesReceived)
                 .arg(status.framesDropped)
                 .arg(status.framesGarbled)
                 .arg(flags.isEmpty() ? tr("none") : flags.join(QStringLiteral(", ")));
    return ExitOk;
}

} // namespace semhap
