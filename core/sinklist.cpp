// SPDX-License-Identifier: MIT
#include "sinklist.h"

namespace semhap {

SinkList::SinkList(std::initializer_list<PipelineSink *> sinks)
{
    for (PipelineSink *sink : sinks)
        add(sink);
}

void SinkList::add(PipelineSink *sink)
{
    if (sink)
        m_sinks.push_back(sink);
}

void SinkList::onEvent(const SemanticEvent &event)
{
    for (PipelineSink *sink : m_sinks)
        sink->onEvent(event);
}

void SinkList::onDeviceFrame(const DeviceFrame &frame)
{
    for (PipelineSink *sink : m_sinks)
        sink->onDeviceFrame(frame);
}

void SinkList::onNodeActivity(const NodeActivity &activity)
{
    for (PipelineSink *sink : m_sinks)
        sink->onNodeActivity(activity);
}

} // namespace semhap
