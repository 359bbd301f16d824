// SPDX-License-Identifier: MIT
#pragma once

namespace semhap {

/**
 * What one router node passes on from time t: the messages it lets through (a detector its
 * own, a filter those that match, a gate those it lets by, a pattern node those it plays)
 * and their highest intensity. The node editor's live wires show these, so they show what
 * really routed.
 */
struct NodeActivity
{
    double t = 0.0;
    int node = -1;          ///< index into Router::nodeIds
    double level = -1.0;    ///< the highest intensity passed on; -1 when nothing passes
    unsigned messages = 0;  ///< one bit per Message passed on (1 << int(message))
    bool exception = false; ///< whether any message passed on is an exception

    bool isActive() const { return level >= 0.0; }
};

} // namespace semhap
