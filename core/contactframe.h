// SPDX-License-Identifier: MIT
#pragma once

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
};

/**
 * One gripper, one tick: the two fingertips' contact state (spec section 1). A missing
 * fingertip is the default Fingertip: no force, no contacts, no actor.
 */
struct ContactFrame
{
    double t = 0.0;
    Gripper gripper = Gripper::Right;
    Fingertip left;  ///< the gripper's left fingertip
    Fingertip right; ///< the gripper's right fingertip

    double totalForce() const { return left.f + right.f; }
    int totalContacts() const { return left.n + right.n; }
};

} // namespace semhap
