// SPDX-License-Identifier: MIT
#pragma once

#include "eventbuffer.h"
#include "semanticevent.h"

namespace semhap {

/**
 * The lifecycle of one message of one detector, so every detector turns "condition and
 * intensity this tick" into begin/update/end events the same way (spec section 2).
 * The detector decides the condition (thresholds, hysteresis); the tracker only delays a
 * begin until the condition has held for `minDuration` seconds, when that is set.
 */
class MessageTracker
{
public:
    /** Sets the fields every event of this message carries; call once, before update(). */
    void configure(Gripper gripper, int node, DetectorKind detector, Message message,
                   Category category, double minDuration = 0.0);

    /** The gripper the next events carry (a composed message takes its input's). */
    void setGripper(Gripper gripper) { m_template.gripper = gripper; }

    /**
     * Feeds one tick: emits begin (inactive to active, with `intensity`), update (active,
     * intensity changed, compared exactly) or end (active to inactive, last intensity).
     */
    void update(double t, bool condition, double intensity, EventBuffer &out);
    /** Ends the message now if active and cancels a pending begin (a detector reset). */
    void forceEnd(double t, EventBuffer &out);
    /** Back to inactive without emitting anything. */
    void clear();
    /**
     * Appends a begin at `t` with the intensity now if the message is active: how a stream
     * that starts now (a recording started mid-grasp) learns it is open.
     */
    void appendActive(double t, EventBuffer &out) const;
    /** A begin of this message at t = 0 with `intensity`: what Router::messageRoutes sends. */
    SemanticEvent probe(double intensity) const;

    bool isActive() const { return m_active; }
    /** Whether the condition holds but has not yet held for minDuration. */
    bool isPending() const { return m_pending; }
    /** The intensity of the last begin or update; meaningful while active. */
    double intensity() const { return m_intensity; }
    double minDuration() const { return m_minDuration; }

private:
    void append(double t, EventPhase phase, EventBuffer &out) const;

    SemanticEvent m_template;
    double m_minDuration = 0.0;
    double m_since = 0.0; ///< when the pending condition started to hold
    double m_intensity = 1.0;
    bool m_active = false;
    bool m_pending = false;
};

} // namespace semhap
