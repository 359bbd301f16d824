// SPDX-License-Identifier: MIT
#pragma once

#include <array>

namespace semhap {

/** A position and an orientation (unit quaternion w, x, y, z) in world coordinates. */
struct Pose
{
    std::array<double, 3> pos{};                    ///< metres
    std::array<double, 4> quat{1.0, 0.0, 0.0, 0.0}; ///< w, x, y, z
};

/** The rotation about the world's vertical axis by `yaw` radians, as a Pose quaternion. */
std::array<double, 4> yawQuaternion(double yaw);

/** `pose` turned about the vertical axis through its position by `yaw` radians. */
Pose turnedAboutVertical(const Pose &pose, double yaw);

/**
 * `pose` turned by `angle` radians about the world-frame direction `axis` (unit length)
 * through its position.
 */
Pose turnedAbout(const Pose &pose, const std::array<double, 3> &axis, double angle);

/** How far `pose`'s z axis leans from the world's vertical (radians, 0 … π). */
double tiltFromVertical(const Pose &pose);

} // namespace semhap
