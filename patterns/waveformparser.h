// SPDX-License-Identifier: MIT
#pragma once

#include "envelopes.h"
#include "jsonreader.h"
#include "waveform.h"
#include "waveformtype.h"

#include <QJsonObject>
#include <QJsonValue>
#include <QLatin1String>
#include <QString>

#include <vector>

namespace semhap {

/**
 * Reads waveforms and numbers from their JSON form, resolving parameter names against a
 * table, and reports the first mistake as `FILE: /json/pointer: reason` so a user can find
 * it. Ranges are checked on constants; parameter-bound values are clamped when sampled.
 */
class WaveformParser : public JsonReader
{
public:
    WaveformParser(const ParamTable &params, const QString &file);

    /** A waveform tree, or null with error() set; `pointer` locates `json` in its document. */
    WaveformPtr parse(const QJsonValue &json, const QString &pointer);
    /** A Number (constant or `{"param": …}`); false with error() set. */
    bool parseNumber(const QJsonValue &json, const QString &pointer, Number *out);

private:
    /**
     * Checks `object`'s keys against `type`'s fields and that the required ones are there;
     * then reads its Number fields, in the table's order, into `numbers` (defaults for the
     * absent ones), checking constants against their ranges.
     */
    bool fields(const QJsonObject &object, const QString &pointer, const WaveformType &type,
                std::vector<Number> *numbers);
    bool pairs(const QJsonValue &json, const QString &pointer,
               std::vector<std::pair<double, double>> *out);
    bool startValue(const QJsonObject &object, const QString &pointer, StartValue *out);
    bool bound(const QJsonObject &object, const QString &pointer, QLatin1String nameKey,
               Number *out);
    bool children(const QJsonObject &object, const QString &pointer,
                  std::vector<WaveformPtr> *out);

    WaveformPtr parseConst(const QJsonObject &object, const QString &pointer);
    WaveformPtr parseParam(const QJsonObject &object, const QString &pointer);
    WaveformPtr parseRamp(const QJsonObject &object, const QString &pointer);
    WaveformPtr parseKeyframes(const QJsonObject &object, const QString &pointer);
    WaveformPtr parseSine(const QJsonObject &object, const QString &pointer);
    WaveformPtr parseSquare(const QJsonObject &object, const QString &pointer);
    WaveformPtr parsePulses(const QJsonObject &object, const QString &pointer);
    WaveformPtr parseSum(const QJsonObject &object, const QString &pointer);
    WaveformPtr parseProduct(const QJsonObject &object, const QString &pointer);
    WaveformPtr parseSequence(const QJsonObject &object, const QString &pointer);
    WaveformPtr parseScale(const QJsonObject &object, const QString &pointer);
    WaveformPtr parseClip(const QJsonObject &object, const QString &pointer);

    const ParamTable &m_params;
};

} // namespace semhap
