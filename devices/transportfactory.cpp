// SPDX-License-Identifier: MIT
#include "transportfactory.h"

#include "linktransport.h"
#include "transportscheme.h"

namespace semhap {

std::unique_ptr<Transport> TransportFactory::create(const QString &uri, DeviceModelPtr model,
                                                    QString *error)
{
    DeviceUri parsed;
    if (!DeviceUri::parse(uri, &parsed, error))
        return nullptr;
    const TransportScheme *scheme = TransportScheme::find(parsed.scheme);
    if (scheme->fits && !scheme->fits(parsed, *model, error))
        return nullptr;
    return create(parsed, std::move(model));
}

std::unique_ptr<Transport> TransportFactory::create(const DeviceUri &uri, DeviceModelPtr model)
{
    const TransportScheme *scheme = TransportScheme::find(uri.scheme);
    if (!scheme)
        return nullptr;
    if (scheme->transport)
        return scheme->transport(uri, std::move(model));
    return std::make_unique<LinkTransport>(scheme->link(uri), std::move(model));
}

std::unique_ptr<Link> TransportFactory::createLink(const DeviceUri &uri)
{
    const TransportScheme *scheme = TransportScheme::find(uri.scheme);
    return scheme && scheme->link ? scheme->link(uri) : nullptr;
}

} // namespace semhap
