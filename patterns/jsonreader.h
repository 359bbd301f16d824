// SPDX-License-Identifier: MIT
#pragma once

#include "loaderror.h"

#include <QJsonObject>
#include <QJsonValue>
#include <QLatin1String>
#include <QString>

#include <initializer_list>

namespace semhap {

/**
 * The checks every semhap JSON loader makes (keys, types, finite numbers), keeping the
 * first mistake as `FILE: /json/pointer: reason` so all loaders word errors alike.
 */
class JsonReader
{
public:
    explicit JsonReader(const QString &file) : m_file(file) {}

    /** The first error met, empty while all went well. */
    const LoadError &error() const { return m_error; }
    /** Records `reason` at `pointer` unless an error is already recorded; returns false. */
    bool fail(const QString &pointer, const QString &reason);

    /** Fails on the first key of `object` that is not in `allowed`, catching typos. */
    bool checkKeys(const QJsonObject &object, const QString &pointer,
                   std::initializer_list<QLatin1String> allowed);
    /** Fails unless `object` has `key`. */
    bool require(const QJsonObject &object, const QString &pointer, QLatin1String key);
    /** Reads a finite JSON number. */
    bool finiteNumber(const QJsonValue &json, const QString &pointer, double *out);
    /** Reads the required non-empty string `key` of `object`. */
    bool nonEmptyString(const QJsonObject &object, const QString &pointer, QLatin1String key,
                        QString *out);

private:
    QString m_file;
    LoadError m_error;
};

/** "a number", "an object", …: how error messages name what they found instead. */
QString jsonTypeName(const QJsonValue &value);
/** `text` in single quotes, the way error messages cite names and values. */
QString quoted(const QString &text);

} // namespace semhap
