// SPDX-License-Identifier: MIT
#include "semhapmessages.h"

#include "actortable.h"
#include "cdrwriter.h"
#include "deviceframe.h"
#include "handcommand.h"
#include "nametable.h"
#include "semanticevent.h"

namespace semhap {

namespace {

/** A header: the stamp and the frame it names. */
void header(CdrWriter &cdr, std::int64_t ns, const QString &frame)
{
    cdr.clear();
    cdr.time(ns);
    cdr.string(frame);
}

void fingertip(CdrWriter &cdr, const Fingertip &tip, const ActorTable &actors)
{
    cdr.float64(tip.f);
    cdr.int32(tip.n);
    cdr.string(tip.actor >= 0 ? actors.name(tip.actor) : QString());
    cdr.boolean(tip.hasFxyz);
    for (double c : tip.fxyz)
        cdr.float64(tip.hasFxyz ? c : 0.0);
    cdr.float64(tip.mu);
}

} // namespace

QString SemhapMessages::contactTopic(Gripper gripper)
{
    return QStringLiteral("/semhap/%1/contact").arg(gripperName(gripper));
}

QString SemhapMessages::wrenchTopic(Gripper gripper, bool leftTip)
{
    return QStringLiteral("/semhap/%1/%2/wrench")
        .arg(gripperName(gripper), leftTip ? QStringLiteral("left") : QStringLiteral("right"));
}

QString SemhapMessages::eventsTopic()
{
    return QStringLiteral("/semhap/events");
}

QString SemhapMessages::deviceTopic(const QString &device)
{
    return QStringLiteral("/semhap/devices/") + device;
}

QString SemhapMessages::inputTopic(Gripper hand)
{
    return QStringLiteral("/semhap/%1/input").arg(gripperName(hand));
}

void SemhapMessages::contact(CdrWriter &cdr, std::int64_t ns, const ContactFrame &frame,
                             const ActorTable &actors)
{
    header(cdr, ns, gripperName(frame.gripper));
    fingertip(cdr, frame.left, actors);
    fingertip(cdr, frame.right, actors);
    cdr.sequence(std::uint32_t(frame.signalValues.size()));
    for (const SignalValue &s : frame.signalValues)
        cdr.string(signalNames().name(s.id));
    cdr.sequence(std::uint32_t(frame.signalValues.size()));
    for (const SignalValue &s : frame.signalValues)
        cdr.float64(s.value);
}

void SemhapMessages::wrench(CdrWriter &cdr, std::int64_t ns, const ContactFrame &frame,
                            bool leftTip)
{
    const Fingertip &tip = leftTip ? frame.left : frame.right;
    header(cdr, ns,
           gripperName(frame.gripper) +
               (leftTip ? QStringLiteral("_left") : QStringLiteral("_right")));
    const std::array<double, 3> force =
        tip.hasFxyz ? tip.fxyz : std::array<double, 3>{0.0, tip.f, 0.0};
    for (double c : force)
        cdr.float64(c);
    for (int i = 0; i < 3; ++i)
        cdr.float64(0.0); // no torque is measured
}

void SemhapMessages::event(CdrWriter &cdr, std::int64_t ns, const SemanticEvent &e,
                           const QString &node)
{
    header(cdr, ns, gripperName(e.gripper));
    cdr.string(node);
    cdr.string(detectorKindName(e.detector));
    cdr.string(messageName(e.message));
    cdr.string(categoryName(e.category));
    cdr.string(eventPhaseName(e.phase));
    cdr.float64(e.intensity);
}

void SemhapMessages::device(CdrWriter &cdr, std::int64_t ns, const DeviceFrame &f,
                            const QString &name, const QString &model,
                            const std::vector<QByteArray> &channels)
{
    header(cdr, ns, name);
    cdr.string(model);
    cdr.sequence(std::uint32_t(f.channelCount));
    for (int c = 0; c < f.channelCount; ++c)
        cdr.string(size_t(c) < channels.size() ? QByteArrayView(channels[size_t(c)])
                                               : QByteArrayView());
    cdr.sequence(std::uint32_t(f.channelCount));
    for (int c = 0; c < f.channelCount; ++c)
        cdr.float64(f.values[size_t(c)]);
}

void SemhapMessages::input(CdrWriter &cdr, std::int64_t ns, const HandCommand &h)
{
    header(cdr, ns, gripperName(h.hand));
    for (double p : h.target.pos)
        cdr.float64(p);
    // geometry_msgs/Quaternion is x, y, z, w; a Pose's is w, x, y, z.
    cdr.float64(h.target.quat[1]);
    cdr.float64(h.target.quat[2]);
    cdr.float64(h.target.quat[3]);
    cdr.float64(h.target.quat[0]);
    cdr.float64(h.grip);
}

} // namespace semhap
