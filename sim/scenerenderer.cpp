// SPDX-License-Identifier: MIT
#include "scenerenderer.h"

#include "mujocohandles.h"
#include "scenefeed_p.h"
#include "world.h"

#include <QOpenGLContext>
#include <QOpenGLExtraFunctions>

#include <algorithm>

namespace semhap {

struct SceneRenderer::Private
{
    mjvCamera camera;
    mjrContext context;
    /** mjv_updateCamera wants state: its own, never the one the simulation writes. */
    MjDataPtr cameraData;
    bool initialized = false;

    Private()
    {
        mjv_defaultCamera(&camera);
        mjr_defaultContext(&context);
    }
    ~Private() { mjr_freeContext(&context); }
};

SceneRenderer::SceneRenderer(const World &world) : d(std::make_unique<Private>()), m_world(world)
{
    d->cameraData.reset(mj_makeData(world.model()));
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

bool SceneRenderer::render(SceneFeed &feed, unsigned int target, int width, int height)
{
    feed.takeLatest();
    if (!feed.hasPicture())
        return false;
    mjvScene &scene = feed.d->scenes[size_t(feed.m_front)];
    mjvCamera &cam = d->camera;
    cam.type = mjCAMERA_FREE;
    std::copy(m_camera.lookAt.begin(), m_camera.lookAt.end(), cam.lookat);
    cam.distance = m_camera.distance;
    cam.azimuth = m_camera.azimuth;
    cam.elevation = m_camera.elevation;
    mjv_updateCamera(m_world.model(), d->cameraData.get(), &cam, &scene);

    const int w = std::min(width, d->context.offWidth);
    const int h = std::min(height, d->context.offHeight);
    mjr_setBuffer(mjFB_OFFSCREEN, &d->context);
    mjr_render(mjrRect{0, 0, w, h}, &scene, &d->context);

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
    return true;
}

} // namespace semhap
