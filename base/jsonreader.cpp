// SPDX-License-Identifier: MIT
#include "jsonreader.h"

#include "inputfile.h"

#include <QJsonDocument>
#include <QJsonParseError>
#include <QSet>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

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

void JsonReader::ignoreUnknownKeys(const QJsonObject &object, const QString &pointer,
                                   std::initializer_list<QLatin1String> known,
                                   QStringList *warnings) const
{
    if (!warnings)
        return;
    for (auto it = object.begin(); it != object.end(); ++it) {
        if (std::find(known.begin(), known.end(), it.key()) == known.end())
            warnings->append(LoadError::at(m_file, jsonPointerChild(pointer, it.key()),
                                           QStringLiteral("ignored: unknown key"))
                                 .toString());
    }
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

namespace {

// Shared by the typed reads: a missing key is fine unless required; a wrong type never is.
template<typename Check>
bool readKey(JsonReader &reader, const QJsonObject &object, const QString &pointer,
             QLatin1String key, bool required, const QString &expected, Check isRightType)
{
    const QJsonValue value = object.value(key);
    if (value.isUndefined())
        return required ? reader.require(object, pointer, key) : true;
    if (!isRightType(value))
        return reader.fail(
            jsonPointerChild(pointer, key),
            QStringLiteral("expected %1, got %2").arg(expected, jsonTypeName(value)));
    return true;
}

} // namespace

bool JsonReader::string(const QJsonObject &object, const QString &pointer, QLatin1String key,
                        QString *out, bool required)
{
    if (!readKey(*this, object, pointer, key, required, QStringLiteral("a string"),
                 [](const QJsonValue &v) { return v.isString(); }))
        return false;
    if (object.contains(key))
        *out = object.value(key).toString();
    return true;
}

bool JsonReader::number(const QJsonObject &object, const QString &pointer, QLatin1String key,
                        double *out, bool required)
{
    if (!object.contains(key))
        return required ? require(object, pointer, key) : true;
    return finiteNumber(object.value(key), jsonPointerChild(pointer, key), out);
}

bool JsonReader::object(const QJsonObject &object, const QString &pointer, QLatin1String key,
                        QJsonObject *out, bool required)
{
    if (!readKey(*this, object, pointer, key, required, QStringLiteral("an object"),
                 [](const QJsonValue &v) { return v.isObject(); }))
        return false;
    if (object.contains(key))
        *out = object.value(key).toObject();
    return true;
}

bool JsonReader::array(const QJsonObject &object, const QString &pointer, QLatin1String key,
                       QJsonArray *out, bool required)
{
    if (!readKey(*this, object, pointer, key, required, QStringLiteral("an array"),
                 [](const QJsonValue &v) { return v.isArray(); }))
        return false;
    if (object.contains(key))
        *out = object.value(key).toArray();
    return true;
}

bool JsonReader::strings(const QJsonObject &object, const QString &pointer, QLatin1String key,
                         QStringList *out, bool required)
{
    QJsonArray items;
    if (!array(object, pointer, key, &items, required))
        return false;
    if (!object.contains(key))
        return true;
    QStringList values;
    for (int i = 0; i < items.size(); ++i) {
        if (!items[i].isString())
            return fail(jsonPointerChild(jsonPointerChild(pointer, key), i),
                        QStringLiteral("expected a string, found ") + jsonTypeName(items[i]));
        values.append(items[i].toString());
    }
    *out = values;
    return true;
}

namespace {

/**
 * Finds the first key an object of a valid JSON text repeats (QJsonDocument keeps the last
 * value without a word). One pass over the text; false when no key repeats, else the
 * repeated key's JSON pointer.
 */
bool findRepeatedKey(const QByteArray &text, QString *pointer)
{
    struct Level
    {
        bool isObject = false;
        bool expectKey = false;
        QString key;
        int index = 0;
        QSet<QString> keys;
    };
    std::vector<Level> levels;
    const char *p = text.constData();
    const char *end = p + text.size();
    const auto readString = [&]() -> QString {
        // p is just past the opening quote; the text is valid JSON.
        QString out;
        QByteArray run;
        while (p < end && *p != '"') {
            if (*p != '\\') {
                run.append(*p++);
                continue;
            }
            ++p;
            const char c = *p++;
            out += QString::fromUtf8(run);
            run.clear();
            if (c == 'u') {
                out += QChar(QByteArray(p, 4).toUShort(nullptr, 16));
                p += 4;
                continue;
            }
            // \b \f \n \r \t; the rest (\" \\ \/) stand for themselves.
            static const char named[] = "bfnrt";
            static const char meant[] = "\b\f\n\r\t";
            const char *at = std::strchr(named, c);
            out += QLatin1Char(at ? meant[at - named] : c);
        }
        ++p; // the closing quote
        return out + QString::fromUtf8(run);
    };
    while (p < end) {
        const char c = *p++;
        switch (c) {
        case '{':
        case '[': {
            Level level;
            level.isObject = c == '{';
            level.expectKey = level.isObject;
            levels.push_back(std::move(level));
            break;
        }
        case '}':
        case ']':
            levels.pop_back();
            break;
        case ',':
            if (levels.back().isObject)
                levels.back().expectKey = true;
            else
                ++levels.back().index;
            break;
        case '"': {
            const QString value = readString();
            if (levels.empty() || !levels.back().isObject || !levels.back().expectKey)
                break;
            Level &level = levels.back();
            level.expectKey = false;
            level.key = value;
            if (!level.keys.contains(value)) {
                level.keys.insert(value);
                break;
            }
            pointer->clear();
            for (const Level &outer : levels)
                *pointer = outer.isObject ? jsonPointerChild(*pointer, outer.key)
                                          : jsonPointerChild(*pointer, outer.index);
            return true;
        }
        default:
            break;
        }
    }
    return false;
}

} // namespace

bool parseJsonObject(const QByteArray &bytes, const QString &file, QJsonObject *object,
                     LoadError *error)
{
    QJsonParseError parseError;
    const QJsonDocument document = QJsonDocument::fromJson(bytes, &parseError);
    if (parseError.error != QJsonParseError::NoError) {
        // QJsonParseError gives a byte offset; editors want a line and a character column.
        const QByteArray before = bytes.left(parseError.offset);
        const qsizetype lineStart = before.lastIndexOf('\n') + 1;
        const int line = int(before.count('\n')) + 1;
        const int column = int(QString::fromUtf8(before.mid(lineStart)).size()) + 1;
        *error = LoadError::atLine(file, line, column,
                                   QStringLiteral("invalid JSON: ") + parseError.errorString());
        return false;
    }
    if (!document.isObject()) {
        // The root has no pointer of its own: say where it starts.
        qsizetype start = 0;
        while (start < bytes.size() && QChar::isSpace(uchar(bytes.at(start))))
            ++start;
        const QByteArray before = bytes.left(start);
        *error = LoadError::atLine(
            file, int(before.count('\n')) + 1, int(start - (before.lastIndexOf('\n') + 1)) + 1,
            QStringLiteral("expected a JSON object, got ") +
                (document.isArray() ? QStringLiteral("an array") : QStringLiteral("nothing")));
        return false;
    }
    QString repeated;
    if (findRepeatedKey(bytes, &repeated)) {
        *error = LoadError::at(file, repeated,
                               QStringLiteral("the key appears twice in its object; which value "
                                              "was meant is unknown"));
        return false;
    }
    *object = document.object();
    return true;
}

bool readJsonObjectFile(const QString &path, QJsonObject *object, LoadError *error)
{
    QByteArray bytes;
    QString reason;
    if (!InputFile::readDocument(path, &bytes, &reason)) {
        *error = LoadError::at(path, QString(), QStringLiteral("cannot read: ") + reason);
        return false;
    }
    return parseJsonObject(bytes, path, object, error);
}

bool checkFormat(const QJsonObject &object, const QString &file, QLatin1String expected,
                 LoadError *error)
{
    JsonReader reader(file);
    QString format;
    if (reader.string(object, QString(), QLatin1String("format"), &format) && format != expected)
        reader.fail(QStringLiteral("/format"), QStringLiteral("unsupported format %1, expected %2")
                                                   .arg(quoted(format), quoted(expected)));
    if (reader.error().isSet() && error)
        *error = reader.error();
    return !reader.error().isSet();
}

} // namespace semhap
