// SPDX-License-Identifier: MIT
#pragma once

#include "contactframe.h"
#include "pose.h"

#include <array>
#include <atomic>
#include <memory>
#include <optional>

namespace semhap {

class World;

/** What the visual overlay shows, each in [0, 1]: per gripper a confirmation and a warning. */
struct SceneOverlay
{
    double leftConfirm = 0.0;
    double leftWarn = 0.0;
    double rightConfirm = 0.0;
    double rightWarn = 0.0;
};

/**
 * Pictures of a World handed from the simulation thread to the renderer without a lock:
 * the simulation captures the world's visible state (geoms, lights, contact forces, the
 * overlay's tint) into one of three scene buffers when the viewport has asked for one, and
 * the renderer takes the newest. Neither side ever waits for the other, and the physics
 * data is read only on the thread that steps it.
 */
class SceneFeed
{
public:
    explicit SceneFeed(const World &world);
    ~SceneFeed();
    SceneFeed(const SceneFeed &) = delete;
    SceneFeed &operator=(const SceneFeed &) = delete;

    /** Draws contact forces as arrows from the next capture on. Any thread. */
    void setShowForces(bool show) { m_showForces.store(show); }
    bool showForces() const { return m_showForces.load(); }

    /** Asks for a capture (the viewport, once per display frame). Any thread. */
    void request() { m_requested.store(true); }
    /** Whether a capture was asked for since the last one. Simulation thread. */
    bool wantsCapture() const { return m_requested.load(std::memory_order_relaxed); }
    /** Records the world's state as it is now. Simulation thread; never blocks. */
    void capture(const World &world, const SceneOverlay &overlay);

    /** Makes the newest capture the one to draw; false when nothing newer came. Renderer. */
    bool takeLatest();
    /** Whether anything was captured yet. Renderer. */
    bool hasPicture() const { return m_hasPicture; }
    /**
     * Where `hand`'s wrist is in the picture takeLatest() made the newest (none: the scene
     * has no such hand, or nothing was captured yet). Renderer.
     */
    std::optional<Pose> handPose(Gripper hand) const;
    /**
     * Whether the straight line from `eye` to `point` is clear in that picture: no opaque
     * fixed geom (a wall, a partition) and none of the other hand's stands on it; `hand`'s
     * own and loose bodies (cubes) do not count, nor what touches the point. Renderer.
     */
    bool inSight(const std::array<double, 3> &eye, const std::array<double, 3> &point,
                 Gripper hand) const;

private:
    friend class SceneRenderer;
    struct Private;
    std::unique_ptr<Private> d;
    std::atomic<bool> m_showForces{false};
    std::atomic<bool> m_requested{true};
    /** The finished buffer's index, with NewBit set until the renderer takes it. */
    std::atomic<int> m_middle{1};
    static constexpr int NewBit = 4;
    int m_back = 0;  ///< the simulation's
    int m_front = 2; ///< the renderer's
    bool m_hasPicture = false;
};

} // namespace semhap
