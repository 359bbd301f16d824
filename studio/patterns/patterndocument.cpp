// SPDX-License-Identifier: MIT
#include "patterndocument.h"

#include "waveformtype.h"

#include "outputfile.h"

#include <QDir>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>

namespace semhap {

namespace {

QStringList pointerTokens(const QString &pointer)
{
    QStringList tokens = pointer.split(QLatin1Char('/'));
    tokens.removeFirst(); // before the leading '/'
    for (QString &token : tokens)
        token.replace(QStringLiteral("~1"), QStringLiteral("/"))
            .replace(QStringLiteral("~0"), QStringLiteral("~"));
    return tokens;
}

QJsonValue replaced(const QJsonValue &node, const QStringList &tokens, int depth,
                    const QJsonValue &value)
{
    if (depth == tokens.size())
        return value;
    const QString &token = tokens[depth];
    if (node.isArray()) {
        QJsonArray array = node.toArray();
        const int index = token.toInt();
        if (index < 0 || index > array.size())
            return node;
        const QJsonValue child = replaced(array.at(index), tokens, depth + 1, value);
        if (child.isUndefined() && index < array.size())
            array.removeAt(index);
        else if (index == array.size())
            array.append(child);
        else
            array[index] = child;
        return array;
    }
    QJsonObject object = node.toObject();
    const QJsonValue child = replaced(object.value(token), tokens, depth + 1, value);
    if (child.isUndefined())
        object.remove(token);
    else
        object.insert(token, child);
    return object;
}

} // namespace

/** One edit: the document before and after, so undo and redo restore it exactly. */
class PatternDocument::SetJsonCommand : public QUndoCommand
{
public:
    SetJsonCommand(PatternDocument &document, QJsonObject before, QJsonObject after,
                   const QString &text)
        : QUndoCommand(text), m_document(document), m_before(std::move(before)),
          m_after(std::move(after))
    {}
    void undo() override { m_document.apply(m_before); }
    void redo() override { m_document.apply(m_after); }

private:
    PatternDocument &m_document;
    QJsonObject m_before;
    QJsonObject m_after;
};

PatternDocument::PatternDocument(QObject *parent) : QObject(parent)
{
    connect(&m_undo, &QUndoStack::cleanChanged, this, &PatternDocument::stateChanged);
}

void PatternDocument::reset(const QJsonObject &json, const QString &path, bool readOnly)
{
    m_undo.clear();
    m_path = path;
    m_readOnly = readOnly;
    apply(json);
    emit stateChanged();
}

void PatternDocument::setPath(const QString &path)
{
    m_path = path;
    emit stateChanged();
}

void PatternDocument::apply(const QJsonObject &json)
{
    m_json = json;
    m_error = LoadError();
    const QString file = m_path.isEmpty() ? json.value(QLatin1String("name")).toString() : m_path;
    m_pattern = Pattern::fromJson(json, QFileInfo(file).fileName(), &m_error);
    emit changed();
}

void PatternDocument::setJson(const QJsonObject &json, const QString &text)
{
    if (m_readOnly || json == m_json)
        return;
    m_undo.push(new SetJsonCommand(*this, m_json, json, text));
}

void PatternDocument::setValue(const QString &pointer, const QJsonValue &value)
{
    if (m_readOnly)
        return;
    const QJsonObject after = withValue(m_json, pointer, value).toObject();
    if (after == m_json)
        return;
    const QStringList tokens = pointerTokens(pointer);
    m_undo.push(new SetJsonCommand(
        *this, m_json, after, tr("Edit %1").arg(tokens.isEmpty() ? QString() : tokens.last())));
}

QJsonValue PatternDocument::value(const QString &pointer) const
{
    return valueAt(m_json, pointer);
}

QString PatternDocument::addTrack()
{
    const QString pointer =
        QStringLiteral("/tracks/%1").arg(value(QStringLiteral("/tracks")).toArray().size());
    setValue(pointer,
             QJsonObject{{QStringLiteral("channels"), QJsonArray{QStringLiteral("*")}},
                         {QStringLiteral("sustain"), newWaveform(QStringLiteral("const"))}});
    return pointer;
}

QString PatternDocument::addPart(const QString &track, const QString &part)
{
    const QString trackPointer = track.section(QLatin1Char('/'), 0, 2);
    if (!trackPointer.startsWith(QLatin1String("/tracks/")))
        return QString();
    const QString pointer = trackPointer + QLatin1Char('/') + part;
    if (value(pointer).isUndefined()) {
        QJsonObject node = newWaveform(part == QLatin1String("sustain") ? QStringLiteral("const")
                                                                        : QStringLiteral("ramp"));
        if (part == QLatin1String("release"))
            node.insert(QStringLiteral("to"), 0);
        setValue(pointer, node);
    }
    return pointer;
}

QString PatternDocument::addInput(const QString &pointer)
{
    const QString list = pointer + QStringLiteral("/of");
    const QString input = QStringLiteral("%1/%2").arg(list).arg(value(list).toArray().size());
    setValue(input, newWaveform(QStringLiteral("const")));
    return input;
}

QString PatternDocument::remove(const QString &pointer)
{
    setValue(pointer, QJsonValue(QJsonValue::Undefined));
    // An input of a combinator sits in its `of` list: what held it is two levels up.
    return pointer.section(QLatin1Char('/'), 0, pointer.contains(QLatin1String("/of/")) ? -3 : -2);
}

bool PatternDocument::canAddPart(const QString &pointer) const
{
    return !m_readOnly && pointer.startsWith(QLatin1String("/tracks/"));
}

bool PatternDocument::canAddInput(const QString &pointer) const
{
    const WaveformType *type = waveformType(value(pointer + QStringLiteral("/type")).toString());
    return !m_readOnly && type && type->field(QStringLiteral("of"));
}

bool PatternDocument::canRemove(const QString &pointer) const
{
    if (m_readOnly)
        return false;
    const int depth = int(pointer.count(QLatin1Char('/')));
    if (depth == 2 && pointer.startsWith(QLatin1String("/tracks/")))
        return value(QStringLiteral("/tracks")).toArray().size() > 1;
    if (depth == 3 && pointer.startsWith(QLatin1String("/tracks/")))
        return true; // an attack, sustain or release
    const QString holder = pointer.section(QLatin1Char('/'), 0, -2);
    return holder.endsWith(QLatin1String("/of")) && value(holder).toArray().size() > 1;
}

QJsonObject PatternDocument::newPattern(const QString &name, const QString &model)
{
    QJsonObject release = newWaveform(QStringLiteral("ramp"));
    release.insert(QStringLiteral("to"), 0);
    return {
        {QStringLiteral("format"), QString::fromLatin1(Pattern::Format)},
        {QStringLiteral("name"), name},
        {QStringLiteral("model"), model},
        {QStringLiteral("tracks"),
         QJsonArray{QJsonObject{{QStringLiteral("channels"), QJsonArray{QStringLiteral("*")}},
                                {QStringLiteral("attack"), newWaveform(QStringLiteral("ramp"))},
                                {QStringLiteral("sustain"), newWaveform(QStringLiteral("const"))},
                                {QStringLiteral("release"), release}}}}};
}

QJsonValue PatternDocument::valueAt(const QJsonValue &root, const QString &pointer)
{
    QJsonValue node = root;
    if (pointer.isEmpty())
        return node;
    for (const QString &token : pointerTokens(pointer)) {
        if (node.isArray()) {
            bool ok = false;
            const int index = token.toInt(&ok);
            const QJsonArray array = node.toArray();
            if (!ok || index < 0 || index >= array.size())
                return QJsonValue(QJsonValue::Undefined);
            node = array.at(index);
        } else if (node.isObject()) {
            node = node.toObject().value(token);
        } else {
            return QJsonValue(QJsonValue::Undefined);
        }
    }
    return node;
}

QJsonValue PatternDocument::withValue(const QJsonValue &root, const QString &pointer,
                                      const QJsonValue &value)
{
    if (pointer.isEmpty())
        return value;
    return replaced(root, pointerTokens(pointer), 0, value);
}

bool PatternDocument::save(const QString &path, QString *error)
{
    QDir().mkpath(QFileInfo(path).absolutePath());
    LoadError failure;
    if (!OutputFile::write(path, QJsonDocument(m_json).toJson(QJsonDocument::Indented),
                           &failure)) {
        *error = failure.toString();
        return false;
    }
    m_path = path;
    m_readOnly = false;
    m_undo.setClean();
    emit stateChanged();
    return true;
}

} // namespace semhap
