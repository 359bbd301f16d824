// SPDX-License-Identifier: MIT
#pragma once

#include "gripperadapter.h"

#include <QString>

#include <array>

namespace semhap {

class MjcfElement;

/**
 * Puts an adapter's gripper model into a scene's wrists, in the MJCF before MuJoCo compiles
 * it (MuJoCo 2.2 cannot nest one model in another): what the bundled gripper had inside
 * `<hand>.gripper` goes, with everything that names it; the model's root body goes there
 * instead, at the mount, with its defaults, assets, contacts, tendons, equalities and
 * sensors, every name prefixed `<hand>.model.`; the pads become `<hand>.tip.<side>.K` and the
 * fingers get semhap's force motors `<hand>.grip.<side>`. The model's own actuators, options
 * and keyframes are left out (docs/grippers.md).
 */
class GripperComposer
{
public:
    /** Where the model's root goes in the wrist's frame. */
    struct Mount
    {
        std::array<double, 3> pos{};
        std::array<double, 4> quat{1, 0, 0, 0};
    };

    /**
     * Replaces the grippers of `scene` (a parsed MJCF) by the adapter's model at `mount`;
     * false with a one-line `error` naming the file at fault.
     */
    static bool compose(MjcfElement *scene, const GripperAdapter &adapter, const Mount &mount,
                        QString *error);
};

} // namespace semhap
