// SPDX-License-Identifier: MIT
#include "pipeline.h"

#include <algorithm>
#include <cmath>

namespace semhap {

namespace {

// Device instants are rounded to the nanosecond; a frame "at" an instant may differ from it
// by floating-point noise.
constexpr double TimeEpsilon = 1e-9;

} // namespace

Pipeline::Pipeline(std::unique_ptr<Router> router) : m_router(std::move(router)) {}

void Pipeline::process(const ContactFrame &frame, PipelineSink &sink)
{
    const bool finite = std::isfinite(frame.t);
    if (!m_router->isStarted()) {
        m_now = finite ? frame.t : 0.0;
        m_router->start(m_now);
    }
    // A frame older than "now" (another gripper lagging) still runs its detectors, but the
    // clock does not go back: its events act at "now".
    const double t = finite ? std::max(frame.t, m_now) : m_now;
    advance(t, false, sink);
    m_now = t;
    m_events.clear();
    m_router->process(frame, m_events);
    for (const SemanticEvent &event : m_events)
        sink.onEvent(event);
    reportActivity(sink);
}

void Pipeline::flush(PipelineSink &sink)
{
    if (m_router->isStarted())
        advance(m_now, true, sink);
}

void Pipeline::endAll(PipelineSink &sink)
{
    if (!m_router->isStarted())
        return;
    m_events.clear();
    m_router->endAll(m_now, m_events);
    for (const SemanticEvent &event : m_events)
        sink.onEvent(event);
    reportActivity(sink);
}

void Pipeline::setRouter(std::unique_ptr<Router> router, PipelineSink &sink)
{
    const bool started = m_router->isStarted();
    endAll(sink);
    m_router = std::move(router);
    if (started)
        m_router->start(m_now);
}

void Pipeline::reportActivity(PipelineSink &sink)
{
    for (int node : m_router->activityChanges())
        sink.onNodeActivity(m_router->activity()[size_t(node)]);
    m_router->clearActivityChanges();
}

void Pipeline::advance(double t, bool inclusive, PipelineSink &sink)
{
    const double limit = inclusive ? t + TimeEpsilon : t - TimeEpsilon;
    Player &player = m_router->player();
    player.skipBefore(limit, MaxInstantsPerGap);
    DeviceFrame frame;
    for (;;) {
        const double timer = m_router->nextTimer();
        const double instant = player.nextInstant();
        // A timer due at an instant acts before it is rendered, like a frame at that time.
        if (timer <= instant && timer <= limit) {
            // A held-back end reaching a compose node raises a message of its own.
            m_events.clear();
            m_router->fireTimers(timer, m_events);
            for (const SemanticEvent &event : m_events)
                sink.onEvent(event);
            reportActivity(sink);
        } else if (instant <= limit) {
            player.renderNext(&frame);
            sink.onDeviceFrame(frame);
        } else {
            return;
        }
    }
}

} // namespace semhap
