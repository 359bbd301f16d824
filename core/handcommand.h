// SPDX-License-Identifier: MIT
#pragma once

#include "contactframe.h"
#include "pose.h"

namespace semhap {

/**
 * What the user commands one hand: where its wrist should be and how hard it grips. The
 * drive inputs (keyboard, network pose input) send it to the simulation's DriveOperator, and
 * sessions record it, so a session shows the user's intent beside the contact it produced.
 */
struct HandCommand
{
    double t = 0.0; ///< when it was given (s, the run's clock); sessions record it
    Gripper hand = Gripper::Right;
    Pose target;       ///< the wrist target, world frame
    double grip = 0.0; ///< total grip force (N); negative opens
};

} // namespace semhap
