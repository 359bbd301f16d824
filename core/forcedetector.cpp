// SPDX-License-Identifier: MIT
#include "forcedetector.h"

#include "detectorparams.h"

#include <algorithm>

namespace semhap {

namespace {

// Every parameter's spec and field, listed once for reading, writing, checking and editing.
DetectorParams fields(ForceDetector::Params &p)
{
    const QString newtons = QStringLiteral("N");
    return {
        {ParamSpec::number(QStringLiteral("grasp"), 0, newtons,
                           QStringLiteral("T_grasp: a grasp is confirmed while the grip force "
                                          "is above it")),
         &p.grasp},
        {ParamSpec::number(QStringLiteral("break"), 0, newtons,
                           QStringLiteral("T_break: a break is warned of while the grip force "
                                          "is above it")),
         &p.brk},
        {ParamSpec::number(QStringLiteral("max"), 0, newtons,
                           QStringLiteral("F_max: the force at which the break warning reaches "
                                          "full intensity")),
         &p.max},
        {hysteresisSpec(newtons, QStringLiteral("An active message holds until the force falls "
                                                "this far below its threshold")),
         &p.hysteresis},
        {minDurationSpec(), &p.minDuration}};
}

} // namespace

bool ForceDetector::Params::read(const QJsonObject &json, QString *key, QString *reason)
{
    return readDetectorParams(json, fields(*this), key, reason);
}

std::vector<ParamSpec> ForceDetector::Params::specs()
{
    Params defaults;
    return detectorParamSpecs(fields(defaults));
}

QJsonObject ForceDetector::Params::toJson() const
{
    Params copy = *this;
    return detectorParamsToJson(fields(copy));
}

bool ForceDetector::Params::validate(QString *key, QString *reason) const
{
    Params copy = *this;
    if (!checkDetectorParams(fields(copy), key, reason))
        return false;
    if (!(grasp < brk)) {
        return paramError(key, reason, QStringLiteral("break"),
                          QStringLiteral("must be greater than grasp (%1), got %2")
                              .arg(formatNumber(grasp), formatNumber(brk)));
    }
    if (!(brk < max)) {
        return paramError(key, reason, QStringLiteral("max"),
                          QStringLiteral("must be greater than break (%1), got %2")
                              .arg(formatNumber(brk), formatNumber(max)));
    }
    return true;
}

ForceDetector::Params ForceDetector::Params::fittedTo(const GripperTraits &gripper) const
{
    // Active above T, ended at T - hysteresis or below: a swing wider than the band would
    // cross both on every cycle.
    Params fitted = *this;
    fitted.hysteresis = std::max(hysteresis, gripper.forceRipple);
    return fitted;
}

ForceDetector::ForceDetector(int node, Gripper gripper, const Params &params, DetectorKind kind)
    : Detector(node, gripper, kind), m_params(params)
{
    m_grasp.configure(gripper, node, kind, Message::Grasp, Category::Confirmation,
                      params.minDuration);
    m_break.configure(gripper, node, kind, Message::Break, Category::Exception,
                      params.minDuration);
}

void ForceDetector::update(const ContactFrame &frame, EventBuffer &out)
{
    if (frame.gripper != m_gripper)
        return;
    const double force = frame.totalForce();
    // An active message holds down to threshold - hysteresis; with 0 this is the spec's F > T.
    const double graspThreshold =
        m_grasp.isActive() ? m_params.grasp - m_params.hysteresis : m_params.grasp;
    const double breakThreshold =
        m_break.isActive() ? m_params.brk - m_params.hysteresis : m_params.brk;
    const double intensity =
        std::clamp((force - m_params.brk) / (m_params.max - m_params.brk), 0.0, 1.0);
    m_grasp.update(frame.t, force > graspThreshold, 1.0, out);
    m_break.update(frame.t, force > breakThreshold, intensity, out);
}

void ForceDetector::endAll(double t, EventBuffer &out)
{
    m_grasp.forceEnd(t, out);
    m_break.forceEnd(t, out);
}

void ForceDetector::clear()
{
    m_grasp.clear();
    m_break.clear();
}

bool ForceDetector::isActive(Message message, double *intensity) const
{
    const MessageTracker *tracker = message == Message::Grasp   ? &m_grasp
                                    : message == Message::Break ? &m_break
                                                                : nullptr;
    if (!tracker || !tracker->isActive())
        return false;
    if (intensity)
        *intensity = tracker->intensity();
    return true;
}

void ForceDetector::appendActive(double t, EventBuffer &out) const
{
    m_grasp.appendActive(t, out);
    m_break.appendActive(t, out);
}

std::vector<SemanticEvent> ForceDetector::probes(double intensity) const
{
    return {m_grasp.probe(intensity), m_break.probe(intensity)};
}

std::vector<DetectorLevel> ForceDetector::levels() const
{
    using L = DetectorLevel;
    return {
        {L::Quantity::Force, L::Meaning::ConfirmationBegins, QStringLiteral("grasp"),
         m_params.grasp},
        {L::Quantity::Force, L::Meaning::ExceptionBegins, QStringLiteral("break"), m_params.brk},
        {L::Quantity::Force, L::Meaning::FullIntensity, QStringLiteral("max"), m_params.max}};
}

} // namespace semhap
