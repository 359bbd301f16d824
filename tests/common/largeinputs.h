// SPDX-License-Identifier: MIT
// Large inputs of realistic shape, generated: the benchmarks time them and the fuzzers
// start from them, so that work growing faster than the input shows as a timeout.
#pragma once

#include <QByteArray>
#include <QJsonObject>

namespace semhap {

/**
 * An AHAP file of `events` events, alternating transients and short continuous ones 20 ms
 * apart with intensities that vary, and an intensity curve every 100 events.
 */
QByteArray largeAhap(int events);
/** A `.haptic` file of `points` amplitude breakpoints, one emphasis every tenth. */
QByteArray largeHaptic(int points);
/**
 * A router of about `nodes` nodes: force detectors, each behind it a chain of eight
 * filters and a pattern node, all driving one of eight vibrotactile bands.
 */
QJsonObject largeRouter(int nodes);

} // namespace semhap
