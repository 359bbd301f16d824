// SPDX-License-Identifier: MIT
#pragma once

#include "haptictimeline.h"
#include "loaderror.h"

#include <QJsonObject>
#include <QStringList>

namespace semhap {

/** The file formats `semhap convert` and the designer read and write, by extension. */
enum class HapticFileFormat
{
    Semhap,     ///< `.json`: a `semhap.pattern/1` document
    Ahap,       ///< `.ahap`: Apple Core Haptics
    MetaHaptic, ///< `.haptic`: Meta Haptics Studio
    /**
     * `.hjif`: MPEG haptics (ISO/IEC 23090-31) as JSON. Converted by the hjif module
     * (HjifConverter), which knows device models; HapticConverter only names it.
     */
    Hjif
};

/** How to map between a haptic file and a semhap pattern; see `docs/convert.md`. */
struct ConvertOptions
{
    /**
     * Import: the new pattern's device model; empty: `lra4` for AHAP and `.haptic`, the
     * file's own device for HJIF.
     */
    QString model;
    /**
     * Import: the one channel the new pattern drives (empty: every channel, `"*"`).
     * Export: the channel whose tracks are written (empty: every track, the loudest wins).
     */
    QString channel;
    /**
     * Only when asked (`--modulate`): the frequency (Hz) of an amplitude modulation that
     * sharpness 1 maps to, so a device without a carrier of its own feels sharpness as a
     * buzz. 0, the default: the envelope is left as it is and sharpness only kept.
     */
    double modulationLimit = 0.0;
    /** Export: when the pattern ends (s); < 0: after the attack, plus 1 s of a live sustain. */
    double releaseAt = -1.0;
    /** Export: seconds rendered; < 0: up to the end of the longest release. */
    double duration = -1.0;
    QString name; ///< import: the pattern's name; empty: the file's base name
    /** HJIF import: the perception read (its id); < 0: the first the model can play. */
    int perception = -1;
    /** HJIF import: the library effect read (its id); < 0: every channel's whole content. */
    int effect = -1;
    /** HJIF export: the hand wearing the band, `left` or `right`; empty: either. */
    QString hand;
};

/**
 * Converts between semhap patterns and the haptic files users already have (AHAP and
 * `.haptic`). An imported file becomes a one-shot pattern: its envelope is the attack (as
 * keyframes), its sharpness the pattern's `sharpness` (and, if asked, an amplitude
 * modulation); an exported pattern is rendered from a begin to an end and written as an
 * envelope with that sharpness. What does not map is listed as warnings.
 */
class HapticConverter
{
public:
    /** The format of `path` by its extension; false with `error` for any other. */
    static bool formatOf(const QString &path, HapticFileFormat *format, LoadError *error);

    /** Reads a file of any of the formats as a semhap pattern document (not yet parsed). */
    static bool readPattern(const QString &path, const ConvertOptions &options,
                            QJsonObject *pattern, QStringList *warnings, LoadError *error);
    /** The same from bytes; `file` names the input in messages and gives its format. */
    static bool parsePattern(const QByteArray &bytes, const QString &file,
                             const ConvertOptions &options, QJsonObject *pattern,
                             QStringList *warnings, LoadError *error);
    /** Writes a semhap pattern document in the format of `path`'s extension. */
    static bool writePattern(const QJsonObject &pattern, const QString &path,
                             const ConvertOptions &options, QStringList *warnings,
                             LoadError *error);
    /** The bytes writePattern would write; `file` names the pattern in messages. */
    static bool serialize(const QJsonObject &pattern, HapticFileFormat format, const QString &file,
                          const ConvertOptions &options, QByteArray *bytes, QStringList *warnings,
                          LoadError *error);

    /** A keyframes waveform through the curve's points, from 0 s. */
    static QJsonObject keyframes(const EnvelopeCurve &curve);
    /** A track that plays `attack` once on begin on `channels`, then is silent. */
    static QJsonObject oneShotTrack(const QStringList &channels, const QJsonValue &attack);
    /** An imported pattern of `tracks` (oneShotTrack), named and modelled by `options`. */
    static QJsonObject oneShotPattern(const QJsonArray &tracks, const ConvertOptions &options,
                                      const QString &description);
    /**
     * When an export of `tracks` (indices) of `pattern` ends the pattern and how long it
     * renders (`ConvertOptions::releaseAt`, `duration`), with a warning when a sustain is
     * cut to DefaultHold; false with `error` beyond MaxDuration.
     */
    static bool span(const QJsonObject &pattern, const QString &file,
                     const ConvertOptions &options, const std::vector<int> &tracks,
                     double *releaseAt, double *duration, QStringList *warnings, LoadError *error);
    /** A one-shot pattern playing `timeline` on begin. */
    static QJsonObject timelineToPattern(const HapticTimeline &timeline,
                                         const ConvertOptions &options, const QString &source);
    /** Renders a pattern document (validated first) into a timeline. */
    static bool patternToTimeline(const QJsonObject &pattern, const QString &file,
                                  const ConvertOptions &options, HapticTimeline *timeline,
                                  QStringList *warnings, LoadError *error);

    /** Samples per second when a pattern is rendered for export. */
    static constexpr double RenderRate = 1000.0;
    /** The longest stretch an export renders (10 minutes at 1 kHz are 600 000 samples). */
    static constexpr double MaxDuration = 600.0;
    /** Seconds a live sustain (or an endless attack) is rendered when no end is given. */
    static constexpr double DefaultHold = 1.0;
};

} // namespace semhap
