// SPDX-License-Identifier: MIT
#pragma once

#include "transport.h"
#include "transportscheme.h"

#include <QStringList>

#include <map>
#include <memory>
#include <vector>

namespace semhap {

/** A bound device and how its transport is doing. */
struct BoundDevice
{
    QString name; ///< the router's device name (`right.vibro`)
    QString uri;
    QString model;
    TransportStatus status;
};

/**
 * The devices of a session: what is present (serial ports, HID bands, sound card outputs,
 * configured virtual and UDP addresses), hot-plug by polling that list, and the bindings of the
 * router's device names to transports, which reconnect by themselves. Closing (or destroying) the
 * manager stops every device.
 */
class DeviceManager
{
public:
    DeviceManager();
    ~DeviceManager();
    DeviceManager(const DeviceManager &) = delete;
    DeviceManager &operator=(const DeviceManager &) = delete;

    /** Adds an address that cannot be discovered (virtual, UDP) to the listing. */
    void addConfigured(const QString &uri);
    /** The addresses added with addConfigured(), in the order they came. */
    QStringList configured() const { return m_configured; }
    /**
     * Everything present now: what each TransportScheme lists (serial ports, HID bands,
     * sound card outputs, …), then the configured addresses.
     */
    std::vector<PortInfo> present() const;
    /**
     * Hot-plug: lists again and reports the URIs that appeared and went since the last
     * call (the first call reports everything as added). True when something changed.
     */
    bool poll(QStringList *added, QStringList *removed);

    /**
     * Binds a router device name to a URI driving `model`: makes and opens its transport.
     * A band that is not there yet is kept and connected when it appears; false with
     * `error` only for a bad URI. Binding a name again replaces its transport.
     */
    bool bind(const QString &name, const QString &uri, DeviceModelPtr model, QString *error);
    /** Stops and closes the name's transport. */
    void unbind(const QString &name);
    /** The transport bound to `name`, or null. */
    Transport *transport(const QString &name) const;
    /**
     * The same, shared: for a user on another thread (an audition), whom a rebinding on
     * this one must not leave with a freed transport. One unbound stays closed.
     */
    std::shared_ptr<Transport> sharedTransport(const QString &name) const;
    QStringList boundNames() const;
    std::vector<BoundDevice> status() const;

    /** Arms or disarms every bound device (real bands start disarmed). */
    void armAll(bool armed);
    void stopAll();

    /** Splits `NAME=URI` (the --bind option); false with a reason. */
    static bool parseBinding(const QString &text, QString *name, QString *uri, QString *error);

private:
    QStringList m_configured;
    QStringList m_lastListed;
    std::map<QString, std::shared_ptr<Transport>> m_bound;
};

} // namespace semhap
