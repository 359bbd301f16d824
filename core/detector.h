// SPDX-License-Identifier: MIT
#pragma once

#include "contactframe.h"
#include "eventbuffer.h"
#include "semanticevent.h"

#include <QJsonObject>
#include <QString>

#include <memory>
#include <vector>

namespace semhap {

/** A level a detector compares a frame's quantity with: what the plots draw. */
struct DetectorLevel
{
    /** The frame's quantity it is a level of: the force F (N) or the contact count N. */
    enum class Quantity
    {
        Force,
        Contacts
    };
    /** What happens at it: a confirmation or an exception begins, or intensity is full. */
    enum class Meaning
    {
        ConfirmationBegins,
        ExceptionBegins,
        FullIntensity
    };
    Quantity quantity = Quantity::Force;
    Meaning meaning = Meaning::ConfirmationBegins;
    QString name; ///< the parameter's, as the router file and the event log spell it
    double value = 0.0;
};

/**
 * A stateful state estimator on one gripper's contact frames (spec section 2). Each update
 * appends the begin/update/end events of that tick to the buffer, in the spec's order.
 * Plain values: no Qt event loop, no allocation in update().
 */
class Detector
{
public:
    Detector(int node, Gripper gripper, DetectorKind kind)
        : m_node(node), m_gripper(gripper), m_kind(kind)
    {}
    virtual ~Detector() = default;

    /** The kind its events carry: its node type's (RouterNodeType::detectorKind). */
    DetectorKind kind() const { return m_kind; }
    /**
     * Consumes one frame and appends this tick's events. Frames of the other gripper are
     * ignored, so a pipeline may hand every frame to every detector.
     */
    virtual void update(const ContactFrame &frame, EventBuffer &out) = 0;
    /** Ends every active message at time t (router swap, end of a run). */
    virtual void endAll(double t, EventBuffer &out) = 0;
    /** Back to the initial state, silently. */
    virtual void clear() = 0;
    /** Whether `message` is active now, and its intensity. */
    virtual bool isActive(Message message, double *intensity = nullptr) const = 0;
    /** Appends a begin at t for each message active now (MessageTracker::appendActive). */
    virtual void appendActive(double t, EventBuffer &out) const = 0;
    /** A begin of each message it may send, at `intensity` (Router::messageRoutes). */
    virtual std::vector<SemanticEvent> probes(double intensity) const = 0;
    /** The levels it runs with, for the plots; none by default. */
    virtual std::vector<DetectorLevel> levels() const { return {}; }

    int node() const { return m_node; }
    Gripper gripper() const { return m_gripper; }

protected:
    int m_node;
    Gripper m_gripper;
    DetectorKind m_kind;
};

} // namespace semhap
