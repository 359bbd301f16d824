// SPDX-License-Identifier: MIT
#include "detectorparams.h"

#include <QLocale>

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
            known = known || it.key() == param.key;
        if (!known)
            return paramError(key, reason, it.key(), QStringLiteral("unknown parameter"));
        if (!it.value().isDouble())
            return paramError(key, reason, it.key(), QStringLiteral("must be a number"));
    }
    for (const DetectorParam &param : params) {
        const QJsonValue value = json.value(param.key);
        if (value.isDouble())
            *param.value = value.toDouble();
    }
    return true;
}

QJsonObject detectorParamsToJson(const DetectorParams &params)
{
    QJsonObject json;
    for (const DetectorParam &param : params)
        json.insert(param.key, *param.value);
    return json;
}

bool checkFiniteParams(const DetectorParams &params, QString *key, QString *reason)
{
    for (const DetectorParam &param : params) {
        if (!std::isfinite(*param.value))
            return paramError(key, reason, param.key, QStringLiteral("must be a finite number"));
    }
    return true;
}

QString formatNumber(double value)
{
    return QString::number(value, 'g', QLocale::FloatingPointShortest);
}

} // namespace semhap
