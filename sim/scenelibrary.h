// SPDX-License-Identifier: MIT
#pragma once

#include "grippercomposer.h"
#include "mujocohandles.h"
#include "sceneoptions.h"

#include <QString>
#include <QStringList>

namespace semhap {

/**
 * The bundled scenes (`:/semhap/scenes/NAME.xml`) and the loader of scene files. A scene
 * declares its default cube count as `<numeric name="semhap:cubes" data="N"/>`; loading
 * with another count drops the bodies `cube_K` with K >= N before MuJoCo compiles it.
 */
class SceneLibrary
{
public:
    /** The shortest and longest simulation time step a scene may set (s). */
    static constexpr double MinTimestep = 1e-5;
    static constexpr double MaxTimestep = 0.05;

    static QStringList builtinNames();
    /**
     * The router preset made for a scene: its `<text name="semhap:router" data="PRESET"/>`
     * (in the scene file itself, not an include); empty when it names none or does not
     * read.
     */
    static QString routerPreset(const QString &nameOrPath);
    /**
     * Compiles a built-in scene or an MJCF file; null with a one-line `error`,
     * `FILE:LINE: reason` where MuJoCo or the check names a place.
     */
    static MjModelPtr load(const QString &nameOrPath, const SceneOptions &options, QString *error);
    /**
     * The same with `gripper`'s model in place of the scene's grippers, its root at `mount`
     * in the wrist (GripperComposer); `options.gripper` is not read here.
     */
    static MjModelPtr load(const QString &nameOrPath, const SceneOptions &options,
                           const GripperAdapter *gripper, const GripperComposer::Mount &mount,
                           QString *error);
};

} // namespace semhap
