// SPDX-License-Identifier: MIT
#include "nodebuilder.h"

#include <QJsonArray>

namespace semhap {

Gripper NodeBuilder::gripper() const
{
    Gripper gripper = Gripper::Right;
    gripperFromName(param(QStringLiteral("gripper")).toString(), &gripper);
    return gripper;
}

QStringList NodeBuilder::channels() const
{
    QStringList list;
    for (const QJsonValue &channel : param(QStringLiteral("channels")).toArray())
        list.append(channel.toString());
    return list;
}

} // namespace semhap
