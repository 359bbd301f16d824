// SPDX-License-Identifier: MIT
#include "devicescommand.h"

#include "devicemanager.h"

namespace semhap {

QString DevicesCommand::summary() const
{
    return tr("Lists the device transports and the serial ports, HID bands and sound outputs "
              "present.");
}

void DevicesCommand::configure(QCommandLineParser &) {}

int DevicesCommand::execute(const QCommandLineParser &parser)
{
    if (!parser.positionalArguments().isEmpty())
        return usageError(
            tr("unexpected argument '%1'").arg(parser.positionalArguments().first()));
    m_out << tr("Transports (URIs for --device and --bind):\n")
          << tr("  virtual:NAME             no hardware; keeps frames for previews\n")
          << tr("  serial:PATH[?baud=N]     a serial port or pseudo-terminal (default "
                "250000 baud)\n")
          << tr("  hid:VID:PID              a USB HID band (hex IDs, usage page 0xFF00)\n")
          << tr("  udp:HOST:PORT            a band on the network\n")
          << tr("  audio:DEVICE[?channels=1,2,…&carrier=HZ,…]\n"
                "                           a sound card's outputs: each channel a carrier "
                "(170 Hz)\n"
                "                           times its envelope\n\n");
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

} // namespace semhap
