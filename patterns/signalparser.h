// SPDX-License-Identifier: MIT
#pragma once

#include "envelopes.h"
#include "jsonreader.h"
#include "signal.h"

#include <QJsonObject>
#include <QJsonValue>
#include <QLatin1String>
#include <QString>

#include <vector>

namespace semhap {

/**
 * Reads signals and numbers from their JSON form, resolving parameter names against a
 * table, and reports the first mistake as `FILE: /json/pointer: reason` so a user can find
 * it. Ranges are checked on constants; parameter-bound values are clamped when sampled.
 */
class SignalParser : public JsonReader
{
public:
    SignalParser(const ParamTable &params, const QString &file);

    /** A signal tree, or null with error() set; `pointer` locates `json` in its document. */
    SignalPtr parse(const QJsonValue &json, const QString &pointer);
    /** A Number (constant or `{"param": …}`); false with error() set. */
    bool parseNumber(const QJsonValue &json, const QString &pointer, Number *out);

private:
    enum class Range
    {
        Any,
        NonNegative,
        Unit
    };

    bool number(const QJsonObject &object, const QString &pointer, QLatin1String key, Range range,
                Number *out);
    bool optionalNumber(const QJsonObject &object, const QString &pointer, QLatin1String key,
                        Range range, double defaultValue, Number *out);
    bool checkRange(const Number &number, const QString &pointer, Range range);
    bool pairs(const QJsonValue &json, const QString &pointer,
               std::vector<std::pair<double, double>> *out);
    bool startValue(const QJsonObject &object, const QString &pointer, StartValue *out);
    bool bound(const QJsonObject &object, const QString &pointer, QLatin1String nameKey,
               Number *out);
    bool children(const QJsonObject &object, const QString &pointer, std::vector<SignalPtr> *out);

    SignalPtr parseConst(const QJsonObject &object, const QString &pointer);
    SignalPtr parseParam(const QJsonObject &object, const QString &pointer);
    SignalPtr parseRamp(const QJsonObject &object, const QString &pointer);
    SignalPtr parseKeyframes(const QJsonObject &object, const QString &pointer);
    SignalPtr parseSine(const QJsonObject &object, const QString &pointer);
    SignalPtr parseSquare(const QJsonObject &object, const QString &pointer);
    SignalPtr parsePulses(const QJsonObject &object, const QString &pointer);
    SignalPtr parseSum(const QJsonObject &object, const QString &pointer);
    SignalPtr parseProduct(const QJsonObject &object, const QString &pointer);
    SignalPtr parseSequence(const QJsonObject &object, const QString &pointer);
    SignalPtr parseScale(const QJsonObject &object, const QString &pointer);
    SignalPtr parseClip(const QJsonObject &object, const QString &pointer);

    const ParamTable &m_params;
};

} // namespace semhap
