// SPDX-License-Identifier: MIT
#pragma once

#include "deviceframe.h"
#include "devicemodel.h"
#include "protocol.h"
#include "safetyfilter.h"
#include "sentlog.h"

#include <QString>

#include <atomic>
#include <cstdint>

namespace semhap {

/** Where a router device's link stands: what every readout of a device calls it. */
enum class LinkState
{
    NotBound,     ///< no transport is bound to the name
    Disconnected, ///< the link is down (retried)
    Connecting,   ///< the link is open, the device has not answered lately
    Connected,    ///< the link is open and the device answers
};

/** A transport's health, as the device manager and `semhap devices` show it. */
struct TransportStatus
{
    bool connected = false;  ///< the link is open (a port, a socket, a HID handle)
    bool responding = false; ///< the device answered within the last 500 ms
    bool armed = false;
    double framesPerSecond = 0.0;    ///< set-values frames written, over the last second
    std::uint32_t framesSent = 0;    ///< set-values frames written
    std::uint32_t framesSkipped = 0; ///< stale frames replaced before they were written
    std::uint32_t errors = 0;        ///< write errors and garbled frames from the device
    double roundTripMs = -1.0;       ///< from the latest heartbeat reply; < 0 before one
    /** Sound cards: from send() to the sample that carries the latest frame; < 0 before one */
    double latencyMs = -1.0;
    std::uint32_t reconnects = 0;  ///< times the link was opened again after a loss
    protocol::DeviceStatus device; ///< the device's own counters (latest status)
    QString identity;              ///< model name from the identify reply, if any
    QString lastError;

    /** The link's state from `connected` and `responding` (never NotBound). */
    LinkState state() const
    {
        if (!connected)
            return LinkState::Disconnected;
        return responding ? LinkState::Connected : LinkState::Connecting;
    }
};

/**
 * Where a device's frames go: one interface for the virtual, serial, UDP and HID links and
 * sound cards, so the pipeline, the device manager and tests drive them alike. send() never
 * blocks (latest value wins); stopAll() always gets through; safety (clamp, gain, inflation
 * limit, armed) is applied inside, whatever the caller did, and what goes out is kept in
 * sent().
 */
class Transport
{
public:
    explicit Transport(DeviceModelPtr model);
    virtual ~Transport();
    Transport(const Transport &) = delete;
    Transport &operator=(const Transport &) = delete;

    /** The URI this transport was made from (`serial:/dev/ttyACM0`). */
    virtual QString uri() const = 0;
    /** Starts the transport; false with `error` when it cannot even start. */
    virtual bool open(QString *error) = 0;
    /** Sends a stop-all and stops; safe to call twice. */
    virtual void close() = 0;
    /** Hands the latest values over (model units); returns at once. */
    virtual void send(const DeviceFrame &frame) = 0;
    /** Every channel to zero now, bypassing the latest-value slot, repeated. */
    virtual void stopAll() = 0;
    virtual TransportStatus status() const = 0;

    const DeviceModel &model() const { return *m_model; }
    const DeviceModelPtr &modelPtr() const { return m_model; }
    /** A transport that is not armed sends zeros: real bands start disarmed. */
    void setArmed(bool armed) { m_armed.store(armed); }
    bool isArmed() const { return m_armed.load(); }
    /** Master gain 0..1 applied to every channel. */
    void setGain(double gain) { m_gain.store(gain); }
    double gain() const { return m_gain.load(); }
    /**
     * The frames sent, as the device got them (after safety; a stop-all's rest values
     * too), with the `t` their caller gave: what meters and plots show.
     */
    const SentLog &sent() const { return m_sent; }

protected:
    DeviceModelPtr m_model;
    SentLog m_sent; ///< each transport appends where its values leave
    std::atomic<bool> m_armed{false};
    std::atomic<double> m_gain{1.0};
};

} // namespace semhap
