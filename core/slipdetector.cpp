// SPDX-License-Identifier: MIT
#include "slipdetector.h"

#include "detectorparams.h"

#include <algorithm>
#include <cmath>

namespace semhap {

namespace {

// Every parameter's JSON key and field, listed once for reading, writing and checking.
DetectorParams fields(SlipDetector::Params &p)
{
    const QString contacts = QStringLiteral("contacts");
    return {
        {ParamSpec::number(QStringLiteral("grasp"), 0, QStringLiteral("N"),
                           QStringLiteral("T_grasp: contacts count as a grasp while the grip "
                                          "force is above it"))
             .atLeast(0),
         &p.grasp},
        {ParamSpec::number(QStringLiteral("loss"), 0, contacts,
                           QStringLiteral("N_loss: a slip is warned of while a grasp has fewer "
                                          "contacts than this")),
         &p.loss},
        {ParamSpec::number(QStringLiteral("min"), 0, contacts,
                           QStringLiteral("N_min: the contact count at which the slip warning "
                                          "reaches full intensity")),
         &p.min},
        {hysteresisSpec(contacts, QStringLiteral("Slipping holds until the contacts rise this "
                                                 "far above loss")),
         &p.hysteresis},
        {minDurationSpec(), &p.minDuration}};
}

} // namespace

bool SlipDetector::Params::read(const QJsonObject &json, QString *key, QString *reason)
{
    return readDetectorParams(json, fields(*this), key, reason);
}

std::vector<ParamSpec> SlipDetector::Params::specs()
{
    Params defaults;
    return detectorParamSpecs(fields(defaults));
}

QJsonObject SlipDetector::Params::toJson() const
{
    Params copy = *this;
    return detectorParamsToJson(fields(copy));
}

bool SlipDetector::Params::validate(QString *key, QString *reason) const
{
    Params copy = *this;
    if (!checkDetectorParams(fields(copy), key, reason))
        return false;
    if (!(min < loss)) {
        return paramError(key, reason, QStringLiteral("loss"),
                          QStringLiteral("must be greater than min (%1), got %2")
                              .arg(formatNumber(min), formatNumber(loss)));
    }
    return true;
}

SlipDetector::Params SlipDetector::Params::fittedTo(const GripperTraits &gripper) const
{
    // The reference gripper runs the values as written, fractions included.
    if (gripper.fullContacts < 1 || gripper.fullContacts == ReferenceFullContacts)
        return *this;
    const double scale = double(gripper.fullContacts) / ReferenceFullContacts;
    // N is a whole count: N < x exactly when N < ceil(x), N <= x exactly when N <= floor(x).
    // So slip begins below ceil(loss), ends from ceil(loss + hysteresis) and is at full
    // intensity up to floor(min), each at the share of a full grasp the written value has;
    // floor(min) <= min < loss <= ceil(loss) keeps min < loss.
    Params fitted = *this;
    fitted.loss = std::ceil(loss * scale);
    fitted.min = std::floor(min * scale);
    fitted.hysteresis = std::ceil((loss + hysteresis) * scale) - fitted.loss;
    return fitted;
}

SlipDetector::SlipDetector(int node, Gripper gripper, const Params &params, DetectorKind kind)
    : Detector(node, gripper, kind), m_params(params)
{
    m_grasp.configure(gripper, node, kind, Message::Grasp, Category::Confirmation,
                      params.minDuration);
    m_slip.configure(gripper, node, kind, Message::Slip, Category::Exception, params.minDuration);
}

void SlipDetector::update(const ContactFrame &frame, EventBuffer &out)
{
    if (frame.gripper != m_gripper)
        return;
    const int actor = frame.left.actor;
    if (actor >= 0 && actor == frame.right.actor) {
        if (actor != m_actor) {
            m_actor = actor;
            reset(frame.t, out);
        }
        if (frame.totalForce() > m_params.grasp) {
            m_stable = true;
            const double contacts = frame.totalContacts();
            // Slipping holds up to loss + hysteresis; with 0 this is the spec's N < loss.
            const double lossThreshold =
                m_slip.isActive() ? m_params.loss + m_params.hysteresis : m_params.loss;
            const double intensity =
                std::clamp((m_params.loss - contacts) / (m_params.loss - m_params.min), 0.0, 1.0);
            m_grasp.update(frame.t, true, 1.0, out);
            m_slip.update(frame.t, contacts < lossThreshold, intensity, out);
        } else {
            reset(frame.t, out);
        }
    } else if (m_actor >= 0) {
        m_actor = -1;
        reset(frame.t, out);
    }
}

void SlipDetector::endAll(double t, EventBuffer &out)
{
    reset(t, out);
}

void SlipDetector::clear()
{
    m_actor = -1;
    m_stable = false;
    m_grasp.clear();
    m_slip.clear();
}

bool SlipDetector::isActive(Message message, double *intensity) const
{
    const MessageTracker *tracker = message == Message::Grasp  ? &m_grasp
                                    : message == Message::Slip ? &m_slip
                                                               : nullptr;
    if (!tracker || !tracker->isActive())
        return false;
    if (intensity)
        *intensity = tracker->intensity();
    return true;
}

void SlipDetector::reset(double t, EventBuffer &out)
{
    m_stable = false;
    m_grasp.forceEnd(t, out);
    m_slip.forceEnd(t, out);
}

void SlipDetector::appendActive(double t, EventBuffer &out) const
{
    m_grasp.appendActive(t, out);
    m_slip.appendActive(t, out);
}

std::vector<SemanticEvent> SlipDetector::probes(double intensity) const
{
    return {m_grasp.probe(intensity), m_slip.probe(intensity)};
}

std::vector<DetectorLevel> SlipDetector::levels() const
{
    using L = DetectorLevel;
    return {
        {L::Quantity::Contacts, L::Meaning::ExceptionBegins, QStringLiteral("loss"),
         m_params.loss},
        {L::Quantity::Contacts, L::Meaning::FullIntensity, QStringLiteral("min"), m_params.min}};
}

} // namespace semhap
