// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <memory>

namespace semhap {

class SceneFeed;
class World;

/** Where the camera looks from: an orbit around a point. */
struct OrbitCamera
{
    std::array<double, 3> lookAt{0.0, 0.0, 0.08};
    double distance = 0.9;
    double azimuth = 90.0;    ///< degrees
    double elevation = -30.0; ///< degrees
};

/**
 * Draws a SceneFeed's newest picture with MuJoCo's renderer into the caller's current
 * OpenGL context: MuJoCo renders offscreen (so its shadow pass survives) and the result is
 * blitted into the target framebuffer, from the caller's orbit camera. No widgets: the
 * studio's viewport wraps this.
 */
class SceneRenderer
{
public:
    explicit SceneRenderer(const World &world);
    ~SceneRenderer();

    /**
     * Creates MuJoCo's GL resources for offscreen images up to the scene's
     * <visual><global offwidth offheight>. The context must be current (and a compatibility
     * profile); call again after the widget moves to another context.
     */
    void initialize();
    bool isInitialized() const;

    OrbitCamera &camera() { return m_camera; }

    /**
     * Renders the feed's newest picture into framebuffer `target` (width × height); false
     * (drawing nothing) until the feed has one.
     */
    bool render(SceneFeed &feed, unsigned int target, int width, int height);

    /** The largest image the offscreen buffer holds (the scene's offwidth × offheight). */
    std::array<int, 2> maxSize() const;

private:
    struct Private;
    std::unique_ptr<Private> d;
    const World &m_world;
    OrbitCamera m_camera;
};

} // namespace semhap
