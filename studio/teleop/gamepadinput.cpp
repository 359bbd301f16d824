// SPDX-License-Identifier: MIT
#include "gamepadinput.h"

#include "handdrive.h"

#include <SDL.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace semhap {

namespace {

/** A control a motion reads, resolved from its name once per mapping. */
struct Binding
{
    SDL_GameControllerAxis axis = SDL_CONTROLLER_AXIS_INVALID;
    bool reversed = false;
    SDL_GameControllerButton negative = SDL_CONTROLLER_BUTTON_INVALID;
    SDL_GameControllerButton positive = SDL_CONTROLLER_BUTTON_INVALID;
};

Binding resolve(const QString &name)
{
    Binding binding;
    if (name.contains(QLatin1Char('+'))) {
        const QStringList buttons = name.split(QLatin1Char('+'));
        binding.negative =
            SDL_GameControllerGetButtonFromString(buttons[0].toLatin1().constData());
        binding.positive =
            SDL_GameControllerGetButtonFromString(buttons[1].toLatin1().constData());
    } else if (!name.isEmpty()) {
        binding.reversed = name.startsWith(QLatin1Char('-'));
        const QString axis = binding.reversed ? name.mid(1) : name;
        binding.axis = SDL_GameControllerGetAxisFromString(axis.toLatin1().constData());
    }
    return binding;
}

bool isTrigger(SDL_GameControllerAxis axis)
{
    return axis == SDL_CONTROLLER_AXIS_TRIGGERLEFT || axis == SDL_CONTROLLER_AXIS_TRIGGERRIGHT;
}

} // namespace

struct GamepadInput::Private
{
    struct Pad
    {
        SDL_GameController *controller = nullptr;
        SDL_JoystickID id = -1;
        QString name;
        DriveRates rates; ///< what it asked for at the last poll
    };

    std::vector<Pad> pads;
    SDL_JoystickID active = -1;
    DriveRates sent;
    bool sentAny = false;
    std::array<Binding, GamepadMapping::MotionCount> motions{};
    std::array<SDL_GameControllerButton, GamepadMapping::ActionCount> actions{};

    void bind(const GamepadMapping &mapping)
    {
        for (size_t m = 0; m < motions.size(); ++m)
            motions[m] = resolve(mapping.motions[m]);
        for (size_t a = 0; a < actions.size(); ++a) {
            actions[a] = mapping.actions[a].isEmpty()
                             ? SDL_CONTROLLER_BUTTON_INVALID
                             : SDL_GameControllerGetButtonFromString(
                                   mapping.actions[a].toLatin1().constData());
        }
    }

    /** A motion's value on `pad` in [-1, 1] (the grip in [0, 1]), dead zone taken out. */
    double read(SDL_GameController *pad, GamepadMapping::Motion motion, double deadZone) const
    {
        const Binding &binding = motions[size_t(motion)];
        double value = 0.0;
        if (binding.axis != SDL_CONTROLLER_AXIS_INVALID) {
            value = std::clamp(SDL_GameControllerGetAxis(pad, binding.axis) / 32767.0, -1.0, 1.0);
            if (binding.reversed)
                value = -value;
            // A trigger rests exactly at zero; a stick rests anywhere inside its dead zone.
            const double zone = isTrigger(binding.axis) ? 0.0 : deadZone;
            const double magnitude = std::abs(value);
            value =
                magnitude <= zone ? 0.0 : std::copysign((magnitude - zone) / (1 - zone), value);
        } else if (binding.positive != SDL_CONTROLLER_BUTTON_INVALID) {
            value = double(SDL_GameControllerGetButton(pad, binding.positive)) -
                    double(SDL_GameControllerGetButton(pad, binding.negative));
        }
        return motion == GamepadMapping::Grip ? std::max(0.0, value) : value;
    }

    DriveRates ratesOf(SDL_GameController *pad, double deadZone) const
    {
        DriveRates rates;
        rates.forward = read(pad, GamepadMapping::Forward, deadZone);
        rates.right = read(pad, GamepadMapping::Right, deadZone);
        rates.up = read(pad, GamepadMapping::Up, deadZone);
        rates.turn = read(pad, GamepadMapping::Turn, deadZone);
        rates.tilt = read(pad, GamepadMapping::Tilt, deadZone);
        rates.roll = read(pad, GamepadMapping::Roll, deadZone);
        const Binding &grip = motions[GamepadMapping::Grip];
        if (grip.axis != SDL_CONTROLLER_AXIS_INVALID ||
            grip.positive != SDL_CONTROLLER_BUTTON_INVALID)
            rates.grip = read(pad, GamepadMapping::Grip, deadZone);
        return rates;
    }
};

GamepadInput::GamepadInput(QObject *parent) : QObject(parent), d(std::make_unique<Private>())
{
    d->bind(m_mapping);
    m_timer.setInterval(PollIntervalMs);
    m_timer.setTimerType(Qt::PreciseTimer);
    connect(&m_timer, &QTimer::timeout, this, &GamepadInput::poll);
}

GamepadInput::~GamepadInput()
{
    stop();
}

void GamepadInput::setDrive(HandDrive *drive)
{
    if (m_drive && d->sentAny)
        m_drive->setRates(DriveDevice::Gamepad, DriveRates());
    m_drive = drive;
    d->sentAny = false;
}

void GamepadInput::setMapping(const GamepadMapping &mapping)
{
    m_mapping = mapping;
    d->bind(mapping);
}

bool GamepadInput::start()
{
    if (m_started)
        return true;
    // The studio owns the process's signals and windows; SDL only reads controllers, also
    // while another application has the focus (the studio's window is not SDL's).
    SDL_SetHint(SDL_HINT_NO_SIGNAL_HANDLERS, "1");
    SDL_SetHint(SDL_HINT_JOYSTICK_ALLOW_BACKGROUND_EVENTS, "1");
    if (SDL_InitSubSystem(SDL_INIT_GAMECONTROLLER) != 0) {
        m_error = QString::fromUtf8(SDL_GetError());
        return false;
    }
    m_started = true;
    m_error.clear();
    m_timer.start();
    poll();
    return true;
}

void GamepadInput::stop()
{
    if (!m_started)
        return;
    m_timer.stop();
    for (Private::Pad &pad : d->pads)
        SDL_GameControllerClose(pad.controller);
    const bool hadPads = !d->pads.empty();
    d->pads.clear();
    d->active = -1;
    if (m_drive && d->sentAny)
        m_drive->setRates(DriveDevice::Gamepad, DriveRates());
    d->sentAny = false;
    SDL_QuitSubSystem(SDL_INIT_GAMECONTROLLER);
    m_started = false;
    if (hadPads)
        emit controllersChanged();
}

QStringList GamepadInput::controllers() const
{
    QStringList names;
    for (const Private::Pad &pad : d->pads)
        names << pad.name;
    return names;
}

QString GamepadInput::activeController() const
{
    for (const Private::Pad &pad : d->pads) {
        if (pad.id == d->active)
            return pad.name;
    }
    return QString();
}

void GamepadInput::poll()
{
    if (!m_started)
        return;
    bool padsChanged = false;
    std::vector<GamepadMapping::Action> pressed;
    SDL_Event event;
    while (SDL_PollEvent(&event)) {
        switch (event.type) {
        case SDL_CONTROLLERDEVICEADDED: {
            const SDL_JoystickID id = SDL_JoystickGetDeviceInstanceID(event.cdevice.which);
            const bool known = std::any_of(d->pads.begin(), d->pads.end(),
                                           [id](const Private::Pad &pad) { return pad.id == id; });
            if (known)
                break;
            SDL_GameController *controller = SDL_GameControllerOpen(event.cdevice.which);
            if (!controller)
                break;
            Private::Pad pad;
            pad.controller = controller;
            pad.id = id;
            pad.name = QString::fromUtf8(SDL_GameControllerName(controller));
            pad.rates = d->ratesOf(controller, m_mapping.deadZone);
            d->pads.push_back(pad);
            if (d->active < 0)
                d->active = id;
            padsChanged = true;
            break;
        }
        case SDL_CONTROLLERDEVICEREMOVED: {
            const SDL_JoystickID id = event.cdevice.which;
            auto gone = std::find_if(d->pads.begin(), d->pads.end(),
                                     [id](const Private::Pad &pad) { return pad.id == id; });
            if (gone == d->pads.end())
                break;
            SDL_GameControllerClose(gone->controller);
            d->pads.erase(gone);
            if (d->active == id)
                d->active = d->pads.empty() ? -1 : d->pads.front().id;
            padsChanged = true;
            break;
        }
        case SDL_CONTROLLERBUTTONDOWN:
            for (size_t a = 0; a < d->actions.size(); ++a) {
                if (d->actions[a] == event.cbutton.button) {
                    d->active = event.cbutton.which;
                    pressed.push_back(GamepadMapping::Action(a));
                }
            }
            break;
        default:
            break;
        }
    }

    // The controller whose sticks or grip moved since the last poll takes over.
    for (Private::Pad &pad : d->pads) {
        const DriveRates rates = d->ratesOf(pad.controller, m_mapping.deadZone);
        const bool gripMoved = rates.grip && pad.rates.grip && *rates.grip != *pad.rates.grip;
        if (pad.id != d->active && ((!rates.isIdle() && pad.rates.isIdle()) || gripMoved))
            d->active = pad.id;
        pad.rates = rates;
    }
    DriveRates rates;
    for (const Private::Pad &pad : d->pads) {
        if (pad.id == d->active)
            rates = pad.rates;
    }
    const bool changed = !d->sentAny || rates.forward != d->sent.forward ||
                         rates.right != d->sent.right || rates.up != d->sent.up ||
                         rates.turn != d->sent.turn || rates.tilt != d->sent.tilt ||
                         rates.roll != d->sent.roll || rates.grip != d->sent.grip;
    if (m_drive && changed) {
        m_drive->setRates(DriveDevice::Gamepad, rates);
        d->sent = rates;
        d->sentAny = true;
    }

    for (GamepadMapping::Action action : pressed) {
        switch (action) {
        case GamepadMapping::ToggleGrip:
            if (m_drive)
                m_drive->toggleGrip();
            break;
        case GamepadMapping::SwitchHand:
            if (m_drive)
                m_drive->switchHand();
            break;
        case GamepadMapping::GripStronger:
            if (m_drive)
                m_drive->adjustGrip(1);
            break;
        case GamepadMapping::GripWeaker:
            if (m_drive)
                m_drive->adjustGrip(-1);
            break;
        default:
            emit triggered(action);
            break;
        }
    }
    if (padsChanged)
        emit controllersChanged();
}

} // namespace semhap
