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
};

} // namespace semhap
