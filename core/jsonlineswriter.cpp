// SPDX-License-Identifier: MIT
#include "jsonlineswriter.h"

#include "actortable.h"
#include "nametable.h"
#include "routernodetype.h"

#include <QIODevice>

#include <algorithm>
#include <charconv>
#include <cmath>

namespace semhap {

namespace {

const QByteArray Null = QByteArrayLiteral("null");

QByteArray encoded(const QString &text)
{
    QByteArray out;
    JsonLinesWriter::appendString(out, text);
    return out;
}

template<typename Enum, size_t Count>
void encodeNames(std::array<QByteArray, Count> &names, QString (*nameOf)(Enum))
{
    for (size_t i = 0; i < Count; ++i)
        names[i] = encoded(nameOf(Enum(i)));
}

template<typename Enum, size_t Count>
const QByteArray &lookup(const std::array<QByteArray, Count> &names, Enum value)
{
    const size_t i = size_t(value);
    return i < Count ? names[i] : Null;
}

const QByteArray &lookup(const std::vector<QByteArray> &names, int index)
{
    return index >= 0 && size_t(index) < names.size() ? names[size_t(index)] : Null;
}

std::vector<QByteArray> encodedList(const QStringList &names)
{
    std::vector<QByteArray> out;
    out.reserve(size_t(names.size()));
    for (const QString &name : names)
        out.push_back(encoded(name));
    return out;
}

} // namespace

JsonLinesWriter::JsonLinesWriter(QIODevice *device) : m_device(device)
{
    encodeNames(m_grippers, gripperName);
    m_kinds = encodedList(detectorKindNames());
    encodeNames(m_categories, categoryName);
    encodeNames(m_phases, eventPhaseName);
    m_line.reserve(256);
}

void JsonLinesWriter::setNodeNames(const QStringList &names)
{
    m_nodes = encodedList(names);
}

void JsonLinesWriter::setDeviceNames(const QStringList &names)
{
    m_devices = encodedList(names);
}

bool JsonLinesWriter::write(const SemanticEvent &event)
{
    m_line.clear();
    m_line += "{\"t\":";
    appendNumber(m_line, event.t);
    m_line += ",\"gripper\":";
    m_line += lookup(m_grippers, event.gripper);
    m_line += ",\"node\":";
    m_line += lookup(m_nodes, event.node);
    m_line += ",\"detector\":";
    m_line += lookup(m_kinds, int(event.detector));
    m_line += ",\"message\":";
    m_line += tableName(messageNames(), m_messages, int(event.message));
    m_line += ",\"category\":";
    m_line += lookup(m_categories, event.category);
    m_line += ",\"phase\":";
    m_line += lookup(m_phases, event.phase);
    m_line += ",\"intensity\":";
    appendNumber(m_line, event.intensity);
    m_line += '}';
    return writeLine();
}

bool JsonLinesWriter::write(const DeviceFrame &frame)
{
    m_line.clear();
    m_line += "{\"t\":";
    appendNumber(m_line, frame.t);
    m_line += ",\"device\":";
    m_line += lookup(m_devices, frame.device);
    m_line += ",\"values\":[";
    const int count = std::clamp(frame.channelCount, 0, MaxChannels);
    for (int i = 0; i < count; ++i) {
        if (i > 0)
            m_line += ',';
        appendNumber(m_line, frame.values[size_t(i)]);
    }
    m_line += "]}";
    return writeLine();
}

bool JsonLinesWriter::write(const ContactFrame &frame)
{
    m_line.clear();
    m_line += "{\"t\":";
    appendNumber(m_line, frame.t);
    m_line += ",\"gripper\":";
    m_line += lookup(m_grippers, frame.gripper);
    appendFingertip(",\"left\":{\"f\":", frame.left);
    appendFingertip(",\"right\":{\"f\":", frame.right);
    if (!frame.signalValues.isEmpty()) {
        m_line += ",\"signals\":{";
        bool first = true;
        for (const SignalValue &signal : frame.signalValues) {
            if (!first)
                m_line += ',';
            first = false;
            m_line += tableName(signalNames(), m_signals, signal.id);
            m_line += ':';
            appendNumber(m_line, signal.value);
        }
        m_line += '}';
    }
    m_line += '}';
    return writeLine();
}

void JsonLinesWriter::appendFingertip(const char *key, const Fingertip &tip)
{
    m_line += key;
    appendNumber(m_line, tip.f);
    m_line += ",\"n\":";
    appendNumber(m_line, tip.n);
    m_line += ",\"actor\":";
    m_line += actorName(tip.actor);
    if (tip.hasFxyz) {
        m_line += ",\"fxyz\":[";
        for (size_t i = 0; i < tip.fxyz.size(); ++i) {
            if (i > 0)
                m_line += ',';
            appendNumber(m_line, tip.fxyz[i]);
        }
        m_line += ']';
    }
    if (tip.mu > 0.0) {
        m_line += ",\"mu\":";
        appendNumber(m_line, tip.mu);
    }
    m_line += '}';
}

const QByteArray &JsonLinesWriter::tableName(const NameTable &table,
                                             std::vector<QByteArray> &cache, int id)
{
    if (id < 0)
        return Null;
    while (cache.size() <= size_t(id)) {
        const QString name = table.name(int(cache.size()));
        if (name.isNull())
            return Null;
        cache.push_back(encoded(name));
    }
    return cache[size_t(id)];
}

const QByteArray &JsonLinesWriter::actorName(int actor)
{
    if (!m_actors || actor < 0 || actor >= m_actors->size())
        return Null;
    while (m_actorNames.size() <= size_t(actor))
        m_actorNames.push_back(encoded(m_actors->name(int(m_actorNames.size()))));
    return m_actorNames[size_t(actor)];
}

bool JsonLinesWriter::writeLine()
{
    m_line += '\n';
    return m_device->write(m_line) == m_line.size();
}

void JsonLinesWriter::appendNumber(QByteArray &out, double value)
{
    if (!std::isfinite(value)) {
        out += Null;
        return;
    }
    // Shortest round-trip form: integers come out without a decimal point.
    char buffer[32];
    const std::to_chars_result result = std::to_chars(buffer, buffer + sizeof buffer, value);
    out.append(buffer, result.ptr - buffer);
}

void JsonLinesWriter::appendString(QByteArray &out, const QString &text)
{
    static const char hex[] = "0123456789abcdef";
    out += '"';
    for (const char c : text.toUtf8()) {
        const auto byte = static_cast<unsigned char>(c);
        if (c == '"' || c == '\\') {
            out += '\\';
            out += c;
        } else if (byte < 0x20) {
            out += "\\u00";
            out += hex[byte >> 4];
            out += hex[byte & 0xf];
        } else {
            out += c;
        }
    }
    out += '"';
}

} // namespace semhap
