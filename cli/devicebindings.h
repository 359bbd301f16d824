// SPDX-License-Identifier: MIT
#pragma once

#include <QString>
#include <QStringList>

namespace semhap {

class DeviceManager;
class Player;

/**
 * Binds the `--bind NAME=URI` options of `route` and `run` in `manager`, with each
 * device's model from the router's player. False with a one-line `message`; `usage` is
 * set when the option itself is malformed (exit 2) rather than naming an unknown device.
 */
bool bindDevices(const QStringList &bindings, const Player &player, DeviceManager &manager,
                 QString *message, bool *usage);

} // namespace semhap
