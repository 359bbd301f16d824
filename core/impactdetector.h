// SPDX-License-Identifier: MIT
#pragma once

#include "detector.h"
#include "messagetracker.h"
#include "paramspec.h"
#include "routercontext.h"
#include "slopefilter.h"

namespace semhap {

/**
 * Collisions: `impact` (an exception) when the grip force rises faster than `rate`, as when
 * the fingers or what they hold strike something. It holds for `hold` seconds after the
 * force last rose that fast, so a strike is felt even when it lasts a few milliseconds, with
 * the intensity of its steepest rise: clip((dF/dt - rate) / (full - rate), 0, 1).
 */
class ImpactDetector : public Detector
{
public:
    struct Params
    {
        double rate = 1000.0; ///< dF/dt at which an impact begins, N/s
        double full = 5000.0; ///< dF/dt of full intensity, N/s (> rate)
        double tau = 0.005;   ///< how far back the rate is taken, s
        double hold = 0.25;   ///< how long an impact stays felt after the last steep rise, s
        double minDuration = 0.0;

        /** Reads the keys present in `json` over the defaults; false with `key`+`reason`. */
        bool read(const QJsonObject &json, QString *key, QString *reason);
        /** Every parameter, under the JSON keys read() accepts. */
        QJsonObject toJson() const;
        /** Every parameter's spec, with the defaults above: what editors and docs show. */
        static std::vector<ParamSpec> specs();
        /** rate < full, each in its range, all finite. */
        bool validate(QString *key, QString *reason) const;
        /** The same on every gripper: a rate of force does not scale with contacts. */
        Params fittedTo(const GripperTraits &) const { return *this; }
    };

    /** The message it raises, interned once: `impact`. */
    static Message message();

    /** `params` should have passed validate(); events carry `node`, `gripper` and `kind`. */
    ImpactDetector(int node, Gripper gripper, const Params &params, DetectorKind kind);

    void update(const ContactFrame &frame, EventBuffer &out) override;
    void endAll(double t, EventBuffer &out) override;
    void clear() override;
    bool isActive(Message message, double *intensity = nullptr) const override;
    void appendActive(double t, EventBuffer &out) const override;
    std::vector<SemanticEvent> probes(double intensity) const override;

private:
    Params m_params;
    SlopeFilter m_slope;
    MessageTracker m_impact;
    double m_lastSteep = 0.0; ///< when the force last rose faster than rate
    double m_peak = 0.0;      ///< the intensity of the impact's steepest rise so far
};

} // namespace semhap
