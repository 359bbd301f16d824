// SPDX-License-Identifier: MIT
#include "actuator.h"

#include "jsonreader.h"

#include <QJsonArray>

#include <cmath>

namespace semhap {

namespace {

bool positive(JsonReader &reader, const QJsonObject &json, const QString &pointer,
              QLatin1String key, double *out)
{
    if (!reader.number(json, pointer, key, out, false))
        return false;
    if (json.contains(key) && !(*out > 0.0))
        return reader.fail(jsonPointerChild(pointer, key),
                           QStringLiteral("must be above 0, got %1").arg(*out));
    return true;
}

bool oneOf(JsonReader &reader, const QJsonObject &json, const QString &pointer, QLatin1String key,
           const QStringList &allowed, QString *out)
{
    if (!reader.string(json, pointer, key, out, false))
        return false;
    if (json.contains(key) && !allowed.contains(*out))
        return reader.fail(jsonPointerChild(pointer, key),
                           QStringLiteral("unknown %1 '%2' (one of %3)")
                               .arg(key, *out, allowed.join(QStringLiteral(", "))));
    return true;
}

void insertKnown(QJsonObject *json, const QString &key, double value)
{
    if (!std::isnan(value))
        json->insert(key, value);
}

} // namespace

bool Actuator::read(const QJsonObject &json, const QString &pointer, JsonReader &reader)
{
    if (!reader.checkKeys(json, pointer,
                          {QLatin1String("type"), QLatin1String("body"),
                           QLatin1String("resonance"), QLatin1String("frequencies"),
                           QLatin1String("max_amplitude"), QLatin1String("amplitude_unit"),
                           QLatin1String("max_displacement"), QLatin1String("weight"),
                           QLatin1String("size")}) ||
        !oneOf(reader, json, pointer, QLatin1String("type"), types(), &type) ||
        !oneOf(reader, json, pointer, QLatin1String("body"), bodies(), &body) ||
        !positive(reader, json, pointer, QLatin1String("resonance"), &resonance) ||
        !positive(reader, json, pointer, QLatin1String("max_amplitude"), &maxAmplitude) ||
        !reader.string(json, pointer, QLatin1String("amplitude_unit"), &amplitudeUnit, false) ||
        !positive(reader, json, pointer, QLatin1String("max_displacement"), &maxDisplacement) ||
        !positive(reader, json, pointer, QLatin1String("weight"), &weight) ||
        !positive(reader, json, pointer, QLatin1String("size"), &size))
        return false;
    QJsonArray frequencies;
    if (!reader.array(json, pointer, QLatin1String("frequencies"), &frequencies, false))
        return false;
    const QString range = jsonPointerChild(pointer, QLatin1String("frequencies"));
    if (json.contains(QLatin1String("frequencies"))) {
        if (frequencies.size() != 2)
            return reader.fail(range, QStringLiteral("expected [lowest, highest] in Hz"));
        if (!reader.finiteNumber(frequencies.at(0), range + QStringLiteral("/0"), &minFrequency) ||
            !reader.finiteNumber(frequencies.at(1), range + QStringLiteral("/1"), &maxFrequency))
            return false;
        if (!(minFrequency >= 0.0 && minFrequency <= maxFrequency))
            return reader.fail(range, QStringLiteral("must rise from 0 Hz or more, got [%1, %2]")
                                          .arg(minFrequency)
                                          .arg(maxFrequency));
        if (resonance > 0.0 && (resonance < minFrequency || resonance > maxFrequency))
            return reader.fail(jsonPointerChild(pointer, QLatin1String("resonance")),
                               QStringLiteral("%1 Hz lies outside the frequencies [%2, %3]")
                                   .arg(resonance)
                                   .arg(minFrequency)
                                   .arg(maxFrequency));
    }
    if (!amplitudeUnit.isEmpty() && std::isnan(maxAmplitude))
        return reader.fail(jsonPointerChild(pointer, QLatin1String("amplitude_unit")),
                           QStringLiteral("a unit without max_amplitude"));
    return true;
}

QJsonObject Actuator::toJson() const
{
    QJsonObject json;
    if (!type.isEmpty())
        json.insert(QStringLiteral("type"), type);
    if (!body.isEmpty())
        json.insert(QStringLiteral("body"), body);
    if (resonance > 0.0)
        json.insert(QStringLiteral("resonance"), resonance);
    if (!std::isnan(minFrequency))
        json.insert(QStringLiteral("frequencies"), QJsonArray{minFrequency, maxFrequency});
    insertKnown(&json, QStringLiteral("max_amplitude"), maxAmplitude);
    if (!amplitudeUnit.isEmpty())
        json.insert(QStringLiteral("amplitude_unit"), amplitudeUnit);
    insertKnown(&json, QStringLiteral("max_displacement"), maxDisplacement);
    insertKnown(&json, QStringLiteral("weight"), weight);
    insertKnown(&json, QStringLiteral("size"), size);
    return json;
}

const QStringList &Actuator::types()
{
    static const QStringList names{QStringLiteral("LRA"), QStringLiteral("VCA"),
                                   QStringLiteral("ERM"), QStringLiteral("piezo"),
                                   QStringLiteral("bellows")};
    return names;
}

const QStringList &Actuator::bodies()
{
    static const QStringList names{QStringLiteral("wrist"), QStringLiteral("fingers")};
    return names;
}

} // namespace semhap
