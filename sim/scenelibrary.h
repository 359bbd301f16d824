// SPDX-License-Identifier: MIT
#pragma once

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
    static QStringList builtinNames();
    /** Compiles a built-in scene or an MJCF file; null with a one-line `error`. */
    static MjModelPtr load(const QString &nameOrPath, const SceneOptions &options, QString *error);
};

} // namespace semhap
