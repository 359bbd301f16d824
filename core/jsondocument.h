// SPDX-License-Identifier: MIT
#pragma once

#include "loaderror.h"

#include <QJsonArray>
#include <QJsonObject>
#include <QJsonValue>
#include <QString>

namespace semhap {

/**
 * Reads a JSON document whose root must be an object. Unreadable files and syntax errors
 * come back as `FILE:LINE:COL: reason`, so users can jump to the spot in an editor.
 */
bool readJsonObjectFile(const QString &path, QJsonObject *object, LoadError *error);
/** The same for bytes already in memory; `file` only names them in errors. */
bool parseJsonObject(const QByteArray &bytes, const QString &file, QJsonObject *object,
                     LoadError *error);

/** Reads the `"format"` key and checks it is `expected` (e.g. "semhap.router/1"). */
bool checkFormat(const QJsonObject &object, const QString &file, const QString &expected,
                 LoadError *error);

/**
 * Small checked accessors for loaders: each returns false and fills `error` with the file,
 * the JSON pointer of the value and what was wrong with it.
 */
class JsonReader
{
public:
    JsonReader(QString file, LoadError *error) : m_file(std::move(file)), m_error(error) {}

    bool fail(const QString &pointer, const QString &reason);
    bool string(const QJsonObject &o, const QString &key, const QString &pointer, QString *out,
                bool required = true);
    bool number(const QJsonObject &o, const QString &key, const QString &pointer, double *out,
                bool required = true);
    bool object(const QJsonObject &o, const QString &key, const QString &pointer,
                QJsonObject *out, bool required = true);
    bool array(const QJsonObject &o, const QString &key, const QString &pointer, QJsonArray *out,
               bool required = true);

    const QString &file() const { return m_file; }

private:
    QString m_file;
    LoadError *m_error;
};

/** A short human description of a JSON value's type, for error messages. */
QString jsonTypeName(const QJsonValue &value);

} // namespace semhap
