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

} // namespace semhap
