// SPDX-License-Identifier: MIT
#pragma once

#include "framedecoder.h"
#include "link.h"
#include "transport.h"

#include <memory>
#include <mutex>
#include <thread>

namespace semhap {

/**
 * A Transport over a Link, on its own I/O thread: the pipeline drops values into a
 * one-frame slot (a tiny mutex, never held across I/O) and pokes an eventfd; the thread
 * writes the newest values, a heartbeat every 100 ms, a status request every second,
 * reads the device's replies, and reopens a lost link every 100 ms.
 */
class LinkTransport : public Transport
{
public:
    static constexpr double HeartbeatPeriod = 0.1;
    static constexpr double ReconnectPeriod = 0.1;
    static constexpr int StopRepeats = 3;

    LinkTransport(std::unique_ptr<Link> link, DeviceModelPtr model);
    ~LinkTransport() override;

    QString uri() const override;
    /**
     * Starts the I/O thread after a first attempt to open the link, whose result it
     * returns; the thread keeps trying either way (a band plugged in later is found).
     */
    bool open(QString *error) override;
    void close() override;
    void send(const DeviceFrame &frame) override;
    void stopAll() override;
    TransportStatus status() const override;

    /** Inflation limit of the safety filter; set before open(). */
    void setInflationLimit(const InflationLimit &limit) { m_safety.setInflationLimit(limit); }

private:
    void run();
    bool connect(QString *error);
    void disconnect(const QString &reason);
    void wait(double until);
    void writeFrame(const std::uint8_t *data, int size);
    void writeMessage(protocol::MessageType type);
    void writeValues(double now);
    void writeStops();
    void readReplies(double now);
    void onMessage(const protocol::Message &message, double now);

    std::unique_ptr<Link> m_link;
    SafetyFilter m_safety;  ///< I/O thread only
    FrameDecoder m_decoder; ///< I/O thread only
    std::thread m_thread;
    int m_wakeFd = -1;
    std::atomic<bool> m_quit{false};
    std::atomic<int> m_stopRequests{0};
    bool m_linkOpen = false;   ///< I/O thread only
    bool m_identified = false; ///< I/O thread only: an identify reply came on this connection
    std::uint16_t m_sequence = 0;
    std::uint32_t m_linkErrors = 0; ///< I/O thread only

    mutable std::mutex m_slotMutex; ///< guards the two fields below only
    DeviceFrame m_slot;
    bool m_slotFresh = false;

    mutable std::mutex m_statusMutex;
    TransportStatus m_status;
    double m_lastReply = -1.0;
};

} // namespace semhap
