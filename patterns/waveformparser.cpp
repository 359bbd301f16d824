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
    const WaveformType &param = *waveformType(QStringLiteral("param"));
    double gain = param.field(gainKey)->defaultNumber;
    double offset = param.field(offsetKey)->defaultNumber;
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

bool WaveformParser::fields(const QJsonObject &object, const QString &pointer,
                            const WaveformType &type, std::vector<Number> *numbers)
{
    for (auto it = object.begin(); it != object.end(); ++it) {
        if (it.key() != QLatin1String("type") && !type.field(it.key()))
            return fail(pointer, QStringLiteral("unknown key ") + quoted(it.key()));
    }
    for (const ParamSpec &spec : type.fields) {
        if (spec.absent == ParamAbsent::Required && !object.contains(spec.name))
            return fail(pointer, QStringLiteral("missing key ") + quoted(spec.name));
        if (spec.kind != ParamKind::Number)
            continue;
        Number number(spec.defaultNumber);
        const QString at = jsonPointerChild(pointer, spec.name);
        QString reason;
        if (object.contains(spec.name) && !parseNumber(object.value(spec.name), at, &number))
            return false;
        // Constants are checked here; parameter-bound values are clamped when sampled.
        if (number.isConstant() && !spec.checkNumber(number.value(nullptr), &reason))
            return fail(at, reason);
        numbers->push_back(number);
    }
    return true;
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
    std::vector<Number> none;
    if (!fields(object, pointer, *waveformType(object.value(QLatin1String("type")).toString()),
                &none))
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
    std::vector<Number> n;
    if (!fields(object, pointer, *waveformType(QStringLiteral("const")), &n))
        return nullptr;
    return std::make_unique<ConstWaveform>(n[0]);
}

WaveformPtr WaveformParser::parseParam(const QJsonObject &object, const QString &pointer)
{
    // Gain and offset are plain numbers here: bound() reads them with the name.
    std::vector<Number> ignored;
    Number value;
    if (!fields(object, pointer, *waveformType(QStringLiteral("param")), &ignored) ||
        !bound(object, pointer, QLatin1String("name"), &value)) {
        return nullptr;
    }
    return std::make_unique<ParamWaveform>(value);
}

WaveformPtr WaveformParser::parseRamp(const QJsonObject &object, const QString &pointer)
{
    std::vector<Number> n;
    StartValue from;
    if (!fields(object, pointer, *waveformType(QStringLiteral("ramp")), &n) ||
        !startValue(object, pointer, &from)) {
        return nullptr;
    }
    return std::make_unique<RampWaveform>(n[0], n[1], from);
}

WaveformPtr WaveformParser::parseKeyframes(const QJsonObject &object, const QString &pointer)
{
    const QLatin1String key("points");
    std::vector<Number> none;
    std::vector<std::pair<double, double>> points;
    StartValue from;
    if (!fields(object, pointer, *waveformType(QStringLiteral("keyframes")), &none) ||
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
    std::vector<Number> n;
    if (!fields(object, pointer, *waveformType(QStringLiteral("sine")), &n))
        return nullptr;
    return std::make_unique<SineWaveform>(n[0], n[1], n[2], n[3]);
}

WaveformPtr WaveformParser::parseSquare(const QJsonObject &object, const QString &pointer)
{
    std::vector<Number> n;
    if (!fields(object, pointer, *waveformType(QStringLiteral("square")), &n))
        return nullptr;
    return std::make_unique<SquareWaveform>(n[0], n[1], n[2], n[3]);
}

WaveformPtr WaveformParser::parsePulses(const QJsonObject &object, const QString &pointer)
{
    std::vector<Number> n;
    if (!fields(object, pointer, *waveformType(QStringLiteral("pulses")), &n))
        return nullptr;
    return std::make_unique<PulsesWaveform>(n[0], n[1], n[2]);
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
    std::vector<Number> n;
    if (!fields(object, pointer, *waveformType(QStringLiteral("scale")), &n))
        return nullptr;
    WaveformPtr in = parse(object.value(inKey), jsonPointerChild(pointer, inKey));
    if (!in)
        return nullptr;
    return std::make_unique<ScaleWaveform>(std::move(in), n[0], n[1], n[2]);
}

WaveformPtr WaveformParser::parseClip(const QJsonObject &object, const QString &pointer)
{
    const QLatin1String inKey("in");
    std::vector<Number> n;
    if (!fields(object, pointer, *waveformType(QStringLiteral("clip")), &n))
        return nullptr;
    const Number &min = n[0];
    const Number &max = n[1];
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
