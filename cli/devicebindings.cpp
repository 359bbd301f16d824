// SPDX-License-Identifier: MIT
#include "devicebindings.h"

#include "devicemanager.h"
#include "player.h"

namespace semhap {

bool bindDevices(const QStringList &bindings, const Player &player, DeviceManager &manager,
                 QString *message, bool *usage)
{
    *usage = false;
    for (const QString &binding : bindings) {
        QString name;
        QString uri;
        if (!DeviceManager::parseBinding(binding, &name, &uri, message)) {
            *usage = true;
            return false;
        }
        const int device = player.deviceIndex(name);
        if (device < 0) {
            *message =
                QStringLiteral("--bind %1: the router has no device '%2'").arg(binding, name);
            return false;
        }
        manager.bind(name, uri, std::make_shared<const DeviceModel>(player.deviceModel(device)),
                     message);
    }
    return true;
}

} // namespace semhap
