// SPDX-License-Identifier: MIT
#include "gamepadmapping.h"

namespace semhap {

namespace {

// The button pairs a motion may use: two buttons that face each other on a pad.
const char *const ButtonPairs[] = {"dpleft+dpright", "dpdown+dpup", "leftshoulder+rightshoulder",
                                   "x+b", "a+y"};

constexpr double MaxDeadZone = 0.9;

} // namespace

const QStringList &GamepadMapping::axisNames()
{
    // SDL_GameControllerGetStringForAxis's names, SDL_CONTROLLER_AXIS_LEFTX first.
    static const QStringList names{QStringLiteral("leftx"),       QStringLiteral("lefty"),
                                   QStringLiteral("rightx"),      QStringLiteral("righty"),
                                   QStringLiteral("lefttrigger"), QStringLiteral("righttrigger")};
    return names;
}

const QStringList &GamepadMapping::buttonNames()
{
    // SDL_GameControllerGetStringForButton's names, SDL_CONTROLLER_BUTTON_A first.
    static const QStringList names{QStringLiteral("a"),
                                   QStringLiteral("b"),
                                   QStringLiteral("x"),
                                   QStringLiteral("y"),
                                   QStringLiteral("back"),
                                   QStringLiteral("guide"),
                                   QStringLiteral("start"),
                                   QStringLiteral("leftstick"),
                                   QStringLiteral("rightstick"),
                                   QStringLiteral("leftshoulder"),
                                   QStringLiteral("rightshoulder"),
                                   QStringLiteral("dpup"),
                                   QStringLiteral("dpdown"),
                                   QStringLiteral("dpleft"),
                                   QStringLiteral("dpright")};
    return names;
}

GamepadMapping GamepadMapping::defaults()
{
    GamepadMapping mapping;
    // SDL's stick y axes grow downwards: pushing a stick up is negative.
    mapping.motions[Forward] = QStringLiteral("-lefty");
    mapping.motions[Right] = QStringLiteral("leftx");
    mapping.motions[Up] = QStringLiteral("-righty");
    mapping.motions[Turn] = QStringLiteral("-rightx");
    mapping.motions[Tilt] = QStringLiteral("leftshoulder+rightshoulder");
    mapping.motions[Roll] = QStringLiteral("dpleft+dpright");
    mapping.motions[Grip] = QStringLiteral("righttrigger");
    mapping.actions[ToggleGrip] = QStringLiteral("a");
    mapping.actions[SwitchHand] = QStringLiteral("y");
    mapping.actions[GripStronger] = QStringLiteral("dpup");
    mapping.actions[GripWeaker] = QStringLiteral("dpdown");
    mapping.actions[HandBack] = QStringLiteral("b");
    mapping.actions[NextCamera] = QStringLiteral("x");
    return mapping;
}

QString GamepadMapping::motionKey(Motion motion)
{
    static const char *const keys[MotionCount] = {"forward", "right", "up",  "turn",
                                                  "tilt",    "roll",  "grip"};
    return QLatin1String(keys[motion]);
}

QString GamepadMapping::actionKey(Action action)
{
    static const char *const keys[ActionCount] = {"togglegrip", "switchhand", "gripstronger",
                                                  "gripweaker", "handback",   "nextcamera"};
    return QLatin1String(keys[action]);
}

QStringList GamepadMapping::motionChoices()
{
    QStringList choices{QString()};
    for (const QString &axis : axisNames())
        choices << axis << QLatin1Char('-') + axis;
    for (const char *pair : ButtonPairs)
        choices << QLatin1String(pair);
    return choices;
}

QStringList GamepadMapping::buttonChoices()
{
    return QStringList{QString()} + buttonNames();
}

QString GamepadMapping::toString() const
{
    QStringList parts;
    for (int m = 0; m < MotionCount; ++m)
        parts << motionKey(Motion(m)) + QLatin1Char('=') + motions[size_t(m)];
    for (int a = 0; a < ActionCount; ++a)
        parts << actionKey(Action(a)) + QLatin1Char('=') + actions[size_t(a)];
    parts << QStringLiteral("deadzone=") + QString::number(deadZone);
    return parts.join(QLatin1Char(';'));
}

std::optional<GamepadMapping> GamepadMapping::fromString(const QString &text, QString *error)
{
    GamepadMapping mapping = defaults();
    const QStringList motionValues = motionChoices();
    const QStringList buttonValues = buttonChoices();
    for (const QString &part : text.split(QLatin1Char(';'), Qt::SkipEmptyParts)) {
        const qsizetype equals = part.indexOf(QLatin1Char('='));
        const QString key = part.left(equals).trimmed();
        const QString value = equals < 0 ? QString() : part.mid(equals + 1).trimmed();
        auto fail = [&](const QString &why) {
            if (error)
                *error = QStringLiteral("key '%1': %2").arg(key, why);
            return std::nullopt;
        };
        if (equals < 0)
            return fail(QStringLiteral("expected key=value"));
        bool known = false;
        for (int m = 0; m < MotionCount && !known; ++m) {
            if (key != motionKey(Motion(m)))
                continue;
            if (!motionValues.contains(value))
                return fail(QStringLiteral("unknown control '%1'").arg(value));
            mapping.motions[size_t(m)] = value;
            known = true;
        }
        for (int a = 0; a < ActionCount && !known; ++a) {
            if (key != actionKey(Action(a)))
                continue;
            if (!buttonValues.contains(value))
                return fail(QStringLiteral("unknown button '%1'").arg(value));
            mapping.actions[size_t(a)] = value;
            known = true;
        }
        if (!known && key == QLatin1String("deadzone")) {
            bool ok = false;
            const double deadZone = value.toDouble(&ok);
            if (!ok || !(deadZone >= 0.0 && deadZone <= MaxDeadZone))
                return fail(QStringLiteral("expected a number from 0 to %1").arg(MaxDeadZone));
            mapping.deadZone = deadZone;
            known = true;
        }
        if (!known)
            return fail(QStringLiteral("unknown key"));
    }
    return mapping;
}

} // namespace semhap
