// SPDX-License-Identifier: MIT
#include "streamsink.h"

#include "router.h"

namespace semhap {

StreamSink::StreamSink(const Router &router, QIODevice *events, QIODevice *deviceFrames)
    : m_writeEvents(events), m_writeFrames(deviceFrames), m_events(events),
      m_deviceFrames(deviceFrames)
{
    QStringList devices;
    for (int d = 0; d < router.player().deviceCount(); ++d)
        devices.append(router.player().deviceName(d));
    m_events.setNodeNames(router.nodeIds());
    m_deviceFrames.setDeviceNames(devices);
}

void StreamSink::onEvent(const SemanticEvent &event)
{
    if (m_writeEvents)
        m_events.write(event);
}

void StreamSink::onDeviceFrame(const DeviceFrame &frame)
{
    if (m_writeFrames)
        m_deviceFrames.write(frame);
}

} // namespace semhap
