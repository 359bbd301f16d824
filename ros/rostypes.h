// SPDX-License-Identifier: MIT
#pragma once

#include <QByteArray>
#include <QString>
#include <QStringList>

namespace semhap {

/**
 * The ROS 2 message types semhap writes: its own `semhap_msgs` and the standard types they
 * use, one `.msg` text per type (resources/ros/PACKAGE/msg/TYPE.msg, built in).
 */
class RosTypes
{
public:
    /**
     * The `ros2msg` schema of `type` (e.g. semhap_msgs/msg/ContactFrame) as rosbag2 writes
     * it: the type's text, then each type it uses once, after a line of '=' and
     * `MSG: package/Type`. Empty for a type semhap does not have.
     */
    static QByteArray schema(const QString &type);
    /** The types semhap has, as package/msg/Type. */
    static QStringList names();
};

} // namespace semhap
