// SPDX-License-Identifier: MIT
#pragma once

#include "framesignals.h"

#include <QString>

#include <array>

namespace semhap {

/** Which gripper (robot hand) a frame or event belongs to. */
enum class Gripper
{
    Left = 0,
    Right = 1
};

QString gripperName(Gripper gripper);
/** Parses `"left"` / `"right"`; returns false for anything else. */
bool gripperFromName(const QString &name, Gripper *gripper);

/** Contact state of one fingertip in one tick. */
struct Fingertip
{
    double f = 0.0; ///< summed contact-force magnitudes, N (finite, >= 0)
    int n = 0;      ///< number of contact points
    int actor = -1; ///< ActorTable id of the touched body, -1 for none
    bool hasFxyz = false;
    std::array<double, 3> fxyz{}; ///< resultant force in the gripper frame, when known
    double mu = 0.0; ///< friction coefficient of the touched surface, when known; 0: unknown

    /**
     * How much of the friction available this fingertip uses: (tangential / normal force)
     * over `mu`, 1 at the edge of the friction cone. The fingers close along the gripper
     * frame's y axis, so the normal force is |fxyz.y| and the tangential the rest. 0 without
     * fxyz, without a coefficient (`mu` <= 0), or with less normal force than MinNormalForce.
     */
    double frictionUse(double mu) const;

    /** Below this normal force (N) a fingertip is not pressing on anything worth a ratio. */
    static constexpr double MinNormalForce = 0.1;
};

/**
 * One gripper, one tick: the two fingertips' contact state (spec section 1) and the task's
 * named signals for the gripper (docs/streams.md, "Signals"). A missing fingertip is the
 * default Fingertip: no force, no contacts, no actor.
 */
struct ContactFrame
{
    double t = 0.0;
    Gripper gripper = Gripper::Right;
    Fingertip left;  ///< the gripper's left fingertip
    Fingertip right; ///< the gripper's right fingertip
    /** The task's named scalars ("signals" in the stream; Qt reserves the word). */
    FrameSignals signalValues;

    double totalForce() const { return left.f + right.f; }
    int totalContacts() const { return left.n + right.n; }
};

} // namespace semhap
