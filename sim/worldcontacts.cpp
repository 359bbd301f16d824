// SPDX-License-Identifier: MIT
// World: what each fingertip touches, with what force, and the fragile objects that break.
#include "worldprivate.h"

#include <algorithm>
#include <cmath>

namespace semhap {

namespace {

// A fragile object breaks when gripped above its force for this many steps in a row: a
// single-step impact spike (a finger arriving fast) is physics noise, not a squeeze.
constexpr int FractureSteps = 3;
// Where broken objects are parked, out of sight and out of play.
constexpr double ParkingDepth = -2.0;
// The least share of a pad's force from an object that must push it open for the object to be
// between the pads (cos 60 degrees). A held cube's weight, borne by the pads' friction, tilts
// that force from the closing axis, by less than 60 degrees while each pad presses with more
// than 0.29 times the weight: any grip that holds it with a friction coefficient up to 1.7.
constexpr double SqueezeShare = 0.5;
// Steps a fingertip's force is held while its force contacts drop out but it still touches.
constexpr int MaxForceHoldSteps = 2;

} // namespace

void World::Private::extract(World &world, double t)
{
    const mjModel *m = model.get();
    const mjData *dd = data.get();
    for (Tip &tip : tips) {
        tip.force = 0.0;
        tip.contacts = 0;
        tip.fworld = {};
        tip.touchedCount = 0;
    }
    std::fill(gripOnObject.begin(), gripOnObject.end(), 0.0);

    for (int c = 0; c < dd->ncon; ++c) {
        const mjContact &contact = dd->contact[c];
        const int tip1 = tipOfGeom[size_t(contact.geom1)];
        const int tip2 = tipOfGeom[size_t(contact.geom2)];
        if ((tip1 < 0) == (tip2 < 0))
            continue; // no fingertip, or two fingertips touching each other
        const bool tipIsFirst = tip1 >= 0;
        Tip &tip = tips[size_t(tipIsFirst ? tip1 : tip2)];
        const int taxel = tipIsFirst ? contact.geom1 : contact.geom2;
        const int other = tipIsFirst ? contact.geom2 : contact.geom1;
        const int root = m->body_rootid[m->geom_bodyid[other]];
        if (root == tip.gripperBody)
            continue; // the gripper's own parts
        const int object = objectOfBody[size_t(root)];
        const int actor = object >= 0 ? world.m_objects[size_t(object)].actor : -1;

        Touch *touch = nullptr;
        for (int i = 0; i < tip.touchedCount; ++i) {
            if (tip.touched[size_t(i)].actor == actor)
                touch = &tip.touched[size_t(i)];
        }
        if (!touch && tip.touchedCount < MaxTouched) {
            touch = &tip.touched[size_t(tip.touchedCount++)];
            *touch = Touch{actor, 0.0, 0, {}};
        }
        // A taxel counts once however many contact points it has. Contacts inside the
        // geoms' gap (efc_address < 0) count too: they keep n steady while an object slides.
        if (taxelStamp[size_t(taxel)] != stepCount) {
            taxelStamp[size_t(taxel)] = stepCount;
            ++tip.contacts;
            if (touch)
                ++touch->contacts;
        }
        if (contact.efc_address < 0)
            continue;
        mjtNum local[6];
        mj_contactForce(m, dd, c, local);
        const double magnitude =
            std::sqrt(local[0] * local[0] + local[1] * local[1] + local[2] * local[2]);
        tip.force += magnitude;
        if (touch)
            touch->force += magnitude;
        if (object >= 0)
            gripOnObject[size_t(object)] += magnitude;
        // The contact frame's rows are its axes in world coordinates; the force acts on
        // geom2 along them, so on geom1 it is the opposite.
        const double sign = tipIsFirst ? -1.0 : 1.0;
        for (int axis = 0; axis < 3; ++axis) {
            for (int k = 0; k < 3; ++k) {
                const double component = sign * local[axis] * contact.frame[3 * axis + k];
                tip.fworld[size_t(k)] += component;
                if (touch)
                    touch->fworld[size_t(k)] += component;
            }
        }
    }

    // Robust force: while an object slides, all of a fingertip's force contacts can drop
    // out for a step or two although its taxels still touch (n holds; sim/README.md). A
    // force sensor would not see such a gap; the detectors would (a grasp ending and
    // beginning again, a slip detector reset), so the last force is held over it.
    for (Tip &tip : tips) {
        if (tip.force == 0.0 && tip.contacts > 0 && tip.heldForce > 0.0 &&
            tip.heldSteps < MaxForceHoldSteps) {
            tip.force = tip.heldForce;
            tip.fworld = tip.heldFworld;
            ++tip.heldSteps;
        } else {
            tip.heldForce = tip.force;
            tip.heldFworld = tip.fworld;
            tip.heldSteps = 0;
        }
    }

    for (Gripper g : {Gripper::Left, Gripper::Right}) {
        Hand &hand = hands[size_t(g)];
        if (!hand.present)
            continue;
        // MuJoCo adds up its time step by step; frames carry it to the nanosecond, as the
        // player's instants do, so streams read 1.25 rather than 1.2499999999999.
        hand.frame.t = std::round(t * 1e9) / 1e9;
        const mjtNum *rotation = dd->xmat + 9 * hand.body;
        for (int finger = 0; finger < 2; ++finger) {
            const Tip &tip = tips[size_t(int(g) * 2 + finger)];
            Fingertip &out = finger == 0 ? hand.frame.left : hand.frame.right;
            out.f = tip.force;
            out.n = tip.contacts;
            // The touched body carrying the most force; without force, the most contacts.
            out.actor = -1;
            double bestForce = -1.0;
            int bestContacts = -1;
            for (int i = 0; i < tip.touchedCount; ++i) {
                const Touch &touch = tip.touched[size_t(i)];
                if (touch.force > bestForce ||
                    (touch.force == bestForce && touch.contacts > bestContacts)) {
                    bestForce = touch.force;
                    bestContacts = touch.contacts;
                    out.actor = touch.actor;
                }
            }
            // The touched object's friction: the objects' geoms have contact priority, so
            // theirs is the coefficient of the contact (sim/README.md).
            out.mu = 0.0;
            for (const SceneObject &object : world.m_objects) {
                if (object.actor == out.actor && out.actor >= 0)
                    out.mu = object.friction;
            }
            // Into the gripper frame: R^T · f (xmat is row-major, body to world).
            out.hasFxyz = true;
            for (int row = 0; row < 3; ++row) {
                out.fxyz[size_t(row)] = rotation[row] * tip.fworld[0] +
                                        rotation[3 + row] * tip.fworld[1] +
                                        rotation[6 + row] * tip.fworld[2];
            }
        }
    }
}

void World::Private::checkFractures(World &world, double t)
{
    for (size_t i = 0; i < world.m_objects.size(); ++i) {
        SceneObject &object = world.m_objects[i];
        if (object.broken) {
            // Gravity would pull a parked object down forever: put it back every step.
            world.placeObject(int(i), {0.0, 0.0, ParkingDepth});
            continue;
        }
        if (object.fragileForce <= 0)
            continue;
        overForceSteps[i] = gripOnObject[i] > object.fragileForce ? overForceSteps[i] + 1 : 0;
        if (overForceSteps[i] >= FractureSteps)
            fracture(world, i, t, gripOnObject[i]);
    }
}

void World::Private::fracture(World &world, size_t i, double t, double force)
{
    SceneObject &object = world.m_objects[i];
    wake(world, i);
    object.broken = true;
    world.m_fractures.push_back({t, int(i), force});
    mjModel *m = model.get();
    std::vector<float> &alphas = rests[i].alphas;
    alphas.clear();
    for (int geom = 0; geom < m->ngeom; ++geom) {
        if (m->geom_bodyid[geom] == object.body) {
            m->geom_contype[geom] = 0;
            m->geom_conaffinity[geom] = 0;
            alphas.push_back(m->geom_rgba[4 * geom + 3]);
            m->geom_rgba[4 * geom + 3] = 0.0f;
        }
    }
    world.placeObject(int(i), {0.0, 0.0, ParkingDepth});
}

bool World::Private::pushesApart(const World &world, Gripper gripper, int finger,
                                 const Touch &touch) const
{
    // The fingers close along the gripper frame's y axis, the left one towards -y: what is
    // between them pushes the left pad towards +y and the right one towards -y. Resting on
    // top of something (the closed fingertips lowered onto a cube) pushes both up instead.
    const double magnitude = std::hypot(touch.fworld[0], touch.fworld[1], touch.fworld[2]);
    if (magnitude < Fingertip::MinNormalForce)
        return false; // touching without force (inside the contact margin, or a dropout)
    const mjtNum *rotation = world.d->data->xmat + 9 * hands[size_t(gripper)].body;
    double across = 0.0;
    for (size_t k = 0; k < 3; ++k)
        across += rotation[3 * k + 1] * touch.fworld[k];
    return (finger == 0 ? across : -across) >= SqueezeShare * magnitude;
}

int World::objectBetween(Gripper gripper) const
{
    return hardestTouched(gripper, false);
}

int World::objectSqueezed(Gripper gripper) const
{
    return hardestTouched(gripper, true);
}

int World::hardestTouched(Gripper gripper, bool squeezed) const
{
    const Private::Tip &left = d->tips[size_t(int(gripper) * 2)];
    const Private::Tip &right = d->tips[size_t(int(gripper) * 2 + 1)];
    int actor = -1;
    double hardest = -1.0;
    for (int i = 0; i < left.touchedCount; ++i) {
        for (int j = 0; j < right.touchedCount; ++j) {
            const Private::Touch &a = left.touched[size_t(i)];
            const Private::Touch &b = right.touched[size_t(j)];
            if (a.actor >= 0 && a.actor == b.actor && a.force + b.force > hardest &&
                (!squeezed ||
                 (d->pushesApart(*this, gripper, 0, a) && d->pushesApart(*this, gripper, 1, b)))) {
                hardest = a.force + b.force;
                actor = a.actor;
            }
        }
    }
    for (size_t i = 0; i < m_objects.size() && actor >= 0; ++i) {
        if (m_objects[i].actor == actor)
            return int(i);
    }
    return -1;
}

bool World::isBetween(Gripper gripper, int object) const
{
    const int actor = m_objects[size_t(object)].actor;
    for (int finger = 0; finger < 2; ++finger) {
        const Private::Tip &tip = d->tips[size_t(int(gripper) * 2 + finger)];
        bool touched = false;
        for (int i = 0; i < tip.touchedCount; ++i)
            touched = touched || tip.touched[size_t(i)].actor == actor;
        if (!touched)
            return false;
    }
    return true;
}

bool World::Private::touches(const World &world, Gripper gripper, int object) const
{
    const int actor = world.m_objects[size_t(object)].actor;
    for (int finger = 0; finger < 2; ++finger) {
        const Tip &tip = tips[size_t(int(gripper) * 2 + finger)];
        for (int i = 0; i < tip.touchedCount; ++i) {
            if (tip.touched[size_t(i)].actor == actor)
                return true;
        }
    }
    return false;
}

} // namespace semhap
