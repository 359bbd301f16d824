// SPDX-License-Identifier: MIT
#pragma once

#include "envelopecurve.h"

namespace semhap {

/**
 * What a haptic file (AHAP, `.haptic`) says, reduced to what semhap's devices can play: one
 * amplitude envelope and one overall sharpness. The file formats read into it and write from
 * it; HapticConverter maps it to and from semhap patterns.
 */
struct HapticTimeline
{
    EnvelopeCurve intensity; ///< 0…1 over seconds from the start
    double sharpness = -1.0; ///< 0…1, intensity-weighted mean; < 0 when the file gives none

    /** Seconds a transient (an AHAP transient, a `.haptic` emphasis) lasts as a pulse. */
    static constexpr double TransientWidth = 0.025;
    /** Grid for combining envelopes whose maximum or product is not piecewise linear. */
    static constexpr double CombineStep = 0.001;
    /** Value error allowed when a sampled envelope is reduced to breakpoints. */
    static constexpr double SimplifyTolerance = 0.002;
};

} // namespace semhap
