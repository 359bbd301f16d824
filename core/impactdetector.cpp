// SPDX-License-Identifier: MIT
#include "impactdetector.h"

#include "detectorparams.h"

#include <algorithm>

namespace semhap {

namespace {

// Every parameter's spec and field, listed once for reading, writing, checking and editing.
DetectorParams fields(ImpactDetector::Params &p)
{
    const QString rate = QStringLiteral("N/s");
    const QString seconds = QStringLiteral("s");
    return {{ParamSpec::number(QStringLiteral("rate"), 0, rate,
                               QStringLiteral("An impact begins when the grip force rises "
                                              "faster than this"))
                 .above(0),
             &p.rate},
            {ParamSpec::number(QStringLiteral("full"), 0, rate,
                               QStringLiteral("The rise of force at which the impact is felt "
                                              "at full intensity"))
                 .above(0),
             &p.full},
            {ParamSpec::number(QStringLiteral("tau"), 0, seconds,
                               QStringLiteral("How far back the rise is taken: longer is "
                                              "smoother and misses shorter strikes"))
                 .atLeast(0),
             &p.tau},
            {ParamSpec::number(QStringLiteral("hold"), 0, seconds,
                               QStringLiteral("How long an impact stays felt after the force "
                                              "last rose that fast"))
                 .atLeast(0),
             &p.hold},
            {minDurationSpec(), &p.minDuration}};
}

} // namespace

bool ImpactDetector::Params::read(const QJsonObject &json, QString *key, QString *reason)
{
    return readDetectorParams(json, fields(*this), key, reason);
}

std::vector<ParamSpec> ImpactDetector::Params::specs()
{
    Params defaults;
    return detectorParamSpecs(fields(defaults));
}

QJsonObject ImpactDetector::Params::toJson() const
{
    Params copy = *this;
    return detectorParamsToJson(fields(copy));
}

bool ImpactDetector::Params::validate(QString *key, QString *reason) const
{
    Params copy = *this;
    if (!checkDetectorParams(fields(copy), key, reason))
        return false;
    if (!(rate < full))
        return paramError(key, reason, QStringLiteral("full"),
                          QStringLiteral("must be greater than rate (%1), got %2")
                              .arg(formatNumber(rate), formatNumber(full)));
    return true;
}

Message ImpactDetector::message()
{
    static const Message impact = [] {
        Message m = Message::Break;
        messageFromName(QStringLiteral("impact"), &m);
        return m;
    }();
    return impact;
}

ImpactDetector::ImpactDetector(int node, Gripper gripper, const Params &params, DetectorKind kind)
    : Detector(node, gripper, kind), m_params(params), m_slope(params.tau)
{
    m_impact.configure(gripper, node, kind, message(), Category::Exception, params.minDuration);
}

void ImpactDetector::update(const ContactFrame &frame, EventBuffer &out)
{
    if (frame.gripper != m_gripper)
        return;
    const double rise = m_slope.update(frame.totalForce(), frame.t);
    const bool steep = rise > m_params.rate;
    if (steep) {
        // An impact is as strong as its steepest rise: it does not fade while it is held.
        const double intensity =
            std::clamp((rise - m_params.rate) / (m_params.full - m_params.rate), 0.0, 1.0);
        m_peak =
            m_impact.isActive() || m_impact.isPending() ? std::max(m_peak, intensity) : intensity;
        m_lastSteep = frame.t;
    }
    const bool held = m_impact.isActive() && frame.t - m_lastSteep < m_params.hold;
    m_impact.update(frame.t, steep || held, m_peak, out);
}

void ImpactDetector::endAll(double t, EventBuffer &out)
{
    m_impact.forceEnd(t, out);
}

void ImpactDetector::clear()
{
    m_impact.clear();
    m_slope = SlopeFilter(m_params.tau);
    m_peak = 0.0;
}

bool ImpactDetector::isActive(Message message, double *intensity) const
{
    if (message != ImpactDetector::message() || !m_impact.isActive())
        return false;
    if (intensity)
        *intensity = m_impact.intensity();
    return true;
}

void ImpactDetector::appendActive(double t, EventBuffer &out) const
{
    m_impact.appendActive(t, out);
}

std::vector<SemanticEvent> ImpactDetector::probes(double intensity) const
{
    return {m_impact.probe(intensity)};
}

} // namespace semhap
