// SPDX-License-Identifier: MIT
#include "detectorparams.h"

#include <cmath>

namespace semhap {

bool paramError(QString *key, QString *reason, const QString &badKey, const QString &why)
{
    if (key)
        *key = badKey;
    if (reason)
        *reason = why;
    return false;
}

bool readDetectorParams(const QJsonObject &json, const DetectorParams &params, QString *key,
                        QString *reason)
{
    // Check everything before assigning, so a rejected object leaves the values untouched.
    for (auto it = json.begin(); it != json.end(); ++it) {
        bool known = false;
        for (const DetectorParam &param : params)
            known = known || it.key() == param.spec.name;
        if (!known)
            return paramError(key, reason, it.key(), QStringLiteral("unknown parameter"));
        if (!it.value().isDouble())
            return paramError(key, reason, it.key(), QStringLiteral("must be a number"));
    }
    for (const DetectorParam &param : params) {
        const QJsonValue value = json.value(param.spec.name);
        if (value.isDouble())
            *param.value = value.toDouble();
    }
    return true;
}

ParamSpec minDurationSpec()
{
    return ParamSpec::number(QStringLiteral("minDuration"), 0, QStringLiteral("s"),
                             QStringLiteral("A message begins only after its condition has "
                                            "held this long"))
        .atLeast(0);
}

ParamSpec hysteresisSpec(const QString &unit, const QString &help)
{
    return ParamSpec::number(QStringLiteral("hysteresis"), 0, unit, help).atLeast(0);
}

QJsonObject detectorParamsToJson(const DetectorParams &params)
{
    QJsonObject json;
    for (const DetectorParam &param : params)
        json.insert(param.spec.name, *param.value);
    return json;
}

bool checkDetectorParams(const DetectorParams &params, QString *key, QString *reason)
{
    for (const DetectorParam &param : params) {
        if (!std::isfinite(*param.value))
            return paramError(key, reason, param.spec.name,
                              QStringLiteral("must be a finite number"));
        QString why;
        if (!param.spec.checkNumber(*param.value, &why))
            return paramError(key, reason, param.spec.name, why);
    }
    return true;
}

std::vector<ParamSpec> detectorParamSpecs(const DetectorParams &params)
{
    std::vector<ParamSpec> specs;
    for (const DetectorParam &param : params) {
        specs.push_back(param.spec);
        specs.back().defaultNumber = *param.value;
    }
    return specs;
}

} // namespace semhap
