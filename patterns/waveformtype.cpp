// SPDX-License-Identifier: MIT
#include "waveformtype.h"

#include <QJsonArray>
#include <QJsonObject>

namespace semhap {

const ParamSpec *WaveformType::field(const QString &name) const
{
    return findParamSpec(fields, name);
}

bool WaveformType::bindsParams() const
{
    return type != QLatin1String("param");
}

bool WaveformType::isModifier() const
{
    for (const ParamSpec &spec : fields) {
        if (spec.kind == ParamKind::Waveform || spec.kind == ParamKind::Waveforms)
            return true;
    }
    return false;
}

namespace {

ParamSpec number(const char *name, double value, const char *unit, const char *help)
{
    return ParamSpec::number(QLatin1String(name), value, QLatin1String(unit), QLatin1String(help));
}

// A number that must be given; `start` is what a new one gets in an editor.
ParamSpec requiredNumber(const char *name, double start, const char *unit, const char *help)
{
    return number(name, 0, unit, help).required().startingWith(start);
}

ParamSpec startField()
{
    return ParamSpec::of(QStringLiteral("from"), ParamKind::Start, ParamAbsent::Default,
                         QStringLiteral("Where it starts: \"current\" (the track's value when "
                                        "the message began), \"peak\" (its highest since), or "
                                        "a number"));
}

ParamSpec inputs(const QJsonArray &start)
{
    return ParamSpec::of(QStringLiteral("of"), ParamKind::Waveforms, ParamAbsent::Required,
                         QStringLiteral("Its input waveforms"))
        .startingWith(start);
}

ParamSpec input()
{
    return ParamSpec::of(QStringLiteral("in"), ParamKind::Waveform, ParamAbsent::Required,
                         QStringLiteral("Its input waveform"));
}

QJsonObject waveform(const char *type, const char *key, double value)
{
    return {{QStringLiteral("type"), QLatin1String(type)}, {QLatin1String(key), value}};
}

QJsonObject ramp(double to, double time)
{
    return {{QStringLiteral("type"), QStringLiteral("ramp")},
            {QStringLiteral("to"), to},
            {QStringLiteral("time"), time}};
}

} // namespace

const std::vector<WaveformType> &waveformTypes()
{
    static const std::vector<WaveformType> types{
        {QStringLiteral("const"),
         QStringLiteral("A constant value"),
         {requiredNumber("value", 1, "", "The value")}},
        {QStringLiteral("ramp"),
         QStringLiteral("A straight line from where the track is to a value"),
         {requiredNumber("to", 1, "", "The value it ends at"),
          requiredNumber("time", 0.5, "s", "How long it takes").atLeast(0), startField()}},
        {QStringLiteral("keyframes"),
         QStringLiteral("Straight lines through [time, value] points"),
         {ParamSpec::of(QStringLiteral("points"), ParamKind::Points, ParamAbsent::Required,
                        QStringLiteral("[time, value] points, times from 0 and not "
                                       "decreasing"))
              .startingWith(
                  QJsonArray{QJsonArray{0, 0}, QJsonArray{0.2, 1}, QJsonArray{0.5, 0.5}}),
          startField()}},
        {QStringLiteral("sine"),
         QStringLiteral("offset + amp * sin(2 pi (freq t + phase))"),
         {requiredNumber("freq", 5, "Hz", "Its frequency").atLeast(0),
          number("amp", 1, "", "Its amplitude"), number("offset", 0, "", "Added to it"),
          number("phase", 0, "cycles", "Where in its cycle it starts")}},
        {QStringLiteral("square"),
         QStringLiteral("high for duty of each period, low for the rest"),
         {requiredNumber("freq", 5, "Hz", "Its frequency").atLeast(0),
          number("duty", 0.5, "", "The share of each period at high").atLeast(0).atMost(1),
          number("high", 1, "", "Its value in the first part of a period"),
          number("low", 0, "", "Its value in the rest")}},
        {QStringLiteral("pulses"),
         QStringLiteral("Pulses of amp, width seconds long, rate times a second"),
         {requiredNumber("rate", 5, "Hz", "Pulses per second").atLeast(0),
          requiredNumber("width", 0.025, "s", "How long each pulse lasts").atLeast(0),
          number("amp", 1, "", "Their height")}},
        {QStringLiteral("param"),
         QStringLiteral("A pattern parameter's live value, mapped linearly or through a curve"),
         {ParamSpec::of(QStringLiteral("name"), ParamKind::ParamName, ParamAbsent::Required,
                        QStringLiteral("The pattern parameter it follows"))
              .startingWith(QStringLiteral("intensity")),
          number("gain", 1, "", "Multiplies the value (not with curve)"),
          number("offset", 0, "", "Added after gain (not with curve)"),
          ParamSpec::of(QStringLiteral("curve"), ParamKind::Points, ParamAbsent::Default,
                        QStringLiteral("[x, y] points the value is mapped through, x "
                                       "increasing (instead of gain and offset)"))}},
        {QStringLiteral("sum"),
         QStringLiteral("The sum of its inputs"),
         {inputs({waveform("const", "value", 1), waveform("square", "freq", 5)})}},
        {QStringLiteral("product"),
         QStringLiteral("The product of its inputs"),
         {inputs({waveform("const", "value", 1), waveform("square", "freq", 5)})}},
        {QStringLiteral("sequence"),
         QStringLiteral("Its inputs one after the other; only the last may last forever"),
         {inputs({ramp(1, 0.2), ramp(0, 0.2)})}},
        {QStringLiteral("scale"),
         QStringLiteral("(in * gain) / div + offset"),
         {input(), number("gain", 1, "", "Multiplies the input"),
          number("div", 1, "", "Divides the input"), number("offset", 0, "", "Added last")}},
        {QStringLiteral("clip"),
         QStringLiteral("Its input held within [min, max]"),
         {input(), number("min", 0, "", "The lowest value it passes"),
          number("max", 1, "", "The highest value it passes")}},
    };
    return types;
}

const WaveformType *waveformType(const QString &type)
{
    for (const WaveformType &t : waveformTypes()) {
        if (t.type == type)
            return &t;
    }
    return nullptr;
}

QJsonObject newWaveform(const QString &type, const QJsonValue &previous)
{
    const WaveformType *spec = waveformType(type);
    if (!spec)
        spec = waveformType(QStringLiteral("const"));
    QJsonObject node{{QStringLiteral("type"), spec->type}};
    // Required fields get the table's starting values; a modifier keeps `previous` as its
    // (first) input, so changing a node's type to a combinator wraps it.
    for (const ParamSpec &field : spec->fields) {
        if (field.absent != ParamAbsent::Required)
            continue;
        if (field.kind == ParamKind::Waveform) {
            node.insert(field.name,
                        previous.isObject() ? previous : newWaveform(QStringLiteral("const")));
        } else if (field.kind == ParamKind::Waveforms) {
            QJsonArray inputs = field.example.toArray();
            if (previous.isObject() && !inputs.isEmpty())
                inputs.replace(0, previous);
            node.insert(field.name, inputs);
        } else {
            node.insert(field.name, field.example);
        }
    }
    return node;
}

} // namespace semhap
