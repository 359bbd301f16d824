// SPDX-License-Identifier: MIT
#pragma once

#include <QJsonObject>
#include <QString>

#include <vector>

namespace semhap {

/** One numeric detector parameter: its JSON key and where its value lives. */
struct DetectorParam
{
    QLatin1String key;
    double *value;
};

/** A detector's parameters, listed once for reading, writing and checking. */
using DetectorParams = std::vector<DetectorParam>;

/**
 * Reads the keys present in `json` into `params`, so every detector's Params::read
 * rejects unknown keys and non-numbers with the same wording. False with key and reason.
 */
bool readDetectorParams(const QJsonObject &json, const DetectorParams &params, QString *key,
                        QString *reason);

/** Every parameter as a JSON object. */
QJsonObject detectorParamsToJson(const DetectorParams &params);

/** Checks each value is finite, so validators need not repeat it. False with key and reason. */
bool checkFiniteParams(const DetectorParams &params, QString *key, QString *reason);

/** Fills `key` and `reason` (either may be null) and returns false, for one-line rejects. */
bool paramError(QString *key, QString *reason, const QString &badKey, const QString &why);

/** `value` in its shortest round-trip form, for messages that quote a number. */
QString formatNumber(double value);

} // namespace semhap
