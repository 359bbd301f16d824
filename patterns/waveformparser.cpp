// SPDX-License-Identifier: MIT
#include "waveformparser.h"

#include "combinators.h"
#include "oscillators.h"

#include <QJsonArray>

#include <algorithm>
#include <cmath>

namespace semhap {

WaveformParser::WaveformParser(const ParamTable &params, const QString &file)
    : JsonReader(file), m_params(params)
{}

bool WaveformParser::pairs(const QJsonValue &json, const QString &pointer,
                           std::vector<std::pair<double, double>> *out)
{
    if (!json.isArray())
        return fail(pointer, QStringLiteral("expected an array, got ") + jsonTypeName(json));
    const QJsonArray array = json.toArray();
    if (array.isEmpty())
        return fail(pointer, QStringLiteral("expected at least one point"));
    out->clear();
    for (int i = 0; i < array.size(); ++i) {
        const QString at = jsonPointerChild(pointer, i);
        const QJsonArray pair = array.at(i).toArray();
        if (!array.at(i).isArray() || pair.size() != 2)
            return fail(at, QStringLiteral("expected a pair [x, y]"));
        double x = 0.0;
        double y = 0.0;
        if (!finiteNumber(pair.at(0), jsonPointerChild(at, 0), &x) ||
            !finiteNumber(pair.at(1), jsonPointerChild(at, 1), &y)) {
            return false;
        }
        out->emplace_back(x, y);
    }
    return true;
}

bool WaveformParser::bound(const QJsonObject &object, const QString &pointer,
                           QLatin1String nameKey, Number *out)
{
    const QJsonValue name = object.value(nameKey);
    if (!name.isString()) {
        return fail(jsonPointerChild(pointer, nameKey),
                    QStringLiteral("expected a parameter name, got ") + jsonTypeName(name));
    }
    const int index = m_params.indexOf(name.toString());
    if (index < 0)
        return fail(pointer, QStringLiteral("unknown parameter ") + quoted(name.toString()));

    const QLatin1String gainKey("gain");
    const QLatin1String offsetKey("offset");
    const QLatin1String curveKey("curve");
    const bool linear = object.contains(gainKey) || object.contains(offsetKey);
    if (linear && object.contains(curveKey))
        return fail(pointer, QStringLiteral("give either 'curve' or 'gain'/'offset', not both"));
    if (object.contains(curveKey)) {
        const QString at = jsonPointerChild(pointer, curveKey);
        std::vector<std::pair<double, double>> points;
        if (!pairs(object.value(curveKey), at, &points))
            return false;
        for (size_t i = 1; i < points.size(); ++i) {
            if (points[i].first <= points[i - 1].first) {
                return fail(jsonPointerChild(at, int(i)),
                            QStringLiteral("the x values of a curve must increase"));
            }
        }
        *out = Number::bound(index, Curve::points(std::move(points)));
        return true;
    }
    if (!linear) {
        *out = Number::bound(index, Curve());
        return true;
    }
    double gain = 1.0;
    double offset = 0.0;
    if (object.contains(gainKey) &&
        !finiteNumber(object.value(gainKey), jsonPointerChild(pointer, gainKey), &gain)) {
        return false;
    }
    if (object.contains(offsetKey) &&
        !finiteNumber(object.value(offsetKey), jsonPointerChild(pointer, offsetKey), &offset)) {
        return false;
    }
    *out = Number::bound(index, Curve::linear(gain, offset));
    return true;
}

bool WaveformParser::parseNumber(const QJsonValue &json, const QString &pointer, Number *out)
{
    if (json.isDouble()) {
        double value = 0.0;
        if (!finiteNumber(json, pointer, &value))
            return false;
        *out = Number(value);
        return true;
    }
    if (!json.isObject()) {
        return fail(pointer, QStringLiteral("expected a number or a {\"param\": …} object, got ") +
                                 jsonTypeName(json));
    }
    const QJsonObject object = json.toObject();
    if (!checkKeys(object, pointer,
                   {QLatin1String("param"), QLatin1String("gain"), QLatin1String("offset"),
                    QLatin1String("curve")})) {
        return false;
    }
    return bound(object, pointer, QLatin1String("param"), out);
}

bool WaveformParser::checkRange(const Number &number, const QString &pointer, Range range)
{
    if (!number.isConstant())
        return true;
    const double value = number.value(nullptr);
    switch (range) {
    case Range::Any:
        return true;
    case Range::NonNegative:
        if (value < 0.0)
            return fail(pointer,
                        QStringLiteral("must not be negative, got ") + QString::number(value));
        return true;
    case Range::Unit:
        if (value < 0.0 || value > 1.0) {
            return fail(pointer,
                        QStringLiteral("must be between 0 and 1, got ") + QString::number(value));
        }
        return true;
    }
    return true;
}

bool WaveformParser::number(const QJsonObject &object, const QString &pointer, QLatin1String key,
                            Range range, Number *out)
{
    const QString at = jsonPointerChild(pointer, key);
    return require(object, pointer, key) && parseNumber(object.value(key), at, out) &&
           checkRange(*out, at, range);
}

bool WaveformParser::optionalNumber(const QJsonObject &object, const QString &pointer,
                                    QLatin1String key, Range range, double defaultValue,
                                    Number *out)
{
    if (!object.contains(key)) {
        *out = Number(defaultValue);
        return true;
    }
    return number(object, pointer, key, range, out);
}

bool WaveformParser::startValue(const QJsonObject &object, const QString &pointer, StartValue *out)
{
    const QLatin1String key("from");
    const QJsonValue from = object.value(key);
    if (from.isUndefined() || from.toString() == QLatin1String("current")) {
        *out = StartValue();
        return true;
    }
    if (from.toString() == QLatin1String("peak")) {
        *out = StartValue::peak();
        return true;
    }
    const QString at = jsonPointerChild(pointer, key);
    if (from.isString()) {
        return fail(at, QStringLiteral("expected \"current\", \"peak\" or a number, got ") +
                            quoted(from.toString()));
    }
    Number value;
    if (!parseNumber(from, at, &value))
        return false;
    *out = StartValue::value(value);
    return true;
}

bool WaveformParser::children(const QJsonObject &object, const QString &pointer,
                              std::vector<WaveformPtr> *out)
{
    const QLatin1String key("of");
    if (!checkKeys(object, pointer, {QLatin1String("type"), key}) ||
        !require(object, pointer, key))
        return false;
    const QString at = jsonPointerChild(pointer, key);
    const QJsonValue of = object.value(key);
    if (!of.isArray())
        return fail(at, QStringLiteral("expected an array, got ") + jsonTypeName(of));
    const QJsonArray array = of.toArray();
    if (array.isEmpty())
        return fail(at, QStringLiteral("expected at least one waveform"));
    for (int i = 0; i < array.size(); ++i) {
        WaveformPtr child = parse(array.at(i), jsonPointerChild(at, i));
        if (!child)
            return false;
        out->push_back(std::move(child));
    }
    return true;
}

WaveformPtr WaveformParser::parse(const QJsonValue &json, const QString &pointer)
{
    using Parse = WaveformPtr (WaveformParser::*)(const QJsonObject &, const QString &);
    static const std::pair<QLatin1String, Parse> parsers[] = {
        {QLatin1String("const"), &WaveformParser::parseConst},
        {QLatin1String("param"), &WaveformParser::parseParam},
        {QLatin1String("ramp"), &WaveformParser::parseRamp},
        {QLatin1String("keyframes"), &WaveformParser::parseKeyframes},
        {QLatin1String("sine"), &WaveformParser::parseSine},
        {QLatin1String("square"), &WaveformParser::parseSquare},
        {QLatin1String("pulses"), &WaveformParser::parsePulses},
        {QLatin1String("sum"), &WaveformParser::parseSum},
        {QLatin1String("product"), &WaveformParser::parseProduct},
        {QLatin1String("sequence"), &WaveformParser::parseSequence},
        {QLatin1String("scale"), &WaveformParser::parseScale},
        {QLatin1String("clip"), &WaveformParser::parseClip},
    };

    if (!json.isObject()) {
        fail(pointer, QStringLiteral("expected a waveform object, got ") + jsonTypeName(json));
        return nullptr;
    }
    const QJsonObject object = json.toObject();
    const QLatin1String typeKey("type");
    if (!require(object, pointer, typeKey))
        return nullptr;
    const QJsonValue type = object.value(typeKey);
    const QString typePointer = jsonPointerChild(pointer, typeKey);
    if (!type.isString()) {
        fail(typePointer, QStringLiteral("expected a string, got ") + jsonTypeName(type));
        return nullptr;
    }
    for (const auto &[name, parser] : parsers) {
        if (type.toString() == name)
            return (this->*parser)(object, pointer);
    }
    fail(typePointer, QStringLiteral("unknown waveform type ") + quoted(type.toString()));
    return nullptr;
}

WaveformPtr WaveformParser::parseConst(const QJsonObject &object, const QString &pointer)
{
    Number value;
    if (!checkKeys(object, pointer, {QLatin1String("type"), QLatin1String("value")}) ||
        !number(object, pointer, QLatin1String("value"), Range::Any, &value)) {
        return nullptr;
    }
    return std::make_unique<ConstWaveform>(value);
}

WaveformPtr WaveformParser::parseParam(const QJsonObject &object, const QString &pointer)
{
    Number value;
    if (!checkKeys(object, pointer,
                   {QLatin1String("type"), QLatin1String("name"), QLatin1String("gain"),
                    QLatin1String("offset"), QLatin1String("curve")}) ||
        !require(object, pointer, QLatin1String("name")) ||
        !bound(object, pointer, QLatin1String("name"), &value)) {
        return nullptr;
    }
    return std::make_unique<ParamWaveform>(value);
}

WaveformPtr WaveformParser::parseRamp(const QJsonObject &object, const QString &pointer)
{
    Number to;
    Number time;
    StartValue from;
    if (!checkKeys(object, pointer,
                   {QLatin1String("type"), QLatin1String("to"), QLatin1String("time"),
                    QLatin1String("from")}) ||
        !number(object, pointer, QLatin1String("to"), Range::Any, &to) ||
        !number(object, pointer, QLatin1String("time"), Range::NonNegative, &time) ||
        !startValue(object, pointer, &from)) {
        return nullptr;
    }
    return std::make_unique<RampWaveform>(to, time, from);
}

WaveformPtr WaveformParser::parseKeyframes(const QJsonObject &object, const QString &pointer)
{
    const QLatin1String key("points");
    std::vector<std::pair<double, double>> points;
    StartValue from;
    if (!checkKeys(object, pointer,
                   {QLatin1String("type"), QLatin1String("points"), QLatin1String("from")}) ||
        !require(object, pointer, key) ||
        !pairs(object.value(key), jsonPointerChild(pointer, key), &points) ||
        !startValue(object, pointer, &from)) {
        return nullptr;
    }
    for (size_t i = 0; i < points.size(); ++i) {
        const QString at = jsonPointerChild(jsonPointerChild(pointer, key), int(i));
        if (points[i].first < 0.0) {
            fail(at, QStringLiteral("time must not be negative, got ") +
                         QString::number(points[i].first));
            return nullptr;
        }
        if (i > 0 && points[i].first < points[i - 1].first) {
            fail(at, QStringLiteral("times must not decrease"));
            return nullptr;
        }
    }
    return std::make_unique<KeyframesWaveform>(std::move(points), from);
}

WaveformPtr WaveformParser::parseSine(const QJsonObject &object, const QString &pointer)
{
    Number freq;
    Number amp;
    Number offset;
    Number phase;
    if (!checkKeys(object, pointer,
                   {QLatin1String("type"), QLatin1String("freq"), QLatin1String("amp"),
                    QLatin1String("offset"), QLatin1String("phase")}) ||
        !number(object, pointer, QLatin1String("freq"), Range::NonNegative, &freq) ||
        !optionalNumber(object, pointer, QLatin1String("amp"), Range::Any, 1.0, &amp) ||
        !optionalNumber(object, pointer, QLatin1String("offset"), Range::Any, 0.0, &offset) ||
        !optionalNumber(object, pointer, QLatin1String("phase"), Range::Any, 0.0, &phase)) {
        return nullptr;
    }
    return std::make_unique<SineWaveform>(freq, amp, offset, phase);
}

WaveformPtr WaveformParser::parseSquare(const QJsonObject &object, const QString &pointer)
{
    Number freq;
    Number duty;
    Number high;
    Number low;
    if (!checkKeys(object, pointer,
                   {QLatin1String("type"), QLatin1String("freq"), QLatin1String("duty"),
                    QLatin1String("high"), QLatin1String("low")}) ||
        !number(object, pointer, QLatin1String("freq"), Range::NonNegative, &freq) ||
        !optionalNumber(object, pointer, QLatin1String("duty"), Range::Unit, 0.5, &duty) ||
        !optionalNumber(object, pointer, QLatin1String("high"), Range::Any, 1.0, &high) ||
        !optionalNumber(object, pointer, QLatin1String("low"), Range::Any, 0.0, &low)) {
        return nullptr;
    }
    return std::make_unique<SquareWaveform>(freq, duty, high, low);
}

WaveformPtr WaveformParser::parsePulses(const QJsonObject &object, const QString &pointer)
{
    Number rate;
    Number width;
    Number amp;
    if (!checkKeys(object, pointer,
                   {QLatin1String("type"), QLatin1String("rate"), QLatin1String("width"),
                    QLatin1String("amp")}) ||
        !number(object, pointer, QLatin1String("rate"), Range::NonNegative, &rate) ||
        !number(object, pointer, QLatin1String("width"), Range::NonNegative, &width) ||
        !optionalNumber(object, pointer, QLatin1String("amp"), Range::Any, 1.0, &amp)) {
        return nullptr;
    }
    return std::make_unique<PulsesWaveform>(rate, width, amp);
}

WaveformPtr WaveformParser::parseSum(const QJsonObject &object, const QString &pointer)
{
    std::vector<WaveformPtr> of;
    if (!children(object, pointer, &of))
        return nullptr;
    return std::make_unique<SumWaveform>(std::move(of));
}

WaveformPtr WaveformParser::parseProduct(const QJsonObject &object, const QString &pointer)
{
    std::vector<WaveformPtr> of;
    if (!children(object, pointer, &of))
        return nullptr;
    return std::make_unique<ProductWaveform>(std::move(of));
}

WaveformPtr WaveformParser::parseSequence(const QJsonObject &object, const QString &pointer)
{
    std::vector<WaveformPtr> of;
    if (!children(object, pointer, &of))
        return nullptr;
    for (size_t i = 0; i + 1 < of.size(); ++i) {
        if (std::isinf(of[i]->duration(m_params.defaults().data()))) {
            fail(jsonPointerChild(jsonPointerChild(pointer, QStringLiteral("of")), int(i)),
                 QStringLiteral("only the last waveform of a sequence may last forever"));
            return nullptr;
        }
    }
    return std::make_unique<SequenceWaveform>(std::move(of));
}

WaveformPtr WaveformParser::parseScale(const QJsonObject &object, const QString &pointer)
{
    const QLatin1String inKey("in");
    Number gain;
    Number div;
    Number offset;
    if (!checkKeys(object, pointer,
                   {QLatin1String("type"), inKey, QLatin1String("gain"), QLatin1String("div"),
                    QLatin1String("offset")}) ||
        !require(object, pointer, inKey) ||
        !optionalNumber(object, pointer, QLatin1String("gain"), Range::Any, 1.0, &gain) ||
        !optionalNumber(object, pointer, QLatin1String("div"), Range::Any, 1.0, &div) ||
        !optionalNumber(object, pointer, QLatin1String("offset"), Range::Any, 0.0, &offset)) {
        return nullptr;
    }
    WaveformPtr in = parse(object.value(inKey), jsonPointerChild(pointer, inKey));
    if (!in)
        return nullptr;
    return std::make_unique<ScaleWaveform>(std::move(in), gain, div, offset);
}

WaveformPtr WaveformParser::parseClip(const QJsonObject &object, const QString &pointer)
{
    const QLatin1String inKey("in");
    Number min;
    Number max;
    if (!checkKeys(object, pointer,
                   {QLatin1String("type"), inKey, QLatin1String("min"), QLatin1String("max")}) ||
        !require(object, pointer, inKey) ||
        !optionalNumber(object, pointer, QLatin1String("min"), Range::Any, 0.0, &min) ||
        !optionalNumber(object, pointer, QLatin1String("max"), Range::Any, 1.0, &max)) {
        return nullptr;
    }
    if (min.isConstant() && max.isConstant() && min.value(nullptr) > max.value(nullptr)) {
        fail(jsonPointerChild(pointer, QStringLiteral("max")),
             QStringLiteral("must not be below min"));
        return nullptr;
    }
    WaveformPtr in = parse(object.value(inKey), jsonPointerChild(pointer, inKey));
    if (!in)
        return nullptr;
    return std::make_unique<ClipWaveform>(std::move(in), min, max);
}

} // namespace semhap
