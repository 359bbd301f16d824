// SPDX-License-Identifier: MIT
#pragma once

#include "contactframe.h"

#include <array>
#include <memory>
#include <optional>
#include <vector>

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
 * Where a driven wrist is asked to go, drawn over the scene: a translucent ghost of the palm
 * at the target, a little larger than the palm so that it shows while the hand is there, and
 * a drop line to the surface straight below it.
 */
struct WristMarker
{
    Gripper hand = Gripper::Right;
    std::array<double, 3> target{};
    std::array<double, 4> quat{1.0, 0.0, 0.0, 0.0}; ///< the target's orientation (w, x, y, z)
    std::optional<double> surface; ///< the height the drop line reaches (none: no line)
    bool active = false;           ///< the hand the user drives now (the other is fainter)
    bool guarded = false;          ///< resting on something: the target stopped descending
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
    /** What is drawn over the scene from the next render on (empty: nothing). */
    void setMarkers(const std::vector<WristMarker> &markers) { m_markers = markers; }

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
    /** Per hand: the half sizes of its palm's box (the ghost's shape), if it has one. */
    std::array<std::optional<std::array<double, 3>>, 2> m_palms;
    OrbitCamera m_camera;
    std::vector<WristMarker> m_markers;
};

} // namespace semhap
