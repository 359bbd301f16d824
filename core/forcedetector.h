// SPDX-License-Identifier: MIT
#pragma once

#include "detector.h"
#include "messagetracker.h"
#include "paramspec.h"
#include "routercontext.h"

namespace semhap {

/**
 * The paper's Algorithm 1 as stateful messages: `grasp` (confirmation) while F > grasp,
 * `break` (exception) while F > break with intensity clip((F - break)/(max - break), 0, 1).
 */
class ForceDetector : public Detector
{
public:
    struct Params
    {
        double grasp = 20.0; ///< T_grasp, N
        double brk = 80.0;   ///< T_break, N (JSON key "break")
        double max = 120.0;  ///< F_max, N
        /** Once active, a message stays active until F <= threshold - hysteresis (N). */
        double hysteresis = 0.0;
        /** A message begins only after its condition has held this long (s). */
        double minDuration = 0.0;

        /** Reads the keys present in `json` over the defaults; false with `key`+`reason`. */
        bool read(const QJsonObject &json, QString *key, QString *reason);
        /** Every parameter, under the JSON keys read() accepts. */
        QJsonObject toJson() const;
        /** Every parameter's spec, with the defaults above: what editors and docs show. */
        static std::vector<ParamSpec> specs();
        /** grasp < break < max, hysteresis and minDuration >= 0, all finite. */
        bool validate(QString *key, QString *reason) const;
        /**
         * The parameters as they run on `gripper`: the hysteresis is at least the gripper's
         * forceRipple, so a steady grip's swing cannot end and begin a message again.
         */
        Params fittedTo(const GripperTraits &gripper) const;
    };

    /** `params` should have passed validate(); events carry `node` and `gripper`. */
    ForceDetector(int node, Gripper gripper, const Params &params,
                  DetectorKind kind = DetectorKind::Force);

    void update(const ContactFrame &frame, EventBuffer &out) override;
    void endAll(double t, EventBuffer &out) override;
    void clear() override;
    bool isActive(Message message, double *intensity = nullptr) const override;
    void appendActive(double t, EventBuffer &out) const override;
    std::vector<SemanticEvent> probes(double intensity) const override;
    std::vector<DetectorLevel> levels() const override;

    /** The parameters it runs with (a router's are fitted to the gripper). */
    const Params &params() const { return m_params; }

private:
    Params m_params;
    MessageTracker m_grasp;
    MessageTracker m_break;
};

} // namespace semhap
