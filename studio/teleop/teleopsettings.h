// SPDX-License-Identifier: MIT
#pragma once

#include "gamepadmapping.h"

namespace semhap {

/**
 * How the user drives the grippers, as Preferences sets it and the window applies it: the
 * wrist's full speed, and which analogue devices are used and how. Stored in the studio's
 * settings; a stored mapping that does not read (an older or hand-edited file) falls back to
 * the defaults rather than leave the gamepad without controls.
 */
struct TeleopSettings
{
    double speed = 0.15; ///< m/s at a held key or full deflection (HandDrive::setSpeed)
    bool gamepad = true;
    GamepadMapping gamepadMapping = GamepadMapping::defaults();
    bool spaceMouse = true;
    double spaceMouseDeadZone = 0.05; ///< of the 3D mouse's full scale

    static TeleopSettings load();
    void save() const;
};

} // namespace semhap
