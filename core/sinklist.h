// SPDX-License-Identifier: MIT
#pragma once

#include "pipeline.h"

#include <initializer_list>
#include <vector>

namespace semhap {

/**
 * Hands everything a pipeline produces to several sinks, in order: the one fan-out that
 * stream writers, session recorders, device outputs, the simulated operator's perception
 * and the studio's feed hang on. Sinks are added between ticks; passing values on never
 * allocates.
 */
class SinkList : public PipelineSink
{
public:
    SinkList() = default;
    /** The sinks, in the order they get each value; nulls are left out. */
    SinkList(std::initializer_list<PipelineSink *> sinks);

    void add(PipelineSink *sink);
    void clear() { m_sinks.clear(); }

    void onEvent(const SemanticEvent &event) override;
    void onDeviceFrame(const DeviceFrame &frame) override;
    void onNodeActivity(const NodeActivity &activity) override;

private:
    std::vector<PipelineSink *> m_sinks;
};

} // namespace semhap
