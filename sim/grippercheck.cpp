// SPDX-License-Identifier: MIT
#include "grippercheck.h"

#include "gripperadapter.h"
#include "mujocohandles.h"
#include "world.h"

#include <algorithm>
#include <cmath>

namespace semhap {

namespace {

// The hold that shows ringing: this grip (N, both fingers), held this long, of which the
// last part is read; a swing above RingingShare of the grip (or RingingFloor N) warns.
constexpr double HoldGrip = 40.0;
constexpr double OpeningGrip = -20.0;
constexpr double HoldSeconds = 0.6;
constexpr double ReadSeconds = 0.3;
constexpr double RingingShare = 0.05;
constexpr double RingingFloor = 1.0;
// Fewer pad geoms than this in a full grasp leave the slip counts nothing between "all" and
// "a fingertip lost".
constexpr int FewContacts = 4;
// How far the closing and approach axes may lean from the wrist's y and -z.
constexpr double AxisTolerance = 0.05; // 1 - cos(angle): about 18 degrees

QString name(const mjModel *m, mjtObj type, int id)
{
    const char *text = mj_id2name(m, type, id);
    return text ? QString::fromUtf8(text) : QStringLiteral("#%1").arg(id);
}

/** `(x, y, z)` to two decimals, without negative zeros. */
QString direction(const std::array<double, 3> &v)
{
    QStringList parts;
    for (double x : v)
        parts.append(QString::number(std::round(x * 100) / 100 + 0.0, 'f', 2));
    return QLatin1Char('(') + parts.join(QStringLiteral(", ")) + QLatin1Char(')');
}

bool excluded(const mjModel *m, int b1, int b2)
{
    const int a = ((b1 + 1) << 16) + b2 + 1;
    const int b = ((b2 + 1) << 16) + b1 + 1;
    for (int i = 0; i < m->nexclude; ++i) {
        if (m->exclude_signature[i] == a || m->exclude_signature[i] == b)
            return true;
    }
    return false;
}

void checkFingersCollide(const World &world, const mjModel *m, Gripper hand, QStringList *out)
{
    // Every geom of the bodies that carry the fingertips, not only the pads: a finger's
    // link can meet the other finger too.
    std::array<std::vector<int>, 2> bodies;
    for (int side = 0; side < 2; ++side) {
        for (int g : world.fingertipGeoms(hand, side)) {
            if (std::find(bodies[size_t(side)].begin(), bodies[size_t(side)].end(),
                          m->geom_bodyid[g]) == bodies[size_t(side)].end())
                bodies[size_t(side)].push_back(m->geom_bodyid[g]);
        }
    }
    for (int b1 : bodies[0]) {
        for (int b2 : bodies[1]) {
            if (b1 == b2 || excluded(m, b1, b2))
                continue;
            for (int g1 = 0; g1 < m->ngeom; ++g1) {
                for (int g2 = 0; g2 < m->ngeom; ++g2) {
                    if (m->geom_bodyid[g1] != b1 || m->geom_bodyid[g2] != b2 ||
                        !((m->geom_contype[g1] & m->geom_conaffinity[g2]) ||
                          (m->geom_contype[g2] & m->geom_conaffinity[g1])))
                        continue;
                    out->append(
                        QStringLiteral("geoms %1 and %2 of the two fingers can collide: fingers "
                                       "closing on nothing push into each other and can lock; add "
                                       "<exclude body1=\"%3\" body2=\"%4\"/> to <contact>")
                            .arg(name(m, mjOBJ_GEOM, g1), name(m, mjOBJ_GEOM, g2),
                                 name(m, mjOBJ_BODY, b1), name(m, mjOBJ_BODY, b2)));
                    return;
                }
            }
        }
    }
}

void checkPadPriority(const World &world, const mjModel *m, Gripper hand, QStringList *out)
{
    // Only objects that ask for their friction to count (a contact priority, as semhap's
    // cubes): an object without one leaves the mix to MuJoCo (dish_wiping's plate, whose
    // sponge's friction is meant to win).
    for (const SceneObject &object : world.objects()) {
        for (int g = 0; g < m->ngeom; ++g) {
            if (m->geom_bodyid[g] != object.body || m->geom_priority[g] == 0)
                continue;
            for (int side = 0; side < 2; ++side) {
                for (int pad : world.fingertipGeoms(hand, side)) {
                    const int pp = m->geom_priority[pad], op = m->geom_priority[g];
                    const double pf = m->geom_friction[3 * pad], of = m->geom_friction[3 * g];
                    if ((pp > op && pf != of) || (pp == op && pf > of)) {
                        out->append(QStringLiteral(
                                        "pad geom %1 has contact priority %2 and friction %3, "
                                        "object %4 priority %5 and friction %6: MuJoCo takes "
                                        "the higher priority's friction, or the larger on a tie, "
                                        "so the object grips as if it were %3; give the pads a "
                                        "lower priority than the objects'")
                                        .arg(name(m, mjOBJ_GEOM, pad))
                                        .arg(pp)
                                        .arg(pf)
                                        .arg(object.name)
                                        .arg(op)
                                        .arg(of));
                        return;
                    }
                }
            }
        }
    }
}

/**
 * Holds the narrowest object that fits between the pads with a steady grip, on a World of
 * its own, and reports how far the pads' force swings.
 */
void checkRinging(const World &world, const QString &scene, const GripperAdapter *adapter,
                  Gripper hand, QStringList *out)
{
    const GripperGeometry &geometry = world.gripperGeometry(hand);
    int narrowest = -1;
    double width = 1e9;
    for (size_t i = 0; i < world.objects().size(); ++i) {
        const SceneObject &o = world.objects()[i];
        const double w = std::min(o.upper[0] - o.lower[0], o.upper[1] - o.lower[1]);
        if (!o.broken && w < width && w < geometry.openGap() - 0.005) {
            width = w;
            narrowest = int(i);
        }
    }
    if (narrowest < 0)
        return;
    SceneOptions options;
    if (adapter)
        options.gripper = adapter->file;
    QString error;
    std::unique_ptr<World> hold = World::load(scene, options, &error);
    if (!hold)
        return;
    const Pose wrist = hold->gripperPose(hand);
    const auto &a = geometry.approachAxis();
    const double drop = geometry.drop(width);
    // The wrist's rotation applied to the pads' centre below it.
    const auto &q = wrist.quat;
    const std::array<double, 3> v{a[0] * drop, a[1] * drop, a[2] * drop};
    const std::array<double, 3> t{2 * (q[2] * v[2] - q[3] * v[1]), 2 * (q[3] * v[0] - q[1] * v[2]),
                                  2 * (q[1] * v[1] - q[2] * v[0])};
    const std::array<double, 3> centre{
        wrist.pos[0] + v[0] + q[0] * t[0] + (q[2] * t[2] - q[3] * t[1]),
        wrist.pos[1] + v[1] + q[0] * t[1] + (q[3] * t[0] - q[1] * t[2]),
        wrist.pos[2] + v[2] + q[0] * t[2] + (q[1] * t[1] - q[2] * t[0])};
    const int steps = int(std::lround(HoldSeconds / hold->timestep()));
    const int reading = int(std::lround(ReadSeconds / hold->timestep()));
    const int actor = hold->objects()[size_t(narrowest)].actor;
    bool held = false;
    int heldSteps = 0;
    double low = 1e9, high = -1e9;
    // Open first: a model may start closed (the Franka hand's fingers rest at 0).
    hold->setGrip(hand, OpeningGrip);
    for (int k = 0; k < steps; ++k)
        hold->step();
    // Held where the pads will close on it until they do (it would fall meanwhile).
    for (int k = 0; k < 4 * steps && heldSteps < steps; ++k) {
        const ContactFrame &frame = hold->frame(hand);
        held = held || (frame.left.actor == actor && frame.right.actor == actor);
        if (!held)
            hold->placeObject(narrowest, centre);
        hold->setGrip(hand, held ? HoldGrip : HoldGrip / 4);
        hold->step();
        if (held && ++heldSteps > steps - reading) {
            low = std::min(low, hold->frame(hand).totalForce());
            high = std::max(high, hold->frame(hand).totalForce());
        }
    }
    if (!held || high < low)
        return;
    const ContactFrame &last = hold->frame(hand);
    if (last.left.actor != actor || last.right.actor != actor) {
        out->append(QStringLiteral("a steady %1 N grip does not keep %2 between the pads for "
                                   "%3 s: the pads' contacts are too soft or too slippery for "
                                   "the objects (their solref, friction and priority)")
                        .arg(HoldGrip)
                        .arg(world.objects()[size_t(narrowest)].name)
                        .arg(HoldSeconds));
        return;
    }
    const double swing = high - low;
    if (swing > std::max(RingingFloor, RingingShare * HoldGrip)) {
        const mjModel *m = world.model();
        const int joint =
            m->actuator_trnid[2 * mj_name2id(m, mjOBJ_ACTUATOR,
                                             (gripperName(hand) + QStringLiteral(".grip.left"))
                                                 .toUtf8()
                                                 .constData())];
        out->append(QStringLiteral("a steady %1 N grip on %2 reads %3 to %4 N: the fingers ring "
                                   "(joint %5 has damping %6); the force detector's hysteresis "
                                   "should be at least the %7 N swing: set "
                                   "\"detectors\": {\"forceRipple\": %7} in the adapter, or "
                                   "damp the finger joints")
                        .arg(HoldGrip)
                        .arg(world.objects()[size_t(narrowest)].name)
                        .arg(low, 0, 'f', 1)
                        .arg(high, 0, 'f', 1)
                        .arg(name(m, mjOBJ_JOINT, joint))
                        .arg(m->dof_damping[m->jnt_dofadr[joint]])
                        .arg(std::ceil(swing * 10) / 10, 0, 'f', 1));
    }
}

} // namespace

QStringList GripperCheck::warnings(const World &world, const QString &scene,
                                   const GripperAdapter *adapter)
{
    QStringList out;
    const mjModel *m = world.model();
    for (Gripper hand : {Gripper::Left, Gripper::Right}) {
        if (!world.hasGripper(hand))
            continue;
        const GripperGeometry &geometry = world.gripperGeometry(hand);
        const QString who = QStringLiteral("gripper '%1': ").arg(gripperName(hand));
        QStringList found;
        checkFingersCollide(world, m, hand, &found);
        checkPadPriority(world, m, hand, &found);
        const auto &y = geometry.closingAxis();
        const auto &z = geometry.approachAxis();
        if (y[1] < 1 - AxisTolerance || -z[2] < 1 - AxisTolerance) {
            QString fix = QStringLiteral("turn the gripper so they do");
            if (adapter && adapter->hasMount)
                fix = QStringLiteral("leave \"mount\" out of the adapter and the loader fits one");
            found.append(QStringLiteral("the fingers close along %1 and point along %2 in the "
                                        "wrist's frame, not along y and -z as the operators and "
                                        "the frames' fxyz assume: %3")
                             .arg(direction(y), direction(z), fix));
        }
        if (adapter && geometry.closesAsJointRises() != (adapter->closing > 0))
            found.append(QStringLiteral("the adapter says \"closing\": \"%1\", but the fingers "
                                        "close as their joints' positions %2: set \"%3\" (the "
                                        "loader followed the model)")
                             .arg(adapter->closing > 0 ? QStringLiteral("positive")
                                                       : QStringLiteral("negative"),
                                  geometry.closesAsJointRises() ? QStringLiteral("grow")
                                                                : QStringLiteral("shrink"),
                                  geometry.closesAsJointRises() ? QStringLiteral("positive")
                                                                : QStringLiteral("negative")));
        const int contacts = world.fullContacts(hand);
        if (contacts > 0 && contacts < FewContacts)
            found.append(QStringLiteral("a full grasp touches only %1 pad geoms: the slip "
                                        "detector's contact counts are fitted to %1 "
                                        "(docs/detectors.md) and can tell only a fingertip's "
                                        "contact lost altogether")
                             .arg(contacts));
        double widest = 0.0; // the widest any hand of the scene opens
        for (Gripper other : {Gripper::Left, Gripper::Right})
            widest = std::max(
                widest, world.hasGripper(other) ? world.gripperGeometry(other).openGap() : 0.0);
        QStringList tooWide;
        double across = 0.0;
        for (const SceneObject &o : world.objects()) {
            // Across its narrowest extent, whichever way the hand would have to turn; only
            // when no hand of the scene can take it.
            const double w = std::min(
                {o.upper[0] - o.lower[0], o.upper[1] - o.lower[1], o.upper[2] - o.lower[2]});
            if (w > widest && geometry.openGap() > 0) {
                tooWide.append(o.name);
                across = std::max(across, w);
            }
        }
        if (tooWide.size() == 1)
            found.append(QStringLiteral("object %1 is %2 mm across at its narrowest, the pads "
                                        "open to %3 mm: this gripper cannot take it")
                             .arg(tooWide.front())
                             .arg(across * 1000, 0, 'f', 0)
                             .arg(geometry.openGap() * 1000, 0, 'f', 0));
        else if (!tooWide.isEmpty())
            found.append(QStringLiteral("%1 objects (%2%3) are up to %4 mm across at their "
                                        "narrowest, the pads open to %5 mm: this gripper cannot "
                                        "take them")
                             .arg(tooWide.size())
                             .arg(tooWide.mid(0, 3).join(QStringLiteral(", ")),
                                  tooWide.size() > 3 ? QStringLiteral(", …") : QString())
                             .arg(across * 1000, 0, 'f', 0)
                             .arg(geometry.openGap() * 1000, 0, 'f', 0));
        checkRinging(world, scene, adapter, hand, &found);
        for (const QString &warning : found)
            out.append(who + warning);
    }
    return out;
}

} // namespace semhap
