// SPDX-License-Identifier: MIT
#include "deviceoutputsink.h"

#include "devicemanager.h"
#include "player.h"

#include <algorithm>

namespace semhap {

DeviceOutputSink::DeviceOutputSink(const Player &player, const DeviceManager &manager)
{
    for (int d = 0; d < player.deviceCount(); ++d)
        m_transports.push_back(manager.transport(player.deviceName(d)));
}

void DeviceOutputSink::onDeviceFrame(const DeviceFrame &frame)
{
    if (frame.device >= 0 && frame.device < int(m_transports.size()) &&
        m_transports[size_t(frame.device)])
        m_transports[size_t(frame.device)]->send(frame);
}

int DeviceOutputSink::boundCount() const
{
    return int(std::count_if(m_transports.begin(), m_transports.end(),
                             [](const Transport *t) { return t != nullptr; }));
}

} // namespace semhap
