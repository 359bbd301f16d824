// SPDX-License-Identifier: MIT
#pragma once

#include "framerate.h"
#include "transport.h"

#include <cstdint>
#include <mutex>

namespace semhap {

/**
 * The embedded default: no hardware; what it sends (after safety) is only kept in sent(),
 * for previews and monitors. Armed from the start. No thread: send() applies the safety
 * filter under a tiny mutex.
 */
class VirtualTransport : public Transport
{
public:
    VirtualTransport(const QString &name, DeviceModelPtr model);

    QString uri() const override;
    bool open(QString *error) override;
    void close() override;
    void send(const DeviceFrame &frame) override;
    void stopAll() override;
    TransportStatus status() const override;

    /** Stop-alls received (tests check that one got through). */
    int stopCount() const;

private:
    /** Sends `frame` (mutex held): into sent() and the rate count. */
    void store(const DeviceFrame &frame);

    QString m_name;
    SafetyFilter m_safety;
    mutable std::mutex m_mutex;
    int m_stops = 0;
    FrameRate m_rate; ///< the status's frames per second, as a real link counts them
    bool m_open = false;
};

} // namespace semhap
