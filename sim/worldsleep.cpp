// SPDX-License-Identifier: MIT
// World: resting objects put to sleep (no contacts, held in place) and woken before anything
// awake can reach them (sim/README.md, "Sleeping objects").
#include "worldprivate.h"

#include <algorithm>
#include <cmath>

namespace semhap {

namespace {

// Resting objects sleep (sim/README.md, "Sleeping objects"): still for this many steps in a
// row, slower than these speeds, with nothing awake within WakeMargin.
constexpr int SleepAfterSteps = 100;
constexpr double StillSpeed = 0.002;       // m/s
constexpr double StillAngularSpeed = 0.05; // rad/s
// Clearance kept between anything awake and a sleeping object, on top of the distance the
// awake thing covers in two steps: a sleeping object wakes before anything can touch it.
constexpr double WakeMargin = 0.008; // m

} // namespace

Aabb World::Private::moverBox(size_t *k) const
{
    const int body = model->geom_bodyid[moverGeoms[*k]];
    Aabb box = geomBox(moverGeoms[*k]);
    for (; *k < moverGeoms.size() && model->geom_bodyid[moverGeoms[*k]] == body; ++*k)
        box.unite(geomBox(moverGeoms[*k]));
    return box;
}

Aabb World::Private::geomBox(int geom) const
{
    const mjModel *m = model.get();
    const mjData *dd = data.get();
    const mjtNum *centre = dd->geom_xpos + 3 * geom;
    const mjtNum *size = m->geom_size + 3 * geom;
    std::array<double, 3> half{};
    if (m->geom_type[geom] == mjGEOM_BOX) {
        // The rotated box's extent along each world axis (xmat is row-major, local to world).
        const mjtNum *r = dd->geom_xmat + 9 * geom;
        for (size_t i = 0; i < 3; ++i) {
            half[i] = std::abs(r[3 * i]) * size[0] + std::abs(r[3 * i + 1]) * size[1] +
                      std::abs(r[3 * i + 2]) * size[2];
        }
    } else {
        const double radius = m->geom_type[geom] == mjGEOM_SPHERE ? size[0] : m->geom_rbound[geom];
        half = {radius, radius, radius};
    }
    Aabb box;
    for (size_t i = 0; i < 3; ++i) {
        box.low[i] = centre[i] - half[i] - m->geom_margin[geom];
        box.high[i] = centre[i] + half[i] + m->geom_margin[geom];
    }
    return box;
}

double World::Private::speedAt(int body, const double *point) const
{
    // cvel is [angular; linear] at the subtree centre of mass of the body's root.
    const mjModel *m = model.get();
    const mjData *dd = data.get();
    const mjtNum *v = dd->cvel + 6 * body;
    const mjtNum *com = dd->subtree_com + 3 * m->body_rootid[body];
    double arm = 0.0;
    for (int i = 0; i < 3; ++i)
        arm += (point[i] - com[i]) * (point[i] - com[i]);
    return std::sqrt(v[3] * v[3] + v[4] * v[4] + v[5] * v[5]) +
           std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) * std::sqrt(arm);
}

Aabb World::Private::objectBox(const World &world, size_t object, bool moving) const
{
    const Rest &rest = rests[object];
    Aabb box = geomBox(rest.colliders.front().geom);
    for (const Collider &c : rest.colliders)
        box.unite(geomBox(c.geom));
    if (moving) {
        const int body = world.m_objects[object].body;
        const mjtNum *centre = data->xpos + 3 * body;
        box.grow(WakeMargin + 2 * model->opt.timestep * speedAt(body, centre));
    }
    return box;
}

void World::Private::collectAwake(const World &world, const std::vector<char> *moving)
{
    const double dt = model->opt.timestep;
    awake.clear();
    // One box per moving body.
    for (size_t k = 0; k < moverGeoms.size();) {
        const int body = model->geom_bodyid[moverGeoms[k]];
        const size_t first = k;
        Aabb box = moverBox(&k);
        double speed = 0.0;
        for (size_t g = first; g < k; ++g)
            speed = std::max(speed, speedAt(body, data->geom_xpos + 3 * moverGeoms[g]));
        box.grow(WakeMargin + 2 * dt * speed);
        awake.push_back(box);
    }
    for (size_t i = 0; i < rests.size(); ++i) {
        if (!rests[i].asleep && !world.m_objects[i].broken && rests[i].canSleep &&
            (!moving || (*moving)[i]))
            awake.push_back(objectBox(world, i, true));
    }
}

void World::Private::wake(const World &world, size_t object)
{
    Rest &rest = rests[object];
    rest.stillSteps = 0;
    if (!rest.asleep)
        return;
    rest.asleep = false;
    --sleeping;
    mjModel *m = model.get();
    if (world.m_objects[object].broken)
        return;
    for (const Collider &c : rest.colliders) {
        m->geom_contype[c.geom] = c.contype;
        m->geom_conaffinity[c.geom] = c.conaffinity;
    }
}

void World::Private::wakeNearAwake(const World &world)
{
    if (sleeping == 0)
        return;
    // Positions are those of the last step's start; the margins cover two steps' travel.
    collectAwake(world, nullptr);
    bool woke = true;
    while (woke && sleeping > 0) {
        woke = false;
        for (size_t i = 0; i < rests.size(); ++i) {
            if (!rests[i].asleep)
                continue;
            const Aabb &box = rests[i].box;
            for (const Aabb &other : awake) {
                if (box.overlaps(other)) {
                    wake(world, i);
                    // What it rests on or leans against wakes with it.
                    awake.push_back(objectBox(world, i, true));
                    woke = true;
                    break;
                }
            }
        }
    }
}

void World::Private::holdSleeping(const World &world)
{
    if (sleeping == 0)
        return;
    const mjModel *m = model.get();
    mjData *dd = data.get();
    for (size_t i = 0; i < rests.size(); ++i) {
        if (!rests[i].asleep)
            continue;
        const int joint = m->body_jntadr[world.m_objects[i].body];
        std::copy(rests[i].qpos.begin(), rests[i].qpos.end(), dd->qpos + m->jnt_qposadr[joint]);
        std::fill_n(dd->qvel + m->jnt_dofadr[joint], 6, 0.0);
    }
}

void World::Private::sleepResting(const World &world)
{
    mjModel *m = model.get();
    mjData *dd = data.get();
    bool candidates = false;
    for (size_t i = 0; i < rests.size(); ++i) {
        Rest &rest = rests[i];
        blocked[i] = 1;
        if (!rest.canSleep || rest.asleep || world.m_objects[i].broken)
            continue;
        const mjtNum *v = dd->qvel + m->jnt_dofadr[m->body_jntadr[world.m_objects[i].body]];
        const bool still =
            v[0] * v[0] + v[1] * v[1] + v[2] * v[2] < StillSpeed * StillSpeed &&
            v[3] * v[3] + v[4] * v[4] + v[5] * v[5] < StillAngularSpeed * StillAngularSpeed;
        rest.stillSteps = still ? rest.stillSteps + 1 : 0;
        if (rest.stillSteps >= SleepAfterSteps) {
            blocked[i] = 0;
            candidates = true;
        }
    }
    if (!candidates)
        return;
    // What is awake and moving keeps the resting objects near it awake, and those keep the
    // ones near them awake, and so on: objects that touch sleep and wake together.
    collectAwake(world, &blocked);
    bool more = true;
    while (more) {
        more = false;
        for (size_t i = 0; i < rests.size(); ++i) {
            if (blocked[i])
                continue;
            const Aabb box = objectBox(world, i, false);
            for (const Aabb &other : awake) {
                if (box.overlaps(other)) {
                    blocked[i] = 1;
                    awake.push_back(objectBox(world, i, true));
                    more = true;
                    break;
                }
            }
        }
    }
    for (size_t i = 0; i < rests.size(); ++i) {
        if (blocked[i])
            continue;
        Rest &rest = rests[i];
        rest.asleep = true;
        rest.box = objectBox(world, i, false);
        ++sleeping;
        const int joint = m->body_jntadr[world.m_objects[i].body];
        std::copy_n(dd->qpos + m->jnt_qposadr[joint], 7, rest.qpos.begin());
        std::fill_n(dd->qvel + m->jnt_dofadr[joint], 6, 0.0);
        for (const Collider &c : rest.colliders) {
            m->geom_contype[c.geom] = 0;
            m->geom_conaffinity[c.geom] = 0;
        }
    }
}

bool Region::contains(const std::array<double, 3> &p) const
{
    for (size_t i = 0; i < 3; ++i) {
        if (std::abs(p[i] - center[i]) > half[i])
            return false;
    }
    return true;
}

} // namespace semhap
