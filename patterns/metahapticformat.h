// SPDX-License-Identifier: MIT
#pragma once

#include "haptictimeline.h"
#include "loaderror.h"

#include <QJsonObject>
#include <QStringList>

namespace semhap {

/**
 * Meta Haptics Studio clips (`.haptic`, JSON): the continuous signal's amplitude envelope
 * (with emphasis points as short pulses) and its frequency envelope, read into a timeline
 * and written back from one (`docs/convert.md`).
 */
class MetaHapticFormat
{
public:
    /**
     * Reads a `.haptic` document. False with `error` (`FILE: /json/pointer: reason`) when it
     * is malformed; what semhap cannot play is listed in `warnings`.
     */
    static bool read(const QJsonObject &json, const QString &file, HapticTimeline *timeline,
                     QStringList *warnings, LoadError *error);
    /** A `.haptic` document playing `timeline`. */
    static QJsonObject write(const HapticTimeline &timeline, const QString &description);
};

} // namespace semhap
