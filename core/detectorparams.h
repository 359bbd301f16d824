// SPDX-License-Identifier: MIT
#pragma once

#include <QJsonObject>
#include <QString>

#include <initializer_list>
#include <utility>

namespace semhap {

/** One numeric detector parameter: its JSON key and where its value lives. */
struct DetectorParam
{
    QLatin1String key;
    double *value;
};

/**
 * Reads the keys present in `json` into `params`, so every detector's Params::read
 * rejects unknown keys and non-numbers with the same wording. False with key and reason.
 */
bool readDetectorParams(const QJsonObject &json, std::initializer_list<DetectorParam> params,
                        QString *key, QString *reason);

/** Checks each value is finite, so validators need not repeat it. False with key and reason. */
bool checkFiniteParams(std::initializer_list<std::pair<QLatin1String, double>> values,
                       QString *key, QString *reason);

/** Fills `key` and `reason` (either may be null) and returns false, for one-line rejects. */
bool paramError(QString *key, QString *reason, const QString &badKey, const QString &why);

/** `value` in its shortest round-trip form, for messages that quote a number. */
QString formatNumber(double value);

} // namespace semhap
