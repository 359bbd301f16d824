// SPDX-License-Identifier: MIT
#pragma once

#include "devicemodel.h"
#include "envelopecurve.h"
#include "hjifdocument.h"

namespace semhap {

/**
 * Renders a perception's channels as the envelopes semhap devices play (docs/convert.md):
 * each band's effects over seconds, library references followed, combined by their maximum.
 * A device with a carrier of its own (an LRA) takes a wave's amplitude; one without (a
 * bellows) takes the wave itself, raised to 0…amplitude (its mean level when faster than
 * the device follows). The work is bounded: a reference
 * plays one library effect, never another reference (in the library an effect's id is its
 * own, so a reference there names itself); at most MaxPoints points; nothing past
 * MaxDuration.
 */
class HjifRenderer
{
public:
    HjifRenderer(const HjifDocument &document, const HjifPerception &perception,
                 const DeviceModel &model, const QString &file, QStringList *warnings);

    /**
     * The envelope of `channel`, from 0 s. With `effect` ≥ 0, only what refers to library
     * effect `effect`, moved to start at 0; `found` says whether anything did. False with
     * `error` (located) when the file cannot be played.
     */
    bool render(const HjifChannel &channel, int effect, EnvelopeCurve *out, bool *found,
                LoadError *error);

    /** The most envelope points one import may make. */
    static constexpr qint64 MaxPoints = 4'000'000;
    /** The latest time an import plays to (s), as an export renders at most. */
    static constexpr double MaxDuration = 600.0;
    /** Seconds a transient lasts (the reference software's 22 ms). */
    static constexpr double TransientWidth = 0.022;
    /** Seconds between samples of curves that are not straight (cubic, raised waves). */
    static constexpr double Step = 0.001;

private:
    bool effect(const HjifBand &band, const HjifEffect &effect, double offset,
                std::vector<EnvelopeCurve> *out);
    bool basis(const HjifBand &band, const HjifEffect &effect, double start,
               std::vector<EnvelopeCurve> *out);
    bool curveOf(const HjifBand &band, const HjifEffect &effect, double start, EnvelopeCurve *out);
    bool wave(const HjifEffect &effect, double start, EnvelopeCurve *out);
    bool spend(qint64 points, const QString &pointer);
    bool checkEnd(double t, const QString &pointer);
    void warnOnce(const QString &key, const QString &pointer, const QString &reason);

    const HjifDocument &m_document;
    const HjifPerception &m_perception;
    bool m_carrier;
    double m_followLimit; ///< Hz: the fastest wave a device without a carrier follows
    QString m_file;
    QStringList *m_warnings;
    QStringList m_warned;
    LoadError m_error;
    qint64 m_points = 0;
};

} // namespace semhap
