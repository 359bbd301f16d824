// SPDX-License-Identifier: MIT
#include "contactframe.h"

namespace semhap {

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
