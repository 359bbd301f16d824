// SPDX-License-Identifier: MIT
#include "transportscheme.h"

#include "audiotransport.h"
#include "hidlink.h"
#include "seriallink.h"
#include "tcplink.h"
#include "udplink.h"
#include "virtualtransport.h"

#include <QStringList>

namespace semhap {

const std::vector<TransportScheme> &TransportScheme::all()
{
    static const std::vector<TransportScheme> rows = {
        {
            "virtual",
            "virtual:NAME",
            "no hardware; keeps frames for previews",
            [](const QString &address, DeviceUri *uri, QString *error) {
                uri->name = address;
                if (address.isEmpty())
                    *error = QStringLiteral("a virtual device needs a name (virtual:NAME)");
                return !address.isEmpty();
            },
            [](const DeviceUri &uri) { return uri.name; },
            nullptr,
            nullptr,
            [](const DeviceUri &uri, DeviceModelPtr model) -> std::unique_ptr<Transport> {
                return std::make_unique<VirtualTransport>(uri.name, std::move(model));
            },
            nullptr,
        },
        {
            "serial",
            "serial:PATH[?baud=N]",
            "a serial port or pseudo-terminal (default 250000 baud)",
            &SerialLink::parseAddress,
            &SerialLink::formatAddress,
            nullptr,
            [](const DeviceUri &uri) -> std::unique_ptr<Link> {
                return std::make_unique<SerialLink>(uri.name, uri.baud);
            },
            nullptr,
            &SerialLink::present,
        },
        {
            "hid",
            "hid:VID:PID",
            "a USB HID band (hex IDs, usage page 0xFF00)",
            &HidLink::parseAddress,
            &HidLink::formatAddress,
            nullptr,
            [](const DeviceUri &uri) -> std::unique_ptr<Link> {
                return std::make_unique<HidLink>(uri.vendorId, uri.productId);
            },
            nullptr,
            &HidLink::present,
        },
        {
            "udp",
            "udp:HOST:PORT",
            "a band on the network, one datagram per frame",
            &DeviceUri::parseHostPort,
            &DeviceUri::formatHostPort,
            nullptr,
            [](const DeviceUri &uri) -> std::unique_ptr<Link> {
                return std::make_unique<UdpLink>(uri.name, uri.port);
            },
            nullptr,
            nullptr,
        },
        {
            "tcp",
            "tcp:HOST:PORT",
            "a band behind a TCP port: a serial band shared by ser2net or socat, or a Wi-Fi board",
            &DeviceUri::parseHostPort,
            &DeviceUri::formatHostPort,
            nullptr,
            [](const DeviceUri &uri) -> std::unique_ptr<Link> {
                return std::make_unique<TcpLink>(uri.name, uri.port);
            },
            nullptr,
            nullptr,
        },
        {
            "audio",
            "audio:DEVICE[?channels=1,2,…&carrier=HZ,…]",
            "a sound card's outputs: each channel a carrier (170 Hz) times its envelope",
            &AudioTransport::parseAddress,
            &AudioTransport::formatAddress,
            &AudioTransport::fits,
            nullptr,
            [](const DeviceUri &uri, DeviceModelPtr model) -> std::unique_ptr<Transport> {
                return std::make_unique<AudioTransport>(uri, std::move(model));
            },
            &AudioTransport::present,
        },
    };
    return rows;
}

const TransportScheme *TransportScheme::find(const QString &name)
{
    for (const TransportScheme &row : all()) {
        if (name == QLatin1String(row.name))
            return &row;
    }
    return nullptr;
}

QString TransportScheme::names()
{
    QStringList names;
    for (const TransportScheme &row : all())
        names.append(QLatin1String(row.name));
    return names.join(QStringLiteral(", "));
}

} // namespace semhap
