// SPDX-License-Identifier: MIT
#pragma once

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
};

} // namespace semhap
