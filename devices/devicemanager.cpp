// SPDX-License-Identifier: MIT
#include "devicemanager.h"

#include "deviceuri.h"
#include "transportfactory.h"

#include <algorithm>

namespace semhap {

DeviceManager::DeviceManager() = default;

DeviceManager::~DeviceManager()
{
    stopAll();
    for (auto &[name, transport] : m_bound)
        transport->close();
}

void DeviceManager::addConfigured(const QString &uri)
{
    if (!m_configured.contains(uri))
        m_configured.append(uri);
}

std::vector<PortInfo> DeviceManager::present() const
{
    std::vector<PortInfo> out;
    for (const TransportScheme &scheme : TransportScheme::all()) {
        if (scheme.present)
            scheme.present(&out);
    }
    for (const QString &uri : m_configured)
        out.push_back(
            {uri, uri.section(QLatin1Char(':'), 0, 0), QStringLiteral("configured"), -1, -1});
    return out;
}

bool DeviceManager::poll(QStringList *added, QStringList *removed)
{
    QStringList now;
    for (const PortInfo &port : present())
        now.append(port.uri);
    added->clear();
    removed->clear();
    for (const QString &uri : now) {
        if (!m_lastListed.contains(uri))
            added->append(uri);
    }
    for (const QString &uri : m_lastListed) {
        if (!now.contains(uri))
            removed->append(uri);
    }
    m_lastListed = now;
    return !added->isEmpty() || !removed->isEmpty();
}

bool DeviceManager::bind(const QString &name, const QString &uri, DeviceModelPtr model,
                         QString *error)
{
    std::unique_ptr<Transport> transport = TransportFactory::create(uri, std::move(model), error);
    if (!transport)
        return false;
    unbind(name);
    QString openError;
    transport->open(&openError); // not there yet: the transport keeps trying
    m_bound[name] = std::move(transport);
    return true;
}

void DeviceManager::unbind(const QString &name)
{
    const auto it = m_bound.find(name);
    if (it == m_bound.end())
        return;
    it->second->stopAll();
    it->second->close();
    m_bound.erase(it);
}

Transport *DeviceManager::transport(const QString &name) const
{
    return sharedTransport(name).get();
}

std::shared_ptr<Transport> DeviceManager::sharedTransport(const QString &name) const
{
    const auto it = m_bound.find(name);
    return it == m_bound.end() ? nullptr : it->second;
}

QStringList DeviceManager::boundNames() const
{
    QStringList names;
    for (const auto &[name, transport] : m_bound)
        names.append(name);
    return names;
}

std::vector<BoundDevice> DeviceManager::status() const
{
    std::vector<BoundDevice> out;
    for (const auto &[name, transport] : m_bound)
        out.push_back({name, transport->uri(), transport->model().name(), transport->status()});
    return out;
}

void DeviceManager::armAll(bool armed)
{
    for (auto &[name, transport] : m_bound)
        transport->setArmed(armed);
}

void DeviceManager::stopAll()
{
    for (auto &[name, transport] : m_bound)
        transport->stopAll();
}

bool DeviceManager::parseBinding(const QString &text, QString *name, QString *uri, QString *error)
{
    const qsizetype equals = text.indexOf(QLatin1Char('='));
    if (equals <= 0 || equals == text.size() - 1) {
        *error = QStringLiteral("%1: a binding is NAME=URI (right.vibro=serial:/dev/ttyACM0)")
                     .arg(text);
        return false;
    }
    *name = text.left(equals);
    *uri = text.mid(equals + 1);
    DeviceUri parsed;
    return DeviceUri::parse(*uri, &parsed, error);
}

} // namespace semhap
