// SPDX-License-Identifier: MIT
#pragma once

#include "loaderror.h"

#include <QJsonArray>
#include <QJsonObject>
#include <QJsonValue>
#include <QLatin1String>
#include <QString>
#include <QStringList>

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
    /**
     * For formats that grow (AHAP, `.haptic`): appends `FILE: /pointer/KEY: ignored: unknown
     * key` to `warnings` (when given) for each key of `object` not in `known`; never fails.
     */
    void ignoreUnknownKeys(const QJsonObject &object, const QString &pointer,
                           std::initializer_list<QLatin1String> known,
                           QStringList *warnings) const;
    /** Fails unless `object` has `key`. */
    bool require(const QJsonObject &object, const QString &pointer, QLatin1String key);
    /** Reads a finite JSON number. */
    bool finiteNumber(const QJsonValue &json, const QString &pointer, double *out);
    /** Reads the required non-empty string `key` of `object`. */
    bool nonEmptyString(const QJsonObject &object, const QString &pointer, QLatin1String key,
                        QString *out);

    /**
     * Typed reads of `key` in `object` (at `pointer`): a missing key leaves `out` alone
     * unless `required`; a value of the wrong type always fails.
     */
    bool string(const QJsonObject &object, const QString &pointer, QLatin1String key, QString *out,
                bool required = true);
    bool number(const QJsonObject &object, const QString &pointer, QLatin1String key, double *out,
                bool required = true);
    bool object(const QJsonObject &object, const QString &pointer, QLatin1String key,
                QJsonObject *out, bool required = true);
    bool array(const QJsonObject &object, const QString &pointer, QLatin1String key,
               QJsonArray *out, bool required = true);
    /** An array of strings, each checked. */
    bool strings(const QJsonObject &object, const QString &pointer, QLatin1String key,
                 QStringList *out, bool required = true);

private:
    QString m_file;
    LoadError m_error;
};

/**
 * Parses a JSON document whose root must be an object. Syntax errors come back as
 * `FILE:LINE:COL: invalid JSON: reason`, so users can jump to the spot in an editor.
 */
bool parseJsonObject(const QByteArray &bytes, const QString &file, QJsonObject *object,
                     LoadError *error);
/** Reads and parses a file the same way; an unreadable file is `FILE: cannot read: why`. */
bool readJsonObjectFile(const QString &path, QJsonObject *object, LoadError *error);
/** Checks the document's `"format"` is `expected` (e.g. "semhap.router/1"). */
bool checkFormat(const QJsonObject &object, const QString &file, QLatin1String expected,
                 LoadError *error);

/** "a number", "an object", …: how error messages name what they found instead. */
QString jsonTypeName(const QJsonValue &value);
/** `text` in single quotes, the way error messages cite names and values. */
QString quoted(const QString &text);

} // namespace semhap
