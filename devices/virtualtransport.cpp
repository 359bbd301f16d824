// SPDX-License-Identifier: MIT
#include "virtualtransport.h"

#include "deviceuri.h"
#include "monotonic.h"

namespace semhap {

VirtualTransport::VirtualTransport(const QString &name, DeviceModelPtr model)
    : Transport(model), m_name(name), m_safety(model)
{
    // Nothing physical to protect: previews play as soon as they are asked to.
    setArmed(true);
}

QString VirtualTransport::uri() const
{
    return DeviceUri::virtualFor(m_name);
}

bool VirtualTransport::open(QString *)
{
    std::lock_guard<std::mutex> lock(m_mutex);
    m_open = true;
    return true;
}

void VirtualTransport::close()
{
    stopAll();
    std::lock_guard<std::mutex> lock(m_mutex);
    m_open = false;
}

void VirtualTransport::send(const DeviceFrame &frame)
{
    DeviceFrame safe = frame;
    safe.channelCount = m_model->channelCount();
    std::lock_guard<std::mutex> lock(m_mutex);
    m_safety.apply(frame.values.data(), frame.channelCount, monotonicSeconds(), gain(), isArmed(),
                   safe.values.data());
    store(safe);
}

void VirtualTransport::stopAll()
{
    std::lock_guard<std::mutex> lock(m_mutex);
    m_safety.reset();
    // At rest from the latest time it was sent anything.
    store(m_model->restFrame(m_sent.last().t));
    ++m_stops;
}

void VirtualTransport::store(const DeviceFrame &frame)
{
    m_sent.append(frame);
    m_rate.record(m_sent.count(), monotonicSeconds());
}

TransportStatus VirtualTransport::status() const
{
    std::lock_guard<std::mutex> lock(m_mutex);
    TransportStatus s;
    s.connected = m_open;
    s.responding = m_open;
    s.armed = isArmed();
    const std::uint64_t count = m_sent.count();
    s.framesSent = std::uint32_t(count);
    s.framesPerSecond = m_rate.perSecond(count, monotonicSeconds());
    s.identity = m_model->name();
    return s;
}

int VirtualTransport::stopCount() const
{
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_stops;
}

} // namespace semhap
