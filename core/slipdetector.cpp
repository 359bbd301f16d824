// SPDX-License-Identifier: MIT
#include "slipdetector.h"

#include "detectorparams.h"

#include <algorithm>

namespace semhap {

namespace {

// Every parameter's JSON key and field, listed once for reading, writing and checking.
DetectorParams fields(SlipDetector::Params &p)
{
    return {{QLatin1String("grasp"), &p.grasp},
            {QLatin1String("loss"), &p.loss},
            {QLatin1String("min"), &p.min},
            {QLatin1String("hysteresis"), &p.hysteresis},
            {QLatin1String("minDuration"), &p.minDuration}};
}

} // namespace

bool SlipDetector::Params::read(const QJsonObject &json, QString *key, QString *reason)
{
    return readDetectorParams(json, fields(*this), key, reason);
}

QJsonObject SlipDetector::Params::toJson() const
{
    Params copy = *this;
    return detectorParamsToJson(fields(copy));
}

bool SlipDetector::Params::validate(QString *key, QString *reason) const
{
    Params copy = *this;
    if (!checkFiniteParams(fields(copy), key, reason))
        return false;
    if (grasp < 0.0) {
        return paramError(key, reason, QStringLiteral("grasp"),
                          QStringLiteral("must not be negative, got %1").arg(formatNumber(grasp)));
    }
    if (!(min < loss)) {
        return paramError(key, reason, QStringLiteral("loss"),
                          QStringLiteral("must be greater than min (%1), got %2")
                              .arg(formatNumber(min), formatNumber(loss)));
    }
    if (hysteresis < 0.0) {
        return paramError(
            key, reason, QStringLiteral("hysteresis"),
            QStringLiteral("must not be negative, got %1").arg(formatNumber(hysteresis)));
    }
    if (minDuration < 0.0) {
        return paramError(
            key, reason, QStringLiteral("minDuration"),
            QStringLiteral("must not be negative, got %1").arg(formatNumber(minDuration)));
    }
    return true;
}

SlipDetector::SlipDetector(int node, Gripper gripper, const Params &params)
    : Detector(node, gripper), m_params(params)
{
    m_grasp.configure(gripper, node, DetectorKind::Slip, Message::Grasp, params.minDuration);
    m_slip.configure(gripper, node, DetectorKind::Slip, Message::Slip, params.minDuration);
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

} // namespace semhap
