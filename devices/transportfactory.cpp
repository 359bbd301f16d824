// SPDX-License-Identifier: MIT
#include "transportfactory.h"

#include "audiotransport.h"
#include "hidlink.h"
#include "linktransport.h"
#include "seriallink.h"
#include "udplink.h"
#include "virtualtransport.h"

namespace semhap {

std::unique_ptr<Transport> TransportFactory::create(const QString &uri, DeviceModelPtr model,
                                                    QString *error)
{
    DeviceUri parsed;
    if (!DeviceUri::parse(uri, &parsed, error))
        return nullptr;
    if (parsed.scheme == DeviceUri::Scheme::Audio && !AudioTransport::check(parsed, *model, error))
        return nullptr;
    return create(parsed, std::move(model));
}

std::unique_ptr<Transport> TransportFactory::create(const DeviceUri &uri, DeviceModelPtr model)
{
    std::unique_ptr<Link> link;
    switch (uri.scheme) {
    case DeviceUri::Scheme::Virtual:
        return std::make_unique<VirtualTransport>(uri.name, std::move(model));
    case DeviceUri::Scheme::Serial:
        link = std::make_unique<SerialLink>(uri.name, uri.baud);
        break;
    case DeviceUri::Scheme::Hid:
        link = std::make_unique<HidLink>(uri.vendorId, uri.productId);
        break;
    case DeviceUri::Scheme::Udp:
        link = std::make_unique<UdpLink>(uri.name, uri.port);
        break;
    case DeviceUri::Scheme::Audio:
        return std::make_unique<AudioTransport>(uri, std::move(model));
    }
    return std::make_unique<LinkTransport>(std::move(link), std::move(model));
}

} // namespace semhap
