// SPDX-License-Identifier: MIT
#pragma once

#include <QString>

namespace semhap {

/** Scene parameters a user may set (semhap run --cubes/--gripper, the studio's scene picker). */
struct SceneOptions
{
    int cubes = -1; ///< how many of the scene's cube_K bodies stay in play; -1: its default
    /**
     * A gripper adapter file (`semhap.gripper/1`, docs/grippers.md) whose model takes the
     * place of the scene's own grippers; empty: the scene's own.
     */
    QString gripper;
};

} // namespace semhap
