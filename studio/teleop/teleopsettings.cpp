// SPDX-License-Identifier: MIT
#include "teleopsettings.h"

#include "handdrive.h"

#include <QSettings>

#include <algorithm>

namespace semhap {

namespace {
const QString SpeedKey = QStringLiteral("teleop/speed");
const QString GamepadKey = QStringLiteral("teleop/gamepad");
const QString MappingKey = QStringLiteral("teleop/gamepadMapping");
const QString SpaceMouseKey = QStringLiteral("teleop/spaceMouse");
const QString SpaceMouseDeadZoneKey = QStringLiteral("teleop/spaceMouseDeadZone");
constexpr double MaxDeadZone = 0.5;
} // namespace

TeleopSettings TeleopSettings::load()
{
    QSettings settings;
    TeleopSettings loaded;
    loaded.speed = std::clamp(settings.value(SpeedKey, loaded.speed).toDouble(),
                              HandDrive::MinSpeed, HandDrive::MaxSpeed);
    loaded.gamepad = settings.value(GamepadKey, loaded.gamepad).toBool();
    QString error;
    if (const std::optional<GamepadMapping> mapping =
            GamepadMapping::fromString(settings.value(MappingKey).toString(), &error))
        loaded.gamepadMapping = *mapping;
    loaded.spaceMouse = settings.value(SpaceMouseKey, loaded.spaceMouse).toBool();
    loaded.spaceMouseDeadZone =
        std::clamp(settings.value(SpaceMouseDeadZoneKey, loaded.spaceMouseDeadZone).toDouble(),
                   0.0, MaxDeadZone);
    return loaded;
}

void TeleopSettings::save() const
{
    QSettings settings;
    settings.setValue(SpeedKey, speed);
    settings.setValue(GamepadKey, gamepad);
    settings.setValue(MappingKey, gamepadMapping.toString());
    settings.setValue(SpaceMouseKey, spaceMouse);
    settings.setValue(SpaceMouseDeadZoneKey, spaceMouseDeadZone);
}

} // namespace semhap
