// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <vector>

namespace semhap {

/**
 * Where a simulated scene's bodies were at one instant, so that a replay can draw it again
 * (a session's `scene_states` table, recorded at display rate). The core does not know
 * what the numbers mean; the simulation writes and reads them (World::sceneState()).
 */
struct SceneState
{
    double t = 0.0;
    /** The world's generalized positions, then each mocap body's position and quaternion. */
    std::vector<double> pose;
    /** The visual overlay as shown: left confirmation, left warning, right ditto (0–1). */
    std::array<double, 4> overlay{};
};

} // namespace semhap
