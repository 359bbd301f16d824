// SPDX-License-Identifier: MIT
#include "scenefeed.h"

#include "scenefeed_p.h"
#include "world.h"

#include <algorithm>

namespace semhap {

namespace {

// Okabe–Ito blue and orange.
constexpr float ConfirmColour[3] = {0.0f, 0.447f, 0.698f};
constexpr float WarnColour[3] = {0.902f, 0.624f, 0.0f};
constexpr int MaxGeoms = 4000;
// How close to a point inSight() looks (m): what touches it there does not hide it.
constexpr double Touching = 0.005;

} // namespace

SceneFeed::SceneFeed(const World &world) : d(std::make_unique<Private>())
{
    const mjModel *m = world.model();
    for (mjvScene &scene : d->scenes)
        mjv_makeScene(m, &scene, MaxGeoms);
    for (Gripper g : {Gripper::Left, Gripper::Right}) {
        const QByteArray name = (gripperName(g) + QStringLiteral(".gripper")).toUtf8();
        const int root = mj_name2id(m, mjOBJ_BODY, name.constData());
        if (root < 0)
            continue;
        for (int body = 0; body < m->nbody; ++body) {
            if (m->body_rootid[body] == root)
                d->gripperBodies[size_t(g)].push_back(body);
        }
    }
    d->geomHand.assign(size_t(m->ngeom), -1);
    for (int geom = 0; geom < m->ngeom; ++geom) {
        for (size_t g = 0; g < 2; ++g) {
            const auto &bodies = d->gripperBodies[g];
            if (std::find(bodies.begin(), bodies.end(), m->geom_bodyid[geom]) != bodies.end())
                d->geomHand[size_t(geom)] = int(g);
        }
    }
}

SceneFeed::~SceneFeed() = default;

SceneFeed::Private::Private()
{
    for (mjvScene &scene : scenes)
        mjv_defaultScene(&scene);
    mjv_defaultOption(&option);
}

SceneFeed::Private::~Private()
{
    for (mjvScene &scene : scenes)
        mjv_freeScene(&scene);
}

void SceneFeed::capture(const World &world, const SceneOverlay &overlay)
{
    m_requested.store(false, std::memory_order_relaxed);
    const mjModel *m = world.model();
    mjvScene &scene = d->scenes[size_t(m_back)];
    d->option.flags[mjVIS_CONTACTFORCE] = m_showForces.load(std::memory_order_relaxed);
    // The camera is the renderer's: only geoms and lights are captured here. mjv_addGeoms
    // only reads the state, but its signature is not const.
    mjData *data = const_cast<mjData *>(world.data());
    scene.ngeom = 0;
    mjv_addGeoms(m, data, &d->option, nullptr, mjCAT_ALL, &scene);
    mjv_makeLights(m, data, &scene);
    for (Gripper g : {Gripper::Left, Gripper::Right}) {
        d->hands[size_t(m_back)][size_t(g)] =
            world.hasGripper(g) ? std::optional<Pose>(world.gripperPose(g)) : std::nullopt;
    }

    // The overlay: tint the gripper's geoms; a warning shows over a confirmation.
    const std::array<std::array<double, 2>, 2> levels{
        {{overlay.leftConfirm, overlay.leftWarn}, {overlay.rightConfirm, overlay.rightWarn}}};
    for (int i = 0; i < scene.ngeom; ++i) {
        mjvGeom &geom = scene.geoms[i];
        if (geom.objtype != mjOBJ_GEOM)
            continue;
        const int body = m->geom_bodyid[geom.objid];
        for (size_t g = 0; g < 2; ++g) {
            const auto &bodies = d->gripperBodies[g];
            if (std::find(bodies.begin(), bodies.end(), body) == bodies.end())
                continue;
            const bool warn = levels[g][1] > 0.0;
            const double level = std::clamp(warn ? levels[g][1] : levels[g][0], 0.0, 1.0);
            const float *colour = warn ? WarnColour : ConfirmColour;
            for (int c = 0; c < 3; ++c)
                geom.rgba[c] = float((1.0 - level) * geom.rgba[c] + level * colour[c]);
            if (level > 0)
                geom.emission = std::max(geom.emission, float(0.4 * level));
        }
    }
    m_back = m_middle.exchange(m_back | NewBit, std::memory_order_acq_rel) & ~NewBit;
}

bool SceneFeed::takeLatest()
{
    if (!(m_middle.load(std::memory_order_relaxed) & NewBit))
        return false;
    m_front = m_middle.exchange(m_front, std::memory_order_acq_rel) & ~NewBit;
    m_hasPicture = true;
    return true;
}

std::optional<Pose> SceneFeed::handPose(Gripper hand) const
{
    return m_hasPicture ? d->hands[size_t(m_front)][size_t(hand)] : std::nullopt;
}

bool SceneFeed::inSight(const std::array<double, 3> &eye, const std::array<double, 3> &point,
                        Gripper hand) const
{
    if (!m_hasPicture)
        return true;
    const mjvScene &scene = d->scenes[size_t(m_front)];
    const mjtNum from[3] = {eye[0], eye[1], eye[2]};
    const mjtNum way[3] = {point[0] - eye[0], point[1] - eye[1], point[2] - eye[2]};
    // What the point touches (a pad on the floor) does not hide it: only what stands
    // further than Touching from it, on the way to the eye.
    const mjtNum length = mju_norm3(way);
    const mjtNum reach = length > Touching ? 1.0 - Touching / length : 0.0;
    for (int i = 0; i < scene.ngeom; ++i) {
        const mjvGeom &geom = scene.geoms[i];
        // Markers, sites and see-through geoms hide nothing.
        if (geom.objtype != mjOBJ_GEOM || geom.rgba[3] < 0.5f)
            continue;
        const int owner = d->geomHand[size_t(geom.objid)];
        const bool otherHand = owner >= 0 && owner != int(hand);
        if (geom.category != mjCAT_STATIC && !otherHand)
            continue;
        mjtNum pos[3], mat[9], size[3];
        std::copy_n(geom.pos, 3, pos);
        std::copy_n(geom.mat, 9, mat);
        std::copy_n(geom.size, 3, size);
        // The distance comes in lengths of `way`.
        const mjtNum hit = mju_rayGeom(pos, mat, size, from, way, geom.type);
        if (hit >= 0 && hit < reach)
            return false;
    }
    return true;
}

} // namespace semhap
