// SPDX-License-Identifier: MIT
#pragma once

#include "contactframe.h"

#include <QByteArray>
#include <QString>

#include <cstdint>
#include <vector>

namespace semhap {

class ActorTable;
class CdrWriter;
struct DeviceFrame;
struct HandCommand;
struct SemanticEvent;

/**
 * semhap's streams as ROS 2 messages: each stream's topic, its type, and each message in
 * CDR. One mapping, read by the MCAP export (McapExport) and the Foxglove server
 * (FoxglovePublisher), so a viewer shows the same topics live and recorded.
 *
 * | topic | type |
 * |---|---|
 * | `/semhap/GRIPPER/contact` | `semhap_msgs/msg/ContactFrame` |
 * | `/semhap/GRIPPER/TIP/wrench` | `geometry_msgs/msg/WrenchStamped` |
 * | `/semhap/events` | `semhap_msgs/msg/SemanticEvent` |
 * | `/semhap/devices/DEVICE` | `semhap_msgs/msg/DeviceFrame` |
 * | `/semhap/HAND/input` | `semhap_msgs/msg/HandCommand` |
 *
 * A wrench is the fingertip's force in the gripper frame. Each writer starts a new message
 * in `cdr`; `ns` is the header's stamp (ns since the epoch).
 */
class SemhapMessages
{
public:
    static constexpr const char *ContactType = "semhap_msgs/msg/ContactFrame";
    static constexpr const char *WrenchType = "geometry_msgs/msg/WrenchStamped";
    static constexpr const char *EventType = "semhap_msgs/msg/SemanticEvent";
    static constexpr const char *DeviceType = "semhap_msgs/msg/DeviceFrame";
    static constexpr const char *InputType = "semhap_msgs/msg/HandCommand";

    static QString contactTopic(Gripper gripper);
    static QString wrenchTopic(Gripper gripper, bool leftTip);
    static QString eventsTopic();
    static QString deviceTopic(const QString &device);
    static QString inputTopic(Gripper hand);

    /** A gripper's frame: both tips (f, n, actor, resultant, mu) and the signals. */
    static void contact(CdrWriter &cdr, std::int64_t ns, const ContactFrame &frame,
                        const ActorTable &actors);
    /** One tip's force as a wrench; without a resultant it lies along the grip axis. */
    static void wrench(CdrWriter &cdr, std::int64_t ns, const ContactFrame &frame, bool leftTip);
    /** An event, with the name of the node that made it. */
    static void event(CdrWriter &cdr, std::int64_t ns, const SemanticEvent &event,
                      const QString &node);
    /** A band's frame, with its name, its model and its channels' names (UTF-8). */
    static void device(CdrWriter &cdr, std::int64_t ns, const DeviceFrame &frame,
                       const QString &name, const QString &model,
                       const std::vector<QByteArray> &channels);
    static void input(CdrWriter &cdr, std::int64_t ns, const HandCommand &command);
};

} // namespace semhap
