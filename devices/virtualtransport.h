// SPDX-License-Identifier: MIT
#pragma once

#include "transport.h"

#include <array>
#include <mutex>

namespace semhap {

/**
 * The embedded default: no hardware, it keeps the latest frames (after safety) for
 * previews and monitors. Armed from the start. No thread: send() takes a tiny mutex that readers
 * hold only to copy.
 */
class VirtualTransport : public Transport
{
public:
    /** Frames kept for monitors. */
    static constexpr int HistorySize = 256;

    VirtualTransport(const QString &name, DeviceModelPtr model);

    QString uri() const override;
    bool open(QString *error) override;
    void close() override;
    void send(const DeviceFrame &frame) override;
    void stopAll() override;
    TransportStatus status() const override;

    /** The latest frame as a device would have received it. */
    DeviceFrame lastFrame() const;
    /** Up to HistorySize frames, oldest first. */
    std::vector<DeviceFrame> history() const;
    /** Stop-alls received (tests check that one got through). */
    int stopCount() const;

private:
    void store(const DeviceFrame &frame);

    QString m_name;
    SafetyFilter m_safety;
    mutable std::mutex m_mutex;
    std::array<DeviceFrame, HistorySize> m_history{};
    int m_count = 0;
    int m_stops = 0;
    // The frame rate the status reports, as a real link counts it: frames over the last
    // whole second, and what the current window has seen once it runs past a second.
    double m_windowStart = 0.0;
    int m_windowCount = 0;
    double m_rate = 0.0;
    bool m_open = false;
};

} // namespace semhap
