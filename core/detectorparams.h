// SPDX-License-Identifier: MIT
#pragma once

#include "paramspec.h"

#include <QJsonObject>
#include <QString>

#include <vector>

namespace semhap {

/** One numeric detector parameter: its spec (key, unit, range, help) and where its value lives. */
struct DetectorParam
{
    ParamSpec spec; ///< spec.defaultNumber is not used: the value a Params starts with is
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

/** `minDuration` (s, >= 0): every detector's, and a threshold node's, delay before a begin. */
ParamSpec minDurationSpec();
/** `hysteresis` (>= 0, in `unit`): how far back past its threshold an active message holds. */
ParamSpec hysteresisSpec(const QString &unit, const QString &help);

/** Every parameter as a JSON object. */
QJsonObject detectorParamsToJson(const DetectorParams &params);

/**
 * Checks each value is finite and within its spec's range, so validators check only what
 * relates parameters to each other. False with key and reason.
 */
bool checkDetectorParams(const DetectorParams &params, QString *key, QString *reason);

/** The specs of `params`, each defaulting to its current value (pass a default Params). */
std::vector<ParamSpec> detectorParamSpecs(const DetectorParams &params);

/** Fills `key` and `reason` (either may be null) and returns false, for one-line rejects. */
bool paramError(QString *key, QString *reason, const QString &badKey, const QString &why);

} // namespace semhap
