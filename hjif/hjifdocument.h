// SPDX-License-Identifier: MIT
#pragma once

#include "loaderror.h"

#include <QJsonObject>
#include <QString>
#include <QStringList>

#include <optional>
#include <vector>

namespace semhap {

/** One keyframe of an effect: its time from the effect's start, in the file's ticks. */
struct HjifKeyframe
{
    qint64 position = 0;
    std::optional<double> amplitude; ///< amplitude_modulation, −1…1
    std::optional<int> frequency;    ///< frequency_modulation, Hz
};

/** An effect: keyframes at a position, or a reference to a library effect by id. */
struct HjifEffect
{
    enum class Type
    {
        Basis,
        Reference,
        Composite
    };
    Type type = Type::Basis;
    int id = -1;         ///< a library effect's own id; a Reference's target
    qint64 position = 0; ///< ticks from the start (of the channel, or of a referring effect)
    QString semantic;    ///< semantic_keywords, empty when none
    QString baseSignal;  ///< base_signal (Sine, Square, …), empty when none
    double phase = 0.0;  ///< radians
    std::vector<HjifKeyframe> keyframes;
    QString pointer; ///< where it is in the file, for messages
};

/** A frequency band of a channel and its effects. */
struct HjifBand
{
    enum class Type
    {
        Transient,
        Curve,
        VectorialWave,
        WaveletWave
    };
    Type type = Type::Curve;
    QString curveType; ///< Curve bands: Linear, Cubic, …; empty when the file gives none
    int lowerFrequency = 0;
    int upperFrequency = 0;
    std::vector<HjifEffect> effects;
    QString pointer;
};

/** One actuator's signal: its bands, where it is worn and which reference device plays it. */
struct HjifChannel
{
    int id = 0;
    QString description;
    double gain = 1.0;
    double mixingCoefficient = 1.0;
    quint32 bodyPartMask = 0;
    std::optional<int> referenceDevice;
    std::vector<HjifBand> bands;
    QString pointer;
};

/** The device a perception was designed for, as the standard describes one. */
struct HjifReferenceDevice
{
    int id = 1;
    QString name;
    std::optional<quint32> bodyPartMask;
    std::optional<double> minimumFrequency;
    std::optional<double> maximumFrequency;
    std::optional<double> resonanceFrequency;
    std::optional<double> maximumAmplitude;
    std::optional<double> maximumDisplacement;
    std::optional<double> weight;
    std::optional<double> size;
    QString type; ///< Unknown, LRA, VCA, ERM or Piezo; empty when not given
};

/** A perception: one sense (modality) on one avatar, its channels and its effect library. */
struct HjifPerception
{
    int id = 0;
    int avatarId = 0;
    QString description;
    QString modality;
    std::vector<HjifEffect> library;
    std::vector<HjifReferenceDevice> devices;
    std::vector<HjifChannel> channels;
    QString pointer;
};

/**
 * An MPEG haptics file (ISO/IEC 23090-31) in its JSON form, HJIF: the keys the MPEG reference
 * software reads and writes, as values (docs/convert.md). Reading checks types, ranges,
 * enumerations and references, and names the JSON pointer of the first problem; keys it does
 * not know are listed as warnings and ignored.
 */
struct HjifDocument
{
    QString version = QStringLiteral("2023");
    QString profile = QStringLiteral("Main");
    int level = 1;
    QString date;
    QString description;
    qint64 timescale = 1000; ///< ticks per second
    std::vector<HjifPerception> perceptions;

    /** Reads `json`; false with `error` (`FILE: /pointer: reason`). */
    static bool fromJson(const QJsonObject &json, const QString &file, HjifDocument *document,
                         QStringList *warnings, LoadError *error);
    QJsonObject toJson() const;

    /** The perception of `id`, or null. */
    const HjifPerception *perception(int id) const;

    /**
     * The most elements (keyframes, effects, bands and channels together) a file may hold:
     * what bounds the memory and the work of reading one.
     */
    static constexpr qint64 MaxElements = 2'000'000;
    /** Body-part bits of the standard's mask (the reference software's). */
    static constexpr quint32 RightWrist = 0x00004000;
    static constexpr quint32 LeftWrist = 0x00008000;
    static constexpr quint32 RightFingers = 0x00100000;
    static constexpr quint32 LeftFingers = 0x00200000;

    static QString bandTypeName(HjifBand::Type type);
    static QString effectTypeName(HjifEffect::Type type);
    /** The perception modalities the standard names. */
    static const QStringList &modalities();
    static const QStringList &baseSignals();
    static const QStringList &curveTypes();
    static const QStringList &actuatorTypes();
};

} // namespace semhap
