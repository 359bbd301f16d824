// SPDX-License-Identifier: MIT
#include "nodeinspector.h"

#include "paramform.h"
#include "patterndocument.h"
#include "waveformtype.h"

#include <QComboBox>
#include <QHash>
#include <QJsonArray>
#include <QLabel>
#include <QLayout>
#include <QRegularExpression>
#include <QVBoxLayout>

namespace semhap {

NodeInspector::NodeInspector(PatternDocument &document, QWidget *parent)
    : QWidget(parent), m_document(document)
{
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    m_heading = new QLabel(this);
    m_heading->setObjectName(QStringLiteral("heading"));
    QFont bold = m_heading->font();
    bold.setBold(true);
    m_heading->setFont(bold);
    layout->addWidget(m_heading);
    m_form = new ParamForm(ParamForm::Numbers::Bound, this);
    m_form->layout()->setContentsMargins(0, 0, 0, 0);
    m_form->setChoices(ParamKind::ParamName, [this] {
        QList<ParamForm::Choice> choices;
        for (const QString &name : paramNames())
            choices.append({name, name});
        return choices;
    });
    connect(m_form, &ParamForm::edited, this, &NodeInspector::edit);
    layout->addWidget(m_form);
    layout->addStretch(1);
    connect(&m_document, &PatternDocument::changed, this, &NodeInspector::scheduleRebuild);
    connect(&m_document, &PatternDocument::stateChanged, this, &NodeInspector::scheduleRebuild);
}

void NodeInspector::setTarget(const QString &pointer)
{
    m_pointer = pointer;
    scheduleRebuild();
}

void NodeInspector::scheduleRebuild()
{
    // Later, not now: the edit that led here may come from a widget the rebuild deletes.
    if (m_rebuildPending)
        return;
    m_rebuildPending = true;
    QMetaObject::invokeMethod(this, &NodeInspector::rebuild, Qt::QueuedConnection);
}

QStringList NodeInspector::waveformTypes()
{
    QStringList names;
    for (const WaveformType &type : semhap::waveformTypes())
        names.append(type.type);
    return names;
}

QStringList NodeInspector::paramNames() const
{
    QStringList names{QStringLiteral("intensity")};
    const QJsonObject params = m_document.json().value(QLatin1String("params")).toObject();
    for (auto it = params.begin(); it != params.end(); ++it) {
        if (!names.contains(it.key()))
            names.append(it.key());
    }
    return names;
}

void NodeInspector::rebuild()
{
    m_rebuildPending = false;
    // Keep the keyboard where it was: the form is rebuilt after every committed edit.
    const ParamForm::Focus focus = m_form->focus();
    m_form->clear();

    const QJsonValue node = m_document.value(m_pointer);
    setEnabled(!m_document.isReadOnly());
    if (m_pointer.isEmpty()) {
        m_heading->setText(tr("Pattern"));
        addPatternFields();
    } else if (QRegularExpression(QStringLiteral("^/tracks/\\d+$")).match(m_pointer).hasMatch()) {
        m_heading->setText(tr("Track %1").arg(m_pointer.section(QLatin1Char('/'), 2).toInt() + 1));
        addTrackFields();
    } else if (node.isObject()) {
        m_heading->setText(tr("Waveform"));
        addWaveformFields(node.toObject());
    } else {
        m_heading->setText(tr("Select a node in the tree"));
    }

    m_form->restoreFocus(focus);
}

void NodeInspector::addPatternFields()
{
    const QJsonObject &json = m_document.json();
    m_form->addText(QStringLiteral("name"), tr("Name"),
                    json.value(QLatin1String("name")).toString(),
                    [](const QString &text) { return QJsonValue(text.trimmed()); });
    m_form->addText(
        QStringLiteral("description"), tr("Description"),
        json.value(QLatin1String("description")).toString(),
        [](const QString &text) {
            return text.trimmed().isEmpty() ? QJsonValue(QJsonValue::Undefined)
                                            : QJsonValue(text.trimmed());
        },
        ParamForm::TextShape::Lines);
    QStringList params;
    const QJsonObject declared = json.value(QLatin1String("params")).toObject();
    for (auto it = declared.begin(); it != declared.end(); ++it)
        params.append(QStringLiteral("%1=%2").arg(it.key()).arg(it.value().toDouble()));
    m_form->addText(
        QStringLiteral("params"), tr("Parameters"), params.join(QStringLiteral(", ")),
        [](const QString &text) {
            QJsonObject out;
            for (const QString &part : text.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
                const QString name = part.section(QLatin1Char('='), 0, 0).trimmed();
                bool ok = false;
                const double value = part.section(QLatin1Char('='), 1).trimmed().toDouble(&ok);
                if (name.isEmpty() || !ok)
                    return QJsonValue(QJsonValue::Null);
                out.insert(name, value);
            }
            return out.isEmpty() ? QJsonValue(QJsonValue::Undefined) : QJsonValue(out);
        });
}

void NodeInspector::addTrackFields()
{
    QStringList channels;
    for (const QJsonValue &c : m_document.value(m_pointer + QStringLiteral("/channels")).toArray())
        channels.append(c.toString());
    m_form->addText(
        QStringLiteral("channels"), tr("Channels"), channels.join(QStringLiteral(", ")),
        [](const QString &text) {
            QJsonArray out;
            for (const QString &name : text.split(QLatin1Char(','), Qt::SkipEmptyParts))
                out.append(name.trimmed());
            return out.isEmpty() ? QJsonValue(QJsonArray{QStringLiteral("*")}) : QJsonValue(out);
        });
    m_form->addNote(tr("* drives every channel of the model"));
}

void NodeInspector::addWaveformFields(const QJsonObject &node)
{
    auto *type = new QComboBox;
    type->setObjectName(ParamForm::fieldName(QStringLiteral("type")));
    type->addItems(waveformTypes());
    type->setCurrentText(node.value(QLatin1String("type")).toString());
    type->setToolTip(tr("Changing the type to a combinator keeps this waveform as its input"));
    connect(type, &QComboBox::activated, this, [this, type, node] {
        if (type->currentText() != node.value(QLatin1String("type")).toString())
            m_document.setValue(m_pointer, newWaveform(type->currentText(), node));
    });
    m_form->addRow(tr("Type"), type);

    const WaveformType *kind = waveformType(node.value(QLatin1String("type")).toString());
    if (!kind)
        return;
    m_form->setBindings(kind->bindsParams() ? paramNames() : QStringList());
    bool inputs = false;
    for (const ParamSpec &field : kind->fields) {
        m_form->addParam(field, node.value(field.name), fieldLabel(field.name));
        inputs = inputs || field.kind == ParamKind::Waveform || field.kind == ParamKind::Waveforms;
    }
    if (inputs)
        m_form->addNote(tr("Its inputs are the children in the tree."));
}

QString NodeInspector::fieldLabel(const QString &key)
{
    // Display names only: which fields exist, their defaults and ranges are the table's.
    static const QHash<QString, const char *> names{
        {QStringLiteral("value"), QT_TR_NOOP("Value")},
        {QStringLiteral("to"), QT_TR_NOOP("To")},
        {QStringLiteral("time"), QT_TR_NOOP("Time")},
        {QStringLiteral("points"), QT_TR_NOOP("Points")},
        {QStringLiteral("freq"), QT_TR_NOOP("Frequency")},
        {QStringLiteral("amp"), QT_TR_NOOP("Amplitude")},
        {QStringLiteral("offset"), QT_TR_NOOP("Offset")},
        {QStringLiteral("phase"), QT_TR_NOOP("Phase")},
        {QStringLiteral("duty"), QT_TR_NOOP("Duty")},
        {QStringLiteral("high"), QT_TR_NOOP("High")},
        {QStringLiteral("low"), QT_TR_NOOP("Low")},
        {QStringLiteral("rate"), QT_TR_NOOP("Rate")},
        {QStringLiteral("width"), QT_TR_NOOP("Width")},
        {QStringLiteral("name"), QT_TR_NOOP("Parameter")},
        {QStringLiteral("gain"), QT_TR_NOOP("Gain")},
        {QStringLiteral("div"), QT_TR_NOOP("Divide by")},
        {QStringLiteral("min"), QT_TR_NOOP("Minimum")},
        {QStringLiteral("max"), QT_TR_NOOP("Maximum")},
        {QStringLiteral("curve"), QT_TR_NOOP("Curve")},
        {QStringLiteral("from"), QT_TR_NOOP("Starts from")},
    };
    const char *name = names.value(key);
    return name ? tr(name) : key;
}

void NodeInspector::edit(const QString &key, const QJsonValue &value)
{
    m_document.setValue(m_pointer + QLatin1Char('/') + key, value);
}

} // namespace semhap
