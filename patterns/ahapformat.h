// SPDX-License-Identifier: MIT
#pragma once

#include "haptictimeline.h"
#include "loaderror.h"

#include <QJsonObject>
#include <QStringList>

namespace semhap {

/**
 * Apple Core Haptics pattern files (AHAP, JSON): haptic events and the intensity control
 * curves read into one intensity envelope; a timeline is written back as continuous events
 * shaped by intensity control curves. What does not map is reported as warnings
 * (`docs/convert.md`).
 */
class AhapFormat
{
public:
    /**
     * Reads an AHAP document. False with `error` (`FILE: /json/pointer: reason`) when it is
     * malformed; what it holds but semhap cannot play is listed in `warnings`.
     */
    static bool read(const QJsonObject &json, const QString &file, HapticTimeline *timeline,
                     QStringList *warnings, LoadError *error);
    /** An AHAP document playing `timeline`. */
    static QJsonObject write(const HapticTimeline &timeline, const QString &description);

    /** Core Haptics refuses curves with more control points than this. */
    static constexpr int MaxCurvePoints = 16;
    /** Core Haptics plays a continuous event for at most this many seconds. */
    static constexpr double MaxEventDuration = 30.0;
};

} // namespace semhap
