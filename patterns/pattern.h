// SPDX-License-Identifier: MIT
#pragma once

#include "loaderror.h"
#include "waveform.h"

#include <QJsonObject>
#include <QString>
#include <QStringList>

#include <memory>
#include <vector>

namespace semhap {

/**
 * One track of a pattern: the channels it drives and its lifecycle. The attack plays from
 * begin, the sustain follows it while the pattern is active, the release plays from end;
 * each starts from wherever the track's value is (WaveformContext::from).
 */
struct PatternTrack
{
    QStringList channels; ///< channel names of the pattern's model; `{"*"}` means all
    WaveformPtr attack;   ///< may be null: begin goes straight to the sustain
    WaveformPtr sustain;  ///< never null (a missing sustain parses as the constant 0)
    WaveformPtr release;  ///< may be null: end drops to 0 at once; otherwise finite
    int stateSize = 0;    ///< state slots of the three waveforms together
};

/**
 * A haptic pattern as data (`"format": "semhap.pattern/1"`): a device model, named live
 * parameters and tracks. Immutable once loaded; voices play it.
 */
class Pattern
{
public:
    static constexpr const char *Format = "semhap.pattern/1";
    /** The most tracks a pattern may have: far more than a band has channels to drive. */
    static constexpr int MaxTracks = 1024;

    /**
     * Parses a pattern document. On failure returns null and fills `error` with
     * `file` and the JSON pointer of the offending value.
     */
    static std::shared_ptr<const Pattern> fromJson(const QJsonObject &json, const QString &file,
                                                   LoadError *error);
    /** Reads and parses a pattern file (errors name the file and line for bad JSON). */
    static std::shared_ptr<const Pattern> fromFile(const QString &path, LoadError *error);

    QJsonObject toJson() const;

    const QString &name() const { return m_name; }
    const QString &description() const { return m_description; }
    const QString &model() const { return m_model; }
    /**
     * The feel of the carrier, 0 (dull) … 1 (crisp), as AHAP sharpness and `.haptic`
     * frequency give it; < 0 when the pattern says nothing. It does not shape the envelope:
     * a device with a carrier of its own to set plays it, the others keep it for export.
     */
    double sharpness() const { return m_sharpness; }
    const ParamTable &params() const { return m_params; }
    const std::vector<PatternTrack> &tracks() const { return m_tracks; }
    int stateSize() const { return m_stateSize; }

private:
    QString m_name;
    QString m_description;
    QString m_model;
    double m_sharpness = -1.0;
    ParamTable m_params;
    std::vector<PatternTrack> m_tracks;
    int m_stateSize = 0;
};

using PatternPtr = std::shared_ptr<const Pattern>;

} // namespace semhap
