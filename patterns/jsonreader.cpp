// SPDX-License-Identifier: MIT
#include "jsonreader.h"

#include <algorithm>
#include <cmath>

namespace semhap {

QString jsonTypeName(const QJsonValue &value)
{
    switch (value.type()) {
    case QJsonValue::Null:
        return QStringLiteral("null");
    case QJsonValue::Bool:
        return QStringLiteral("a boolean");
    case QJsonValue::Double:
        return QStringLiteral("a number");
    case QJsonValue::String:
        return QStringLiteral("a string");
    case QJsonValue::Array:
        return QStringLiteral("an array");
    case QJsonValue::Object:
        return QStringLiteral("an object");
    case QJsonValue::Undefined:
        break;
    }
    return QStringLiteral("nothing");
}

QString quoted(const QString &text)
{
    return QLatin1Char('\'') + text + QLatin1Char('\'');
}

bool JsonReader::fail(const QString &pointer, const QString &reason)
{
    if (!m_error.isSet())
        m_error = LoadError::at(m_file, pointer, reason);
    return false;
}

bool JsonReader::checkKeys(const QJsonObject &object, const QString &pointer,
                           std::initializer_list<QLatin1String> allowed)
{
    for (auto it = object.begin(); it != object.end(); ++it) {
        if (std::find(allowed.begin(), allowed.end(), it.key()) == allowed.end())
            return fail(pointer, QStringLiteral("unknown key ") + quoted(it.key()));
    }
    return true;
}

bool JsonReader::require(const QJsonObject &object, const QString &pointer, QLatin1String key)
{
    if (object.contains(key))
        return true;
    return fail(pointer, QStringLiteral("missing key ") + quoted(key));
}

bool JsonReader::finiteNumber(const QJsonValue &json, const QString &pointer, double *out)
{
    if (!json.isDouble())
        return fail(pointer, QStringLiteral("expected a number, got ") + jsonTypeName(json));
    *out = json.toDouble();
    if (!std::isfinite(*out))
        return fail(pointer, QStringLiteral("must be a finite number"));
    return true;
}

bool JsonReader::nonEmptyString(const QJsonObject &object, const QString &pointer,
                                QLatin1String key, QString *out)
{
    if (!require(object, pointer, key))
        return false;
    const QJsonValue value = object.value(key);
    const QString at = jsonPointerChild(pointer, key);
    if (!value.isString())
        return fail(at, QStringLiteral("expected a string, got ") + jsonTypeName(value));
    *out = value.toString();
    if (out->isEmpty())
        return fail(at, QStringLiteral("must not be empty"));
    return true;
}

} // namespace semhap
