// SPDX-License-Identifier: MIT
#pragma once

#include <QStringList>

namespace semhap {

class World;
struct GripperAdapter;

/**
 * What is likely wrong with a loaded scene's grippers, each with the element at fault and
 * the fix (docs/grippers.md, "What validate warns about"): fingers that can collide with each
 * other, pads whose contact priority puts their friction over the objects', a steady grip
 * that rings, a full grasp of too few pad geoms for the slip counts, fingers that do not close
 * along the wrist's y axis or not the way the adapter says, objects wider than the opening.
 * The ringing is measured by a short hold on a copy of the scene, so this is for validate,
 * not for every load.
 */
class GripperCheck
{
public:
    /**
     * The warnings for `world`, loaded from `scene` with `adapter` (null for the scene's own
     * grippers). Loads the scene again for the hold.
     */
    static QStringList warnings(const World &world, const QString &scene,
                                const GripperAdapter *adapter);
};

} // namespace semhap
