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
    switch (uri.scheme) {
    case DeviceUri::Scheme::Virtual:
        return std::make_unique<VirtualTransport>(uri.name, std::move(model));
    case DeviceUri::Scheme::Audio:
        return std::make_unique<AudioTransport>(uri, std::move(model));
    case DeviceUri::Scheme::Serial:
    case DeviceUri::Scheme::Hid:
    case DeviceUri::Scheme::Udp:
        break;
    }
    return std::make_unique<LinkTransport>(createLink(uri), std::move(model));
}

std::unique_ptr<Link> TransportFactory::createLink(const DeviceUri &uri)
{
    switch (uri.scheme) {
    case DeviceUri::Scheme::Virtual:
    case DeviceUri::Scheme::Audio:
        break;
    case DeviceUri::Scheme::Serial:
        return std::make_unique<SerialLink>(uri.name, uri.baud);
    case DeviceUri::Scheme::Hid:
        return std::make_unique<HidLink>(uri.vendorId, uri.productId);
    case DeviceUri::Scheme::Udp:
        return std::make_unique<UdpLink>(uri.name, uri.port);
    }
    return nullptr;
}

} // namespace semhap
