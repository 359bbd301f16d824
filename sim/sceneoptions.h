// SPDX-License-Identifier: MIT
#pragma once

namespace semhap {

/** Scene parameters a user may set (semhap run --cubes, the studio's scene picker). */
struct SceneOptions
{
    int cubes = -1; ///< how many of the scene's cube_K bodies stay in play; -1: its default
};

} // namespace semhap
