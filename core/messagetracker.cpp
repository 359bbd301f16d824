// SPDX-License-Identifier: MIT
#include "messagetracker.h"

namespace semhap {

void MessageTracker::configure(Gripper gripper, int node, DetectorKind detector, Message message,
                               Category category, double minDuration)
{
    m_template = SemanticEvent();
    m_template.gripper = gripper;
    m_template.node = node;
    m_template.detector = detector;
    m_template.message = message;
    m_template.category = category;
    m_minDuration = minDuration;
    clear();
}

void MessageTracker::update(double t, bool condition, double intensity, EventBuffer &out)
{
    if (!condition) {
        m_pending = false;
        if (m_active) {
            m_active = false;
            append(t, EventPhase::End, out);
        }
        return;
    }
    if (m_active) {
        if (intensity != m_intensity) {
            m_intensity = intensity;
            append(t, EventPhase::Update, out);
        }
        return;
    }
    if (!m_pending) {
        m_pending = true;
        m_since = t;
    }
    if (t - m_since >= m_minDuration) {
        m_pending = false;
        m_active = true;
        m_intensity = intensity;
        append(t, EventPhase::Begin, out);
    }
}

void MessageTracker::forceEnd(double t, EventBuffer &out)
{
    m_pending = false;
    if (m_active) {
        m_active = false;
        append(t, EventPhase::End, out);
    }
}

void MessageTracker::clear()
{
    m_active = false;
    m_pending = false;
    m_since = 0.0;
    m_intensity = 1.0;
}

void MessageTracker::appendActive(double t, EventBuffer &out) const
{
    if (m_active)
        append(t, EventPhase::Begin, out);
}

SemanticEvent MessageTracker::probe(double intensity) const
{
    SemanticEvent event = m_template;
    event.t = 0.0;
    event.phase = EventPhase::Begin;
    event.intensity = intensity;
    return event;
}

void MessageTracker::append(double t, EventPhase phase, EventBuffer &out) const
{
    SemanticEvent event = m_template;
    event.t = t;
    event.phase = phase;
    event.intensity = m_intensity;
    out.push(event);
}

} // namespace semhap
