// SPDX-License-Identifier: MIT
#pragma once

#include "pipeline.h"

#include <vector>

namespace semhap {

class DeviceManager;
class Player;
class Transport;

/**
 * Sends a pipeline's device frames to the transports bound to their device names. Put it
 * in a SinkList beside the writers and recorders that want the same frames.
 * Never blocks: a transport's send() only fills its latest-value slot.
 */
class DeviceOutputSink : public PipelineSink
{
public:
    /** Looks the player's device names up in `manager` once; bind before making the sink. */
    DeviceOutputSink(const Player &player, const DeviceManager &manager);

    void onDeviceFrame(const DeviceFrame &frame) override;

    /** How many of the player's devices have a transport. */
    int boundCount() const;

private:
    std::vector<Transport *> m_transports; ///< by player device index; null when unbound
};

} // namespace semhap
