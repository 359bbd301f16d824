// SPDX-License-Identifier: MIT
#pragma once

#include "world.h"

#include <array>

namespace semhap {

/** What the user commands one hand: the inputs keep one per hand and send it on. */
struct HandCommand
{
    bool present = false; ///< whether the scene has this gripper
    Pose target;
    double grip = 0.0; ///< total grip force (N); negative opens
};

/**
 * Each hand's target and grip as the world has them now: taking over starts there, so the
 * grippers do not jump. Read the world on the thread that steps it, or while it is paused.
 */
std::array<HandCommand, 2> currentCommands(const World &world);

/** The rotation about the world's vertical axis by `yaw` radians, as a Pose quaternion. */
std::array<double, 4> yawQuaternion(double yaw);

/** `pose` turned about the vertical axis through its position by `yaw` radians. */
Pose turnedAboutVertical(const Pose &pose, double yaw);

} // namespace semhap
