// SPDX-License-Identifier: MIT
#pragma once

#include "detector.h"
#include "messagetracker.h"
#include "paramspec.h"
#include "routercontext.h"

namespace semhap {

/**
 * The paper's Algorithm 2 as stateful messages: once both fingertips hold the same actor
 * with F > grasp the grasp is stable (`grasp`, confirmation); while stable, `slip`
 * (exception) is active when N < loss, intensity clip((loss - N)/(loss - min), 0, 1).
 * An actor switch, a release or F <= grasp resets: every active message ends at once.
 */
class SlipDetector : public Detector
{
public:
    struct Params
    {
        double grasp = 20.0; ///< T_grasp, N
        double loss = 28.0;  ///< N_loss, contacts
        double min = 8.0;    ///< N_min, contacts (< loss)
        /** Once slipping, slip stays active until N >= loss + hysteresis (contacts). */
        double hysteresis = 0.0;
        /** A message begins only after its condition has held this long (s). */
        double minDuration = 0.0;

        /** Reads the keys present in `json` over the defaults; false with `key`+`reason`. */
        bool read(const QJsonObject &json, QString *key, QString *reason);
        /** Every parameter, under the JSON keys read() accepts. */
        QJsonObject toJson() const;
        /** Every parameter's spec, with the defaults above: what editors and docs show. */
        static std::vector<ParamSpec> specs();
        /** min < loss, grasp >= 0, hysteresis and minDuration >= 0, all finite. */
        bool validate(QString *key, QString *reason) const;
        /**
         * The parameters as they run on `gripper`: the counts (loss, min, hysteresis) are
         * written for a full grasp of ReferenceFullContacts and scaled to the gripper's
         * fullContacts, rounded to whole contacts so that every rule holds at the same share
         * of a full grasp (docs/detectors.md). Valid parameters stay valid.
         */
        Params fittedTo(const GripperTraits &gripper) const;
    };

    /** `params` should have passed validate(); events carry `node` and `gripper`. */
    SlipDetector(int node, Gripper gripper, const Params &params,
                 DetectorKind kind = DetectorKind::Slip);

    void update(const ContactFrame &frame, EventBuffer &out) override;
    void endAll(double t, EventBuffer &out) override;
    void clear() override;
    bool isActive(Message message, double *intensity = nullptr) const override;
    void appendActive(double t, EventBuffer &out) const override;
    std::vector<SemanticEvent> probes(double intensity) const override;
    std::vector<DetectorLevel> levels() const override;

    /** The parameters it runs with (a router's are fitted to the gripper). */
    const Params &params() const { return m_params; }
    /** The grasped actor (ActorTable id), -1 for none. */
    int graspedActor() const { return m_actor; }
    bool isStable() const { return m_stable; }

private:
    /** The spec's reset: not stable, every active message ends now (grasp, then slip). */
    void reset(double t, EventBuffer &out);

    Params m_params;
    int m_actor = -1;
    bool m_stable = false;
    MessageTracker m_grasp;
    MessageTracker m_slip;
};

} // namespace semhap
