// SPDX-License-Identifier: MIT
#pragma once

#include "contactframe.h"

#include <QString>
#include <QStringList>

#include <array>
#include <vector>

// MuJoCo's handles (only sim/ includes MuJoCo's header).
struct mjModel_;
struct mjData_;

namespace semhap {

/**
 * The signals a scene declares for its grippers' frames (sim/README.md, "Signals"): each
 * `<custom><text name="signal:HAND:NAME" data="KIND ARGS..."/>` read and checked once at
 * load, then evaluated after every step into the frame's signalValues without allocating.
 */
class SceneSignals
{
public:
    /**
     * Reads the declarations of `model`; `hasHand` says which grippers the scene has.
     * False with `FILE: signal:HAND:NAME: reason` in `error` (FILE is `file`).
     */
    bool load(const mjModel_ *model, const QString &file, const std::array<bool, 2> &hasHand,
              QString *error);
    /** The names `gripper`'s frames carry, in the order declared. */
    QStringList names(Gripper gripper) const;
    /** Sets each of `gripper`'s signals, as `data` has them now, in `frame`. */
    void write(const mjModel_ *model, const mjData_ *data, Gripper gripper,
               ContactFrame *frame) const;

private:
    enum class Kind
    {
        Sensor,
        Along,
        Across,
        Distance,
        Angle,
        Speed
    };
    /** A site or a body of the model. */
    struct Place
    {
        bool site = false;
        int id = -1;
    };
    struct Signal
    {
        QString name;
        int id = -1; ///< in signalNames()
        Kind kind = Kind::Sensor;
        int sensor = -1;
        int component = -1; ///< -1: the norm
        Place a;
        Place b;
        int axisA = 0;
        int axisB = 0;
    };

    /** Parses one declaration's data into `signal`; false with the reason. */
    static bool parse(const mjModel_ *model, const QString &data, Signal *signal, QString *reason);
    static double value(const mjModel_ *model, const mjData_ *data, const Signal &signal);

    std::array<std::vector<Signal>, 2> m_signals; ///< per gripper
};

} // namespace semhap
