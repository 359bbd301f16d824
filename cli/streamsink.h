// SPDX-License-Identifier: MIT
#pragma once

#include "jsonlineswriter.h"
#include "pipeline.h"

class QIODevice;

namespace semhap {

/**
 * Writes what a pipeline produces as JSON Lines, each stream to its own device (null: not
 * written); what `route`, `replay` and `listen` share, in a SinkList with their other sinks.
 */
class StreamSink : public PipelineSink
{
public:
    StreamSink(const Router &router, QIODevice *events, QIODevice *deviceFrames);

    void onEvent(const SemanticEvent &event) override;
    void onDeviceFrame(const DeviceFrame &frame) override;

private:
    bool m_writeEvents;
    bool m_writeFrames;
    JsonLinesWriter m_events;
    JsonLinesWriter m_deviceFrames;
};

} // namespace semhap
