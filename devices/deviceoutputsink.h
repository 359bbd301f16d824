// SPDX-License-Identifier: MIT
#pragma once

#include "pipeline.h"

#include <vector>

namespace semhap {

class DeviceManager;
class Player;
class Transport;

/**
 * Sends a pipeline's device frames to the transports bound to their device names; every
 * frame, event and node activity also goes on to an optional next sink (the stream
 * writers, the studio's feed).
 * Never blocks: a transport's send() only fills its latest-value slot.
 */
class DeviceOutputSink : public PipelineSink
{
public:
    /** Looks the player's device names up in `manager` once; bind before making the sink. */
    DeviceOutputSink(const Player &player, const DeviceManager &manager,
                     PipelineSink *next = nullptr);

    void onEvent(const SemanticEvent &event) override;
    void onDeviceFrame(const DeviceFrame &frame) override;
    void onNodeActivity(const NodeActivity &activity) override;

    /** How many of the player's devices have a transport. */
    int boundCount() const;

private:
    std::vector<Transport *> m_transports; ///< by player device index; null when unbound
    PipelineSink *m_next;
};

} // namespace semhap
