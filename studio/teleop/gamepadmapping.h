// SPDX-License-Identifier: MIT
#pragma once

#include <QString>
#include <QStringList>

#include <array>
#include <optional>

namespace semhap {

/**
 * Which game-controller control drives each motion and action of the hand drive, named by
 * SDL's game-controller names ("leftx", "righttrigger", "a", "dpup"), so any controller SDL
 * knows maps the same way. A value: Preferences edits it, settings store it as text.
 *
 * A motion is driven by an axis ("leftx"), an axis reversed ("-lefty"), a pair of buttons
 * ("dpleft+dpright": the first drives towards -1, the second towards +1), or nothing ("").
 * An action is a button, or nothing. The defaults are in docs/studio.md.
 */
struct GamepadMapping
{
    enum Motion
    {
        Forward,
        Right,
        Up,
        Turn,
        Tilt,
        Roll,
        Grip, ///< an analogue grip: a trigger or a stick half (0 open … 1 full grip force)
        MotionCount
    };
    enum Action
    {
        ToggleGrip,
        SwitchHand,
        GripStronger,
        GripWeaker,
        HandBack,   ///< gives the grippers back to the scripted operator
        NextCamera, ///< the viewport's next camera preset
        ActionCount
    };

    std::array<QString, MotionCount> motions;
    std::array<QString, ActionCount> actions;
    /** Stick deflection (fraction of full) that counts as none: worn sticks rest off-centre. */
    double deadZone = 0.15;

    /** The documented default mapping. */
    static GamepadMapping defaults();

    /** The settings text: "forward=-lefty;right=leftx;…;deadzone=0.15". */
    QString toString() const;
    /**
     * Reads toString()'s text; keys it leaves out keep their defaults. None with `error`
     * naming the key and why ("key 'turn': unknown control 'rightz'").
     */
    static std::optional<GamepadMapping> fromString(const QString &text, QString *error);

    /** The settings keys and the names Preferences shows, in order. */
    static QString motionKey(Motion motion);
    static QString actionKey(Action action);
    /** Everything a motion may be bound to: "", axes, reversed axes, button pairs. */
    static QStringList motionChoices();
    /** Everything an action may be bound to: "" and the buttons. */
    static QStringList buttonChoices();
    /** SDL's axis names, in SDL_GameControllerAxis order. */
    static const QStringList &axisNames();
    /** SDL's button names, in SDL_GameControllerButton order. */
    static const QStringList &buttonNames();

    bool operator==(const GamepadMapping &other) const
    {
        return motions == other.motions && actions == other.actions && deadZone == other.deadZone;
    }
    bool operator!=(const GamepadMapping &other) const { return !(*this == other); }
};

} // namespace semhap
