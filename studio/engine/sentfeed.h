// SPDX-License-Identifier: MIT
#pragma once

#include "deviceframe.h"

#include <QStringList>

#include <cstdint>
#include <memory>
#include <vector>

namespace semhap {

class DeviceManager;
class RunHistory;
class Transport;

/**
 * What the running router's devices were sent, into the history the meters and plots read:
 * per router device, the transport bound to its name and how far its SentLog was read. So
 * the readouts show the frames as the transports sent them — clamped, scaled by the gain,
 * capped, zero while disarmed — whoever sent them: the pipeline, an audition, a stop-all.
 * GUI thread; rebind whenever a binding changes. A transport read is held shared, so one a
 * rebinding replaced stays readable until the next rebind, and a new one at the same address
 * is never taken for it.
 */
class SentFeed
{
public:
    /** Reads the transports bound to `devices` (the router's names, by index) from now on. */
    void start(const QStringList &devices, const DeviceManager &manager);
    /**
     * Reads the transports bound to `devices` now: those read before go on from where they
     * were, the others from now on.
     */
    void rebind(const QStringList &devices, const DeviceManager &manager);
    /** Moves what was sent since the last call into `history`; does not commit it. */
    void drainInto(RunHistory &history);
    /** Frames a transport sent that were overwritten before they could be read. */
    quint64 lost() const { return m_lost; }

private:
    struct Reader
    {
        std::shared_ptr<const Transport> transport;
        std::uint64_t next = 0; ///< running count of the next frame to read
    };

    std::vector<Reader> m_readers; ///< by router device index
    std::vector<DeviceFrame> m_frames;
    quint64 m_lost = 0;
};

} // namespace semhap
