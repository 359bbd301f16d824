// SPDX-License-Identifier: MIT
#pragma once

#include "contactframe.h"

#include <array>

namespace semhap {

/**
 * What the user commanded one hand at a moment — where its wrist should be and how hard
 * it grips — so a session shows the operator's intent beside the contact it produced.
 */
struct OperatorInput
{
    double t = 0.0;
    Gripper hand = Gripper::Right;
    std::array<double, 3> pos{};                    ///< wrist target, world frame (m)
    std::array<double, 4> quat{1.0, 0.0, 0.0, 0.0}; ///< wrist orientation (w, x, y, z)
    double grip = 0.0;                              ///< total grip force (N); negative opens
};

} // namespace semhap
