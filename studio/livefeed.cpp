// SPDX-License-Identifier: MIT
#include "livefeed.h"

#include "livehistory.h"

namespace semhap {

LiveFeed::LiveFeed(std::size_t capacity)
    : m_frames(capacity), m_events(capacity), m_deviceFrames(capacity), m_activity(capacity)
{}

void LiveFeed::count(bool pushed)
{
    if (!pushed)
        m_dropped.fetch_add(1, std::memory_order_relaxed);
}

void LiveFeed::push(const ContactFrame &frame)
{
    count(m_frames.push(frame));
}

void LiveFeed::onEvent(const SemanticEvent &event)
{
    count(m_events.push(event));
}

void LiveFeed::onDeviceFrame(const DeviceFrame &frame)
{
    count(m_deviceFrames.push(frame));
}

void LiveFeed::onNodeActivity(const NodeActivity &activity)
{
    count(m_activity.push(activity));
}

void LiveFeed::drainInto(LiveHistory &history)
{
    ContactFrame frame;
    while (m_frames.pop(&frame))
        history.append(frame);
    SemanticEvent event;
    while (m_events.pop(&event))
        history.append(event);
    DeviceFrame deviceFrame;
    while (m_deviceFrames.pop(&deviceFrame))
        history.append(deviceFrame);
    NodeActivity activity;
    while (m_activity.pop(&activity))
        history.append(activity);
}

void LiveFeed::discard()
{
    ContactFrame frame;
    while (m_frames.pop(&frame)) {
    }
    SemanticEvent event;
    while (m_events.pop(&event)) {
    }
    DeviceFrame deviceFrame;
    while (m_deviceFrames.pop(&deviceFrame)) {
    }
    NodeActivity activity;
    while (m_activity.pop(&activity)) {
    }
}

} // namespace semhap
