// SPDX-License-Identifier: MIT
#include "scenerenderer.h"

#include "mujocohandles.h"
#include "world.h"

#include <QOpenGLContext>
#include <QOpenGLExtraFunctions>

#include <algorithm>

namespace semhap {

namespace {

// Okabe–Ito blue and orange.
constexpr float ConfirmColour[3] = {0.0f, 0.447f, 0.698f};
constexpr float WarnColour[3] = {0.902f, 0.624f, 0.0f};

} // namespace

struct SceneRenderer::Private
{
    mjvScene scene;
    mjvOption option;
    mjvCamera camera;
    mjrContext context;
    bool initialized = false;
    std::array<std::vector<int>, 2> gripperBodies; ///< bodies whose geoms show the overlay

    Private()
    {
        mjv_defaultScene(&scene);
        mjv_defaultOption(&option);
        mjv_defaultCamera(&camera);
        mjr_defaultContext(&context);
    }
    ~Private()
    {
        mjv_freeScene(&scene);
        mjr_freeContext(&context);
    }
};

SceneRenderer::SceneRenderer(const World &world) : d(std::make_unique<Private>()), m_world(world)
{
    const mjModel *m = world.model();
    mjv_makeScene(m, &d->scene, 4000);
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

SceneRenderer::~SceneRenderer() = default;

void SceneRenderer::initialize()
{
    mjr_freeContext(&d->context);
    mjr_defaultContext(&d->context);
    mjr_makeContext(m_world.model(), &d->context, mjFONTSCALE_100);
    d->initialized = true;
}

bool SceneRenderer::isInitialized() const
{
    return d->initialized;
}

std::array<int, 2> SceneRenderer::maxSize() const
{
    return {m_world.model()->vis.global.offwidth, m_world.model()->vis.global.offheight};
}

void SceneRenderer::render(unsigned int target, int width, int height)
{
    const mjModel *m = m_world.model();
    mjvCamera &cam = d->camera;
    cam.type = mjCAMERA_FREE;
    std::copy(m_camera.lookAt.begin(), m_camera.lookAt.end(), cam.lookat);
    cam.distance = m_camera.distance;
    cam.azimuth = m_camera.azimuth;
    cam.elevation = m_camera.elevation;
    d->option.flags[mjVIS_CONTACTFORCE] = m_showForces;

    // mjv_updateScene only reads the state, but its signature is not const.
    mjv_updateScene(m, const_cast<mjData *>(m_world.data()), &d->option, nullptr, &cam, mjCAT_ALL,
                    &d->scene);

    // The overlay: tint the gripper's geoms; a warning shows over a confirmation.
    const std::array<std::array<double, 2>, 2> levels{
        {{m_overlay.leftConfirm, m_overlay.leftWarn},
         {m_overlay.rightConfirm, m_overlay.rightWarn}}};
    for (int i = 0; i < d->scene.ngeom; ++i) {
        mjvGeom &geom = d->scene.geoms[i];
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

    const int w = std::min(width, d->context.offWidth);
    const int h = std::min(height, d->context.offHeight);
    mjr_setBuffer(mjFB_OFFSCREEN, &d->context);
    mjr_render(mjrRect{0, 0, w, h}, &d->scene, &d->context);

    QOpenGLExtraFunctions *gl = QOpenGLContext::currentContext()->extraFunctions();
    gl->glBindFramebuffer(GL_READ_FRAMEBUFFER, d->context.offFBO);
    gl->glBindFramebuffer(GL_DRAW_FRAMEBUFFER, target);
    gl->glBlitFramebuffer(0, 0, w, h, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_LINEAR);
    gl->glBindFramebuffer(GL_FRAMEBUFFER, target);
    // MuJoCo leaves alpha at 0: grabs of the window would look translucent.
    gl->glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_TRUE);
    gl->glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    gl->glClear(GL_COLOR_BUFFER_BIT);
    gl->glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

} // namespace semhap
