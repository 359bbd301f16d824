// SPDX-License-Identifier: MIT
#pragma once

#include <QStringList>

#include <array>

namespace semhap {

/**
 * A person's reaction time to a cue at the wrist (s): part of the predict node's default
 * horizon, the simulated operator's delay, and how early a warning must be felt to count as
 * in time (docs/metrics.md).
 */
constexpr double DefaultReactionTime = 0.25;

/**
 * The contacts a full, steady grasp of the bundled gripper touches (two pads of 4 × 4
 * taxels): the grasp the slip detector's contact counts are written for.
 */
constexpr int ReferenceFullContacts = 32;

/**
 * Facts of one gripper that its detectors' parameters are fitted to when a router is
 * compiled (docs/detectors.md, "Fitted to the gripper"); the defaults are the bundled
 * gripper's, for which the parameters run as written.
 */
struct GripperTraits
{
    /**
     * The contacts a full, steady grasp of this gripper touches, both fingertips together
     * (its pad geoms); the bundled gripper's 32 is the reference. Below 1: not known, as 32.
     */
    int fullContacts = ReferenceFullContacts;
    /**
     * How far a steady grip's measured force swings on this gripper, lowest to highest (N):
     * the force detector's hysteresis is never less.
     */
    double forceRipple = 0.0;
};

/** What a router is compiled for besides its graph: facts of the run it serves. */
struct RouterContext
{
    double reactionTime = DefaultReactionTime; ///< of the person the router warns (s)
    /**
     * Whether the source says in advance which named signals its frames carry (a scene
     * declares them): then a signal node naming another is refused. Unknown (a file, a live
     * rig): any name is taken.
     */
    bool knowsSignals = false;
    /**
     * The named signals the source's frames carry, per gripper (left, right): a scene's
     * declared ones; a live rig's seen so far, offered by the router editor, not checked.
     */
    std::array<QStringList, 2> signalNames;
    /** The grippers' traits (left, right): what their detectors are fitted to. */
    std::array<GripperTraits, 2> grippers;
};

} // namespace semhap
