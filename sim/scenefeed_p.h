// SPDX-License-Identifier: MIT
#pragma once

#include "scenefeed.h"

#include <mujoco/mujoco.h>

#include <array>
#include <optional>
#include <vector>

namespace semhap {

/** The feed's MuJoCo side, shared with the renderer inside sim/ only. */
struct SceneFeed::Private
{
    Private();
    ~Private();
    std::array<mjvScene, 3> scenes;
    mjvOption option;
    std::array<std::vector<int>, 2> gripperBodies; ///< bodies whose geoms show the overlay
    /** Per model geom: the hand it belongs to (0 left, 1 right), or -1. */
    std::vector<int> geomHand;
    /** Per scene buffer: the hands' wrists when it was captured. */
    std::array<std::array<std::optional<Pose>, 2>, 3> hands;
};

} // namespace semhap
