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

namespace {

constexpr double GhostRadius = 0.012;
constexpr double DiscRadius = 0.014;
// How much larger than the palm its ghost is on every side (m).
constexpr double GhostMargin = 0.004;

/** Appends a decoration geom to `scene` (turned by `mat`, if given); null when it is full. */
mjvGeom *addGeom(mjvScene &scene, int type, const mjtNum size[3], const mjtNum pos[3],
                 const float rgba[4], const mjtNum *mat = nullptr)
{
    if (scene.ngeom >= scene.maxgeom)
        return nullptr;
    mjvGeom *geom = scene.geoms + scene.ngeom++;
    mjv_initGeom(geom, type, size, pos, mat, rgba);
    geom->category = mjCAT_DECOR;
    geom->objtype = mjOBJ_UNKNOWN;
    geom->objid = -1;
    return geom;
}

void addMarker(mjvScene &scene, const WristMarker &marker,
               const std::optional<std::array<double, 3>> &palm)
{
    // Cyan while free, amber while the guard holds; the other hand's ghost is fainter.
    const float alpha = marker.active ? 0.55f : 0.25f;
    const float free[4] = {0.35f, 0.85f, 1.0f, alpha};
    const float guarded[4] = {1.0f, 0.7f, 0.2f, alpha};
    const float *rgba = marker.guarded ? guarded : free;
    const mjtNum at[3] = {marker.target[0], marker.target[1], marker.target[2]};
    double below = GhostRadius;
    if (palm) {
        // The palm's box, a little larger all round: it shows over the palm while the wrist
        // is at its target, and turns with the target.
        const mjtNum size[3] = {(*palm)[0] + GhostMargin, (*palm)[1] + GhostMargin,
                                (*palm)[2] + GhostMargin};
        const mjtNum quat[4] = {marker.quat[0], marker.quat[1], marker.quat[2], marker.quat[3]};
        mjtNum mat[9];
        mju_quat2Mat(mat, quat);
        addGeom(scene, mjGEOM_BOX, size, at, rgba, mat);
        below = size[2];
    } else {
        const mjtNum ghost[3] = {GhostRadius, GhostRadius, GhostRadius};
        addGeom(scene, mjGEOM_SPHERE, ghost, at, rgba);
    }
    if (!marker.surface || *marker.surface >= marker.target[2] - below)
        return;
    const mjtNum foot[3] = {marker.target[0], marker.target[1], *marker.surface + 0.0005};
    const float line[4] = {rgba[0], rgba[1], rgba[2], 0.9f};
    const mjtNum width[3] = {GhostRadius, GhostRadius, GhostRadius};
    if (mjvGeom *drop = addGeom(scene, mjGEOM_LINE, width, at, line))
        mjv_makeConnector(drop, mjGEOM_LINE, 2.0, at[0], at[1], at[2] - below, foot[0], foot[1],
                          foot[2]);
    const mjtNum disc[3] = {DiscRadius, DiscRadius, 0.0005};
    addGeom(scene, mjGEOM_CYLINDER, disc, foot, line);
}

} // namespace

SceneRenderer::SceneRenderer(const World &world) : d(std::make_unique<Private>()), m_world(world)
{
    d->cameraData.reset(mj_makeData(world.model()));
    const mjModel *m = world.model();
    for (Gripper hand : {Gripper::Left, Gripper::Right}) {
        const QByteArray name = (gripperName(hand) + QStringLiteral(".palm")).toUtf8();
        const int palm = mj_name2id(m, mjOBJ_GEOM, name.constData());
        if (palm >= 0 && m->geom_type[palm] == mjGEOM_BOX)
            m_palms[size_t(hand)] = {m->geom_size[3 * palm], m->geom_size[3 * palm + 1],
                                     m->geom_size[3 * palm + 2]};
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

    // The markers go on top of the captured geoms for this render only: the feed's buffer
    // is drawn again, unmarked or marked anew, on the next frame.
    const int captured = scene.ngeom;
    for (const WristMarker &marker : m_markers)
        addMarker(scene, marker, m_palms[size_t(marker.hand)]);
    const int w = std::min(width, d->context.offWidth);
    const int h = std::min(height, d->context.offHeight);
    mjr_setBuffer(mjFB_OFFSCREEN, &d->context);
    mjr_render(mjrRect{0, 0, w, h}, &scene, &d->context);
    scene.ngeom = captured;

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
