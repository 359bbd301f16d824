// SPDX-License-Identifier: MIT
#include "workspace.h"

#include "devicemanager.h"
#include "deviceuri.h"
#include "patterndocument.h"
#include "routerdocument.h"

#include <QSettings>

namespace semhap {

namespace {

/** Where the device addresses the user added are kept between sessions. */
const QString AddressesKey = QStringLiteral("devices/addresses");

} // namespace

Workspace::Workspace(QObject *parent)
    : QObject(parent), m_routerDocument(new RouterDocument(this)),
      m_patternDocument(new PatternDocument(this))
{
    const QSettings settings;
    for (const QString &text : settings.value(AddressesKey).toStringList()) {
        DeviceUri uri;
        QString error;
        if (DeviceUri::parse(text, &uri, &error))
            m_engine.devices().addConfigured(uri.toString());
        else
            qWarning("%s: %s: %s", qPrintable(settings.fileName()), qPrintable(AddressesKey),
                     qPrintable(error));
    }
}

Workspace::~Workspace() = default;

void Workspace::saveDeviceAddresses()
{
    QSettings().setValue(AddressesKey, m_engine.devices().configured());
}

} // namespace semhap
