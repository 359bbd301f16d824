// SPDX-License-Identifier: MIT
#pragma once

#include "loaderror.h"

#include <QString>
#include <QStringList>

#include <array>

namespace semhap {

/**
 * A gripper adapter (`semhap.gripper/1`, docs/grippers.md): what semhap needs to know of a
 * gripper model it did not write, so the model file stays as downloaded. It names the model
 * (relative to the adapter), the body to mount, the two fingers' joints and pads and which
 * way they close, and the force the actuators may give.
 */
struct GripperAdapter
{
    static constexpr const char *Format = "semhap.gripper/1";

    /** One finger, in semhap's sides: `left` closes towards the gripper frame's -y. */
    struct Finger
    {
        QString joint;    ///< the joint its force motor drives
        QStringList pads; ///< bodies (their colliding geoms) or geoms that touch what is held
    };

    QString file;      ///< the adapter, as the user named it
    QString name;      ///< what pickers show
    QString model;     ///< the MJCF, absolute
    QString modelName; ///< the MJCF as the adapter names it (for messages)
    QString root;      ///< the body whose subtree is the gripper
    bool hasMount = false;
    std::array<double, 3> mountPos{};
    std::array<double, 4> mountQuat{1, 0, 0, 0};
    std::array<Finger, 2> fingers; ///< left, right
    /** +1: the fingers' joints close with increasing position; -1: with decreasing. */
    int closing = 1;
    double maxForce = 100.0; ///< the highest total grip (N, both fingers)
    double openForce = 40.0; ///< the total force that opens the fingers (N)
    /**
     * The damping of each pad's motion (N·s/m) that stands in for the velocity term of the
     * servo the model's actuator was (left out with it); semhap's own fingers have 60.
     */
    double damping = 60.0;
    /**
     * Whether only the pads collide (the rest of the model passes through what it meets, as
     * semhap's own fingers' links do); else every geom collides as the model says.
     */
    bool padsOnly = false;
    /** Overrides of what the loader measures (docs/grippers.md); 0 or less: measured. */
    int fullContacts = 0;
    double forceRipple = -1.0;

    /** Reads and checks an adapter; false with `FILE: /pointer: reason` in `error`. */
    static bool read(const QString &path, GripperAdapter *out, LoadError *error);
};

} // namespace semhap
