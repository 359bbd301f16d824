// SPDX-License-Identifier: MIT
#pragma once

#include "deviceframe.h"
#include "eventbuffer.h"
#include "router.h"

#include <memory>

namespace semhap {

/** Receives what a pipeline produces, as it is produced. */
class PipelineSink
{
public:
    virtual ~PipelineSink() = default;
    virtual void onEvent(const SemanticEvent &) {}
    virtual void onDeviceFrame(const DeviceFrame &) {}
    /** A router node's activity changed (what it passes on): the editor's live wires. */
    virtual void onNodeActivity(const NodeActivity &) {}
};

/**
 * Contact frames in, semantic events and device frames out, on a clock the frames drive:
 * a frame at t first renders every device instant before t (and fires due timers, in time
 * order), then runs the detectors and the router. flush() renders the instants at the last
 * frame's time, once every gripper's frame of that tick is in. Deterministic; the per-tick
 * path allocates nothing. Whatever its frames' times, a call does bounded work: a jump of
 * the clock renders at most MaxInstantsPerGap instants per device (sources refuse such
 * jumps first: ContactFrameParser's maximum gap), and a non-finite time is taken as "now".
 */
class Pipeline
{
public:
    explicit Pipeline(std::unique_ptr<Router> router);

    /** Processes one contact frame; the first one starts the clocks at its t. */
    void process(const ContactFrame &frame, PipelineSink &sink);
    /** Renders the device instants up to and including the latest frame's time. */
    void flush(PipelineSink &sink);
    /**
     * Swaps in another router mid-run (the editor's Apply): the old one's active messages
     * end now, their events going to `sink`, and the new one starts now, on the same clock,
     * so a device it keeps goes on from the next instant.
     */
    void setRouter(std::unique_ptr<Router> router, PipelineSink &sink);
    /**
     * Events lost because one tick made more than EventBuffer::Capacity of them (a router
     * with very many detectors on one gripper); 0 in any sane design. Callers report it.
     */
    int droppedEvents() const { return m_events.dropped(); }

    Router &router() { return *m_router; }
    const Router &router() const { return *m_router; }
    /** The latest frame time seen (the pipeline's "now"). */
    double now() const { return m_now; }
    /**
     * Ends every active message now (a source fell silent): their End events go to `sink`;
     * the devices play out what follows as the next frames advance the clock.
     */
    void endAll(PipelineSink &sink);

    /** Device instants rendered at most per device across one jump of the clock. */
    static constexpr long long MaxInstantsPerGap = 1000;

private:
    void advance(double t, bool inclusive, PipelineSink &sink);
    /** Hands the sink the nodes whose activity changed, after events or timers. */
    void reportActivity(PipelineSink &sink);

    std::unique_ptr<Router> m_router;
    EventBuffer m_events;
    double m_now = 0.0;
};

} // namespace semhap
