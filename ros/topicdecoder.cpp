// SPDX-License-Identifier: MIT
#include "topicdecoder.h"

#include "jsonreader.h"
#include "msgschema.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <cmath>
#include <limits>

namespace semhap {

namespace {

constexpr double NaN = std::numeric_limits<double>::quiet_NaN();

/** The value at `path` in a JSON message: fields by name, elements by [INDEX]. */
QJsonValue at(const QJsonValue &root, const QString &path)
{
    QJsonValue v = root;
    for (const QString &part : path.split(QLatin1Char('.'))) {
        const qsizetype bracket = part.indexOf(QLatin1Char('['));
        v = v.toObject().value(bracket < 0 ? part : part.left(bracket));
        if (bracket >= 0) {
            const QJsonArray array = v.toArray();
            const int index = part.mid(bracket + 1).chopped(1).toInt();
            v = index >= 0 && index < array.size() ? array[index] : QJsonValue();
        }
    }
    return v;
}

} // namespace

bool TopicDecoder::compile(const Description &d, const std::vector<Want> &wants, QString *error)
{
    m_wants = wants;
    m_offsets.clear();
    m_valueCount = 0;
    for (const Want &w : wants) {
        m_offsets.push_back(m_valueCount);
        m_valueCount += w.width;
    }
    const QString what = QStringLiteral("%1 (%2)").arg(quoted(d.topic), d.schemaName);
    if (d.messageEncoding == QLatin1String("json")) {
        m_json = true;
        return true;
    }
    if (d.messageEncoding != QLatin1String("cdr") ||
        d.schemaEncoding != QLatin1String("ros2msg")) {
        *error = QStringLiteral("%1: messages in %2 with a %3 schema are not read (cdr with "
                                "ros2msg, or json)")
                     .arg(what, quoted(d.messageEncoding), quoted(d.schemaEncoding));
        return false;
    }
    m_json = false;
    MsgSchema schema;
    QString why;
    if (!MsgSchema::parse(d.schemaName, d.schema, &schema, &why)) {
        *error = QStringLiteral("%1: its schema, line %2").arg(what, why);
        return false;
    }
    // An optional path the type lacks is left out; the rest must all be there.
    QStringList paths;
    std::vector<int> compiled; // want i's index among the paths compiled, or -1
    for (const Want &w : wants) {
        CdrDecoder probe;
        const bool absent = w.optional && !CdrDecoder::compile(schema, {w.path}, &probe, &why);
        compiled.push_back(absent ? -1 : int(paths.size()));
        if (!absent)
            paths << w.path;
    }
    if (!CdrDecoder::compile(schema, paths, &m_cdr, &why)) {
        *error = QStringLiteral("%1: %2").arg(what, why);
        return false;
    }
    m_cdrOffsets.clear();
    for (size_t i = 0; i < wants.size(); ++i) {
        const int c = compiled[i];
        if (c >= 0 && m_cdr.width(c) != wants[i].width) {
            *error = QStringLiteral("%1: '%2' gives %3 number(s), not the %4 wanted")
                         .arg(what, wants[i].path)
                         .arg(m_cdr.width(c))
                         .arg(wants[i].width);
            return false;
        }
        m_cdrOffsets.push_back(c >= 0 ? m_cdr.offset(c) : -1);
    }
    m_scratch.assign(size_t(m_cdr.valueCount()), 0.0);
    m_cdr.setEpoch(m_epoch);
    return true;
}

void TopicDecoder::setEpoch(std::int64_t seconds)
{
    m_epoch = seconds;
    m_cdr.setEpoch(seconds);
}

bool TopicDecoder::decode(const char *data, std::size_t size, double *values, QString *error)
{
    if (m_json)
        return decodeJson(data, size, values, error);
    if (!m_cdr.decode(data, size, m_scratch.data(), error))
        return false;
    for (size_t i = 0; i < m_wants.size(); ++i) {
        for (int k = 0; k < m_wants[i].width; ++k)
            values[m_offsets[i] + k] =
                m_cdrOffsets[i] < 0 ? NaN : m_scratch[size_t(m_cdrOffsets[i] + k)];
    }
    return true;
}

bool TopicDecoder::decodeJson(const char *data, std::size_t size, double *values,
                              QString *error) const
{
    QJsonParseError parseError;
    const QJsonDocument document =
        QJsonDocument::fromJson(QByteArray::fromRawData(data, qsizetype(size)), &parseError);
    if (parseError.error != QJsonParseError::NoError) {
        *error = QStringLiteral("byte %1: invalid JSON: %2")
                     .arg(parseError.offset)
                     .arg(parseError.errorString());
        return false;
    }
    const QJsonValue root = document.isObject() ? QJsonValue(document.object()) : QJsonValue();
    for (size_t i = 0; i < m_wants.size(); ++i) {
        const Want &w = m_wants[i];
        double *out = values + m_offsets[i];
        std::fill(out, out + w.width, NaN);
        const QJsonValue v = at(root, w.path);
        if (w.width == 1 && v.isDouble()) {
            out[0] = v.toDouble();
        } else if (w.width == 1 && v.isObject() && v.toObject().contains(QLatin1String("sec"))) {
            const QJsonObject time = v.toObject();
            out[0] = (time.value(QLatin1String("sec")).toDouble() - double(m_epoch)) +
                     time.value(QLatin1String("nanosec")).toDouble() * 1e-9;
        } else if (v.isArray() && v.toArray().size() == w.width) {
            for (int k = 0; k < w.width; ++k)
                out[k] = v.toArray()[k].isDouble() ? v.toArray()[k].toDouble() : NaN;
        } else if (w.width == 3 && v.isObject()) {
            const QJsonObject xyz = v.toObject();
            const char *names[] = {"x", "y", "z"};
            for (int k = 0; k < 3; ++k) {
                const QJsonValue c = xyz.value(QLatin1String(names[k]));
                out[k] = c.isDouble() ? c.toDouble() : NaN;
            }
        }
    }
    return true;
}

} // namespace semhap
