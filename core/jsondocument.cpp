// SPDX-License-Identifier: MIT
#include "jsondocument.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonParseError>

#include <algorithm>
#include <cmath>

namespace semhap {

namespace {

// QJsonParseError gives a byte offset; users want the line and column of their editor.
void lineAndColumn(const QByteArray &bytes, int offset, int *line, int *column)
{
    *line = 1;
    int lineStart = 0;
    const int end = std::min(offset, int(bytes.size()));
    for (int i = 0; i < end; ++i) {
        if (bytes.at(i) == '\n') {
            ++*line;
            lineStart = i + 1;
        }
    }
    *column = int(QString::fromUtf8(bytes.mid(lineStart, end - lineStart)).size()) + 1;
}

} // namespace

bool parseJsonObject(const QByteArray &bytes, const QString &file, QJsonObject *object,
                     LoadError *error)
{
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(bytes, &parseError);
    if (parseError.error != QJsonParseError::NoError) {
        int line = 0;
        int column = 0;
        lineAndColumn(bytes, parseError.offset, &line, &column);
        *error = LoadError::atLine(file, line, column,
                                   QStringLiteral("invalid JSON: ") + parseError.errorString());
        return false;
    }
    if (!doc.isObject()) {
        *error = LoadError::at(file, QString(), QStringLiteral("the document must be a JSON object"));
        return false;
    }
    *object = doc.object();
    return true;
}

bool readJsonObjectFile(const QString &path, QJsonObject *object, LoadError *error)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        *error = LoadError::atLine(path, 0, 0, QStringLiteral("cannot read: ") + file.errorString());
        return false;
    }
    return parseJsonObject(file.readAll(), path, object, error);
}

bool checkFormat(const QJsonObject &object, const QString &file, const QString &expected,
                 LoadError *error)
{
    const QJsonValue format = object.value(QStringLiteral("format"));
    if (format.isUndefined()) {
        *error = LoadError::at(file, QStringLiteral("/format"),
                               QStringLiteral("missing; expected \"%1\"").arg(expected));
        return false;
    }
    if (format.toString() != expected) {
        *error = LoadError::at(file, QStringLiteral("/format"),
                               QStringLiteral("expected \"%1\", found %2")
                                   .arg(expected,
                                        format.isString()
                                            ? QLatin1Char('"') + format.toString() + QLatin1Char('"')
                                            : jsonTypeName(format)));
        return false;
    }
    return true;
}

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

bool JsonReader::fail(const QString &pointer, const QString &reason)
{
    *m_error = LoadError::at(m_file, pointer, reason);
    return false;
}

bool JsonReader::string(const QJsonObject &o, const QString &key, const QString &pointer,
                        QString *out, bool required)
{
    const QJsonValue v = o.value(key);
    const QString where = jsonPointerChild(pointer, key);
    if (v.isUndefined())
        return required ? fail(where, QStringLiteral("missing (a string)")) : true;
    if (!v.isString())
        return fail(where, QStringLiteral("must be a string, found ") + jsonTypeName(v));
    *out = v.toString();
    return true;
}

bool JsonReader::number(const QJsonObject &o, const QString &key, const QString &pointer,
                        double *out, bool required)
{
    const QJsonValue v = o.value(key);
    const QString where = jsonPointerChild(pointer, key);
    if (v.isUndefined())
        return required ? fail(where, QStringLiteral("missing (a number)")) : true;
    if (!v.isDouble() || !std::isfinite(v.toDouble()))
        return fail(where, QStringLiteral("must be a finite number, found ") + jsonTypeName(v));
    *out = v.toDouble();
    return true;
}

bool JsonReader::object(const QJsonObject &o, const QString &key, const QString &pointer,
                        QJsonObject *out, bool required)
{
    const QJsonValue v = o.value(key);
    const QString where = jsonPointerChild(pointer, key);
    if (v.isUndefined())
        return required ? fail(where, QStringLiteral("missing (an object)")) : true;
    if (!v.isObject())
        return fail(where, QStringLiteral("must be an object, found ") + jsonTypeName(v));
    *out = v.toObject();
    return true;
}

bool JsonReader::array(const QJsonObject &o, const QString &key, const QString &pointer,
                       QJsonArray *out, bool required)
{
    const QJsonValue v = o.value(key);
    const QString where = jsonPointerChild(pointer, key);
    if (v.isUndefined())
        return required ? fail(where, QStringLiteral("missing (an array)")) : true;
    if (!v.isArray())
        return fail(where, QStringLiteral("must be an array, found ") + jsonTypeName(v));
    *out = v.toArray();
    return true;
}

} // namespace semhap
