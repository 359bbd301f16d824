// SPDX-License-Identifier: MIT
#pragma once

#include "contactframe.h"
#include "pipeline.h"
#include "semanticevent.h"
#include "spscring.h"

#include <atomic>

namespace semhap {

class RunHistory;

/**
 * The handover from the pipeline thread to the GUI: one lock-free queue per stream. The
 * pipeline pushes and never waits — when the GUI falls behind, the newest values are
 * dropped and counted — and the GUI drains everything into a RunHistory at display rate.
 * Device frames do not come this way: the history shows what the transports sent
 * (SentFeed), not what the pipeline asked for.
 */
class RunFeed : public PipelineSink
{
public:
    /** Each queue holds `capacity` values: a few seconds of a busy run. */
    explicit RunFeed(std::size_t capacity = 1 << 15);

    // Pipeline thread.
    void push(const ContactFrame &frame);
    void onEvent(const SemanticEvent &event) override;
    void onNodeActivity(const NodeActivity &activity) override;

    // GUI thread.
    /** Moves everything queued into `history`; does not commit it. */
    void drainInto(RunHistory &history);
    /** Drops everything queued (the history shows something else, a replay). */
    void discard();
    /** Values refused because a queue was full, since construction. */
    quint64 dropped() const { return m_dropped.load(std::memory_order_relaxed); }

private:
    void count(bool pushed);

    SpscRing<ContactFrame> m_frames;
    SpscRing<SemanticEvent> m_events;
    SpscRing<NodeActivity> m_activity;
    std::atomic<quint64> m_dropped{0};
};

} // namespace semhap
