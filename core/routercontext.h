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
     * The named signals the source's frames carry, per gripper (left, right), when the
     * source says so in advance (a scene declares them): a signal node naming another is
     * refused. Unknown (a file, a live rig): any name is taken.
     */
    bool knowsSignals = false;
    std::array<QStringList, 2> signalNames;
};

} // namespace semhap
