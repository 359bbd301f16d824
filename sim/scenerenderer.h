// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <memory>

namespace semhap {

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
 * Draws a World with MuJoCo's renderer into the caller's current OpenGL context: MuJoCo
 * renders offscreen (so its shadow pass survives) and the result is blitted into the
 * target framebuffer. The visual overlay device is shown on the grippers — confirmation in
 * blue, warning in orange (Okabe–Ito colours, told apart with the common colour-vision
 * deficiencies), at the channel's level, so a blinking channel blinks — and contact forces
 * can be drawn as arrows. No widgets: the studio's viewport wraps this.
 */
class SceneRenderer
{
public:
    /** Overlay channels in the overlay model's order: left/right confirm and warn. */
    struct Overlay
    {
        double leftConfirm = 0.0;
        double leftWarn = 0.0;
        double rightConfirm = 0.0;
        double rightWarn = 0.0;
    };

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
    void setOverlay(const Overlay &overlay) { m_overlay = overlay; }
    void setShowForces(bool show) { m_showForces = show; }
    bool showForces() const { return m_showForces; }

    /** Renders the world's current state into framebuffer `target` (width × height). */
    void render(unsigned int target, int width, int height);

    /** The largest image the offscreen buffer holds (the scene's offwidth × offheight). */
    std::array<int, 2> maxSize() const;

private:
    struct Private;
    std::unique_ptr<Private> d;
    const World &m_world;
    OrbitCamera m_camera;
    Overlay m_overlay;
    bool m_showForces = false;
};

} // namespace semhap
