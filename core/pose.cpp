// SPDX-License-Identifier: MIT
#include "pose.h"

#include <algorithm>
#include <cmath>

namespace semhap {

std::array<double, 4> yawQuaternion(double yaw)
{
    return {std::cos(yaw / 2), 0.0, 0.0, std::sin(yaw / 2)};
}

Pose turnedAboutVertical(const Pose &pose, double yaw)
{
    return turnedAbout(pose, {0.0, 0.0, 1.0}, yaw);
}

Pose turnedAbout(const Pose &pose, const std::array<double, 3> &axis, double angle)
{
    // Hamilton product r * q: the turn happens in world axes, so the pose's own lean is kept.
    const double c = std::cos(angle / 2);
    const double s = std::sin(angle / 2);
    const std::array<double, 4> r{c, s * axis[0], s * axis[1], s * axis[2]};
    const auto &q = pose.quat;
    Pose turned = pose;
    turned.quat = {r[0] * q[0] - r[1] * q[1] - r[2] * q[2] - r[3] * q[3],
                   r[0] * q[1] + r[1] * q[0] + r[2] * q[3] - r[3] * q[2],
                   r[0] * q[2] - r[1] * q[3] + r[2] * q[0] + r[3] * q[1],
                   r[0] * q[3] + r[1] * q[2] - r[2] * q[1] + r[3] * q[0]};
    const double norm =
        std::sqrt(turned.quat[0] * turned.quat[0] + turned.quat[1] * turned.quat[1] +
                  turned.quat[2] * turned.quat[2] + turned.quat[3] * turned.quat[3]);
    for (double &v : turned.quat)
        v /= norm;
    return turned;
}

double tiltFromVertical(const Pose &pose)
{
    // The z component of the pose's z axis: the rotation matrix's entry (2, 2).
    const auto &q = pose.quat;
    const double zz = 1.0 - 2.0 * (q[1] * q[1] + q[2] * q[2]);
    return std::acos(std::clamp(zz, -1.0, 1.0));
}

} // namespace semhap
