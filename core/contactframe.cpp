// SPDX-License-Identifier: MIT
#include "contactframe.h"

#include <cmath>

namespace semhap {

double Fingertip::frictionUse(double coefficient) const
{
    const double normal = std::abs(fxyz[1]);
    if (!hasFxyz || !(coefficient > 0.0) || normal < MinNormalForce)
        return 0.0;
    return std::hypot(fxyz[0], fxyz[2]) / normal / coefficient;
}

QString gripperName(Gripper gripper)
{
    return gripper == Gripper::Left ? QStringLiteral("left") : QStringLiteral("right");
}

bool gripperFromName(const QString &name, Gripper *gripper)
{
    if (name == QLatin1String("left")) {
        *gripper = Gripper::Left;
        return true;
    }
    if (name == QLatin1String("right")) {
        *gripper = Gripper::Right;
        return true;
    }
    return false;
}

} // namespace semhap
