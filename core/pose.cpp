// SPDX-License-Identifier: MIT
#include "pose.h"

#include <cmath>

namespace semhap {

std::array<double, 4> yawQuaternion(double yaw)
{
    return {std::cos(yaw / 2), 0.0, 0.0, std::sin(yaw / 2)};
}

Pose turnedAboutVertical(const Pose &pose, double yaw)
{
    // Hamilton product z(yaw) * q: the turn happens in world axes, so a tilt is kept.
    const double c = std::cos(yaw / 2);
    const double s = std::sin(yaw / 2);
    const auto &q = pose.quat;
    Pose turned = pose;
    turned.quat = {c * q[0] - s * q[3], c * q[1] - s * q[2], c * q[2] + s * q[1],
                   c * q[3] + s * q[0]};
    const double norm =
        std::sqrt(turned.quat[0] * turned.quat[0] + turned.quat[1] * turned.quat[1] +
                  turned.quat[2] * turned.quat[2] + turned.quat[3] * turned.quat[3]);
    for (double &v : turned.quat)
        v /= norm;
    return turned;
}

} // namespace semhap
