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

bool readDetectorParams(const QJsonObject &json, std::initializer_list<DetectorParam> params,
                        QString *key, QString *reason)
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

bool checkFiniteParams(std::initializer_list<std::pair<QLatin1String, double>> values,
                       QString *key, QString *reason)
{
    for (const auto &[name, value] : values) {
        if (!std::isfinite(value))
            return paramError(key, reason, name, QStringLiteral("must be a finite number"));
    }
    return true;
}

QString formatNumber(double value)
{
    return QString::number(value, 'g', QLocale::FloatingPointShortest);
}

} // namespace semhap
