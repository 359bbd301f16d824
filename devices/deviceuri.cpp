// SPDX-License-Identifier: MIT
#include "deviceuri.h"

#include "deviceframe.h"

#include <QStringList>

#include <algorithm>
#include <cmath>

namespace semhap {

namespace {

bool parseHexId(const QString &text, int *value)
{
    bool ok = false;
    const uint parsed = text.toUInt(&ok, 16);
    if (!ok || text.isEmpty() || text.size() > 4 || text.startsWith(QLatin1Char('+')))
        return false;
    *value = int(parsed);
    return true;
}

/** `audio:` options (`channels=1,2&carrier=170`) into `uri`; false with a reason. */
bool parseAudioOptions(const QString &text, const QString &options, DeviceUri *uri, QString *error)
{
    for (const QString &option : options.split(QLatin1Char('&'))) {
        const QString key = option.section(QLatin1Char('='), 0, 0);
        const QStringList values = option.section(QLatin1Char('='), 1).split(QLatin1Char(','));
        if (key == QLatin1String("channels")) {
            uri->outputChannels.clear();
            for (const QString &value : values) {
                bool ok = false;
                const int channel = value.toInt(&ok);
                if (!ok || channel < 1) {
                    *error = QStringLiteral("%1: channels= takes the card's output channels, "
                                            "from 1, comma-separated (channels=1,2,3,4)")
                                 .arg(text);
                    return false;
                }
                if (std::find(uri->outputChannels.begin(), uri->outputChannels.end(), channel) !=
                    uri->outputChannels.end()) {
                    *error = QStringLiteral("%1: output channel %2 is given twice")
                                 .arg(text)
                                 .arg(channel);
                    return false;
                }
                uri->outputChannels.push_back(channel);
            }
            if (int(uri->outputChannels.size()) > MaxChannels) {
                *error = QStringLiteral("%1: at most %2 channels").arg(text).arg(MaxChannels);
                return false;
            }
        } else if (key == QLatin1String("carrier")) {
            uri->carriers.clear();
            for (const QString &value : values) {
                bool ok = false;
                const double carrier = value.toDouble(&ok);
                if (!ok || !std::isfinite(carrier) || carrier <= 0.0) {
                    *error = QStringLiteral("%1: carrier= takes frequencies above 0 Hz, one "
                                            "for all channels or one per channel "
                                            "(carrier=170 or carrier=170,170,200,200)")
                                 .arg(text);
                    return false;
                }
                uri->carriers.push_back(carrier);
            }
        } else {
            *error = QStringLiteral("%1: unknown option '%2' (audio takes "
                                    "?channels=1,2,…&carrier=HZ,…)")
                         .arg(text, option);
            return false;
        }
    }
    if (uri->carriers.size() > 1 && !uri->outputChannels.empty() &&
        uri->carriers.size() != uri->outputChannels.size()) {
        *error = QStringLiteral("%1: %2 carriers for %3 channels: give one for all, or one "
                                "per channel")
                     .arg(text)
                     .arg(uri->carriers.size())
                     .arg(uri->outputChannels.size());
        return false;
    }
    return true;
}

} // namespace

bool DeviceUri::parse(const QString &text, DeviceUri *uri, QString *error)
{
    const qsizetype colon = text.indexOf(QLatin1Char(':'));
    const QString scheme = colon < 0 ? QString() : text.left(colon);
    const QString rest = colon < 0 ? QString() : text.mid(colon + 1);
    DeviceUri out;
    if (scheme == QLatin1String("virtual")) {
        if (rest.isEmpty()) {
            *error = QStringLiteral("%1: a virtual device needs a name (virtual:NAME)").arg(text);
            return false;
        }
        out.scheme = Scheme::Virtual;
        out.name = rest;
    } else if (scheme == QLatin1String("serial")) {
        out.scheme = Scheme::Serial;
        const qsizetype query = rest.indexOf(QLatin1Char('?'));
        out.name = rest.left(query);
        if (out.name.isEmpty()) {
            *error =
                QStringLiteral("%1: a serial device needs a path (serial:/dev/ttyACM0)").arg(text);
            return false;
        }
        if (query >= 0) {
            const QString option = rest.mid(query + 1);
            bool ok = false;
            const int baud =
                option.startsWith(QLatin1String("baud=")) ? option.mid(5).toInt(&ok) : 0;
            if (!ok || baud <= 0) {
                *error = QStringLiteral("%1: unknown option '%2' (serial takes ?baud=N, N > 0)")
                             .arg(text, option);
                return false;
            }
            out.baud = baud;
        }
    } else if (scheme == QLatin1String("hid")) {
        out.scheme = Scheme::Hid;
        const QStringList ids = rest.split(QLatin1Char(':'));
        if (ids.size() != 2 || !parseHexId(ids[0], &out.vendorId) ||
            !parseHexId(ids[1], &out.productId)) {
            *error = QStringLiteral("%1: a HID device is hid:VID:PID, each up to four hex "
                                    "digits (hid:1234:5678)")
                         .arg(text);
            return false;
        }
    } else if (scheme == QLatin1String("udp")) {
        out.scheme = Scheme::Udp;
        const qsizetype portColon = rest.lastIndexOf(QLatin1Char(':'));
        bool ok = false;
        out.name = rest.left(portColon);
        out.port = portColon < 0 ? 0 : rest.mid(portColon + 1).toInt(&ok);
        if (out.name.startsWith(QLatin1Char('[')) && out.name.endsWith(QLatin1Char(']')))
            out.name = out.name.mid(1, out.name.size() - 2);
        if (!ok || out.name.isEmpty() || out.port <= 0 || out.port > 65535) {
            *error = QStringLiteral("%1: a UDP device is udp:HOST:PORT with a port 1-65535 "
                                    "(udp:127.0.0.1:9000)")
                         .arg(text);
            return false;
        }
    } else if (scheme == QLatin1String("audio")) {
        out.scheme = Scheme::Audio;
        const qsizetype query = rest.indexOf(QLatin1Char('?'));
        out.name = rest.left(query);
        if (out.name.isEmpty()) {
            *error = QStringLiteral("%1: an audio device needs an output (audio:default, or a "
                                    "name `semhap devices` lists)")
                         .arg(text);
            return false;
        }
        if (query >= 0 && !parseAudioOptions(text, rest.mid(query + 1), &out, error))
            return false;
    } else {
        *error = QStringLiteral("%1: unknown device scheme '%2' (virtual, serial, hid, udp, "
                                "audio)")
                     .arg(text, colon < 0 ? text : scheme);
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
    switch (scheme) {
    case Scheme::Virtual:
        return virtualFor(name);
    case Scheme::Serial:
        return baud == DefaultBaud ? QStringLiteral("serial:") + name
                                   : QStringLiteral("serial:%1?baud=%2").arg(name).arg(baud);
    case Scheme::Hid:
        return QStringLiteral("hid:%1:%2")
            .arg(vendorId, 4, 16, QLatin1Char('0'))
            .arg(productId, 4, 16, QLatin1Char('0'));
    case Scheme::Udp:
        return name.contains(QLatin1Char(':')) ? QStringLiteral("udp:[%1]:%2").arg(name).arg(port)
                                               : QStringLiteral("udp:%1:%2").arg(name).arg(port);
    case Scheme::Audio: {
        QStringList options;
        QStringList list;
        for (const int channel : outputChannels)
            list.append(QString::number(channel));
        if (!list.isEmpty())
            options.append(QStringLiteral("channels=") + list.join(QLatin1Char(',')));
        list.clear();
        for (const double carrier : carriers)
            list.append(QString::number(carrier));
        if (!list.isEmpty() && !(carriers.size() == 1 && carriers[0] == DefaultCarrier))
            options.append(QStringLiteral("carrier=") + list.join(QLatin1Char(',')));
        return QStringLiteral("audio:") + name +
               (options.isEmpty() ? QString() : QLatin1Char('?') + options.join(QLatin1Char('&')));
    }
    }
    return {};
}

} // namespace semhap
