// SPDX-License-Identifier: MIT
#include "deviceuri.h"

#include "transportscheme.h"

namespace semhap {

bool DeviceUri::parse(const QString &text, DeviceUri *uri, QString *error)
{
    const qsizetype colon = text.indexOf(QLatin1Char(':'));
    const QString name = colon < 0 ? QString() : text.left(colon);
    const TransportScheme *scheme = colon < 0 ? nullptr : TransportScheme::find(name);
    if (!scheme) {
        *error = QStringLiteral("%1: unknown device scheme '%2' (%3)")
                     .arg(text, colon < 0 ? text : name, TransportScheme::names());
        return false;
    }
    DeviceUri out;
    out.scheme = name;
    QString reason;
    if (!scheme->parse(text.mid(colon + 1), &out, &reason)) {
        *error = QStringLiteral("%1: %2").arg(text, reason);
        return false;
    }
    *uri = out;
    return true;
}

QString DeviceUri::virtualFor(const QString &name)
{
    return QStringLiteral("virtual:") + name;
}

QString DeviceUri::toString() const
{
    const TransportScheme *row = TransportScheme::find(scheme);
    return row ? scheme + QLatin1Char(':') + row->format(*this) : QString();
}

bool DeviceUri::parseHostPort(const QString &address, DeviceUri *uri, QString *error)
{
    const qsizetype portColon = address.lastIndexOf(QLatin1Char(':'));
    bool ok = false;
    uri->name = address.left(portColon);
    uri->port = portColon < 0 ? 0 : address.mid(portColon + 1).toInt(&ok);
    if (uri->name.startsWith(QLatin1Char('[')) && uri->name.endsWith(QLatin1Char(']')))
        uri->name = uri->name.mid(1, uri->name.size() - 2);
    if (!ok || uri->name.isEmpty() || uri->port <= 0 || uri->port > 65535) {
        *error = QStringLiteral("a %1 device is %1:HOST:PORT with a port 1-65535 "
                                "(%1:127.0.0.1:9000)")
                     .arg(uri->scheme);
        return false;
    }
    return true;
}

QString DeviceUri::hostPortUri(const QString &scheme, const QString &host, int port)
{
    DeviceUri uri;
    uri.scheme = scheme;
    uri.name = host;
    uri.port = port;
    return uri.toString();
}

QString DeviceUri::formatHostPort(const DeviceUri &uri)
{
    return uri.name.contains(QLatin1Char(':'))
               ? QStringLiteral("[%1]:%2").arg(uri.name).arg(uri.port)
               : QStringLiteral("%1:%2").arg(uri.name).arg(uri.port);
}

} // namespace semhap
