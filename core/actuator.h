// SPDX-License-Identifier: MIT
#pragma once

#include <QJsonObject>
#include <QString>
#include <QStringList>

#include <limits>

namespace semhap {

class JsonReader;

/**
 * A device model's actuators as their datasheet describes them (the `actuator` object of a
 * model): what a haptics file's reference device carries. Every field is optional; a number
 * the model does not give is NaN.
 */
struct Actuator
{
    static constexpr double Unknown = std::numeric_limits<double>::quiet_NaN();

    QString type;           ///< one of types(); empty when the model does not say
    QString body;           ///< where it is worn: one of bodies(); empty when not said
    double resonance = 0.0; ///< Hz; 0 when it makes no carrier of its own (it takes levels)
    double minFrequency = Unknown;   ///< Hz, the lowest frequency it plays
    double maxFrequency = Unknown;   ///< Hz, the highest
    double maxAmplitude = Unknown;   ///< its strongest output, in amplitudeUnit
    QString amplitudeUnit;           ///< e.g. `G rms` or `N`
    double maxDisplacement = Unknown; ///< mm
    double weight = Unknown;         ///< g, one actuator
    double size = Unknown;           ///< mm, its largest dimension

    bool isEmpty() const { return toJson().isEmpty(); }
    /** Whether the device makes its own carrier: values are the carrier's amplitude. */
    bool hasCarrier() const { return resonance > 0.0; }

    /** Reads the object at `pointer`; false with the reader's located error. */
    bool read(const QJsonObject &json, const QString &pointer, JsonReader &reader);
    QJsonObject toJson() const;

    /** The actuator types a model may name: LRA, VCA, ERM, piezo, bellows. */
    static const QStringList &types();
    /** The places a band may be worn: wrist, fingers. */
    static const QStringList &bodies();
};

} // namespace semhap
