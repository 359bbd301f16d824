// SPDX-License-Identifier: MIT
#include "runfeed.h"

#include "runhistory.h"

namespace semhap {

RunFeed::RunFeed(std::size_t capacity)
    : m_frames(capacity), m_events(capacity), m_activity(capacity)
{}

void RunFeed::count(bool pushed)
{
    if (!pushed)
        m_dropped.fetch_add(1, std::memory_order_relaxed);
}

void RunFeed::push(const ContactFrame &frame)
{
    count(m_frames.push(frame));
}

void RunFeed::onEvent(const SemanticEvent &event)
{
    count(m_events.push(event));
}

void RunFeed::onNodeActivity(const NodeActivity &activity)
{
    count(m_activity.push(activity));
}

void RunFeed::drainInto(RunHistory &history)
{
    ContactFrame frame;
    while (m_frames.pop(&frame))
        history.append(frame);
    SemanticEvent event;
    while (m_events.pop(&event))
        history.append(event);
    NodeActivity activity;
    while (m_activity.pop(&activity))
        history.append(activity);
}

void RunFeed::discard()
{
    ContactFrame frame;
    while (m_frames.pop(&frame)) {
    }
    SemanticEvent event;
    while (m_events.pop(&event)) {
    }
    NodeActivity activity;
    while (m_activity.pop(&activity)) {
    }
}

} // namespace semhap
