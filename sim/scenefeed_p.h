// SPDX-License-Identifier: MIT
#pragma once

#include "scenefeed.h"

#include <mujoco/mujoco.h>

#include <array>
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
};

} // namespace semhap
