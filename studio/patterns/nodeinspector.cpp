// SPDX-License-Identifier: MIT
#include "nodeinspector.h"

#include "colors.h"
#include "numberedit.h"
#include "patterndocument.h"
#include "waveformtype.h"

#include <QAbstractTextDocumentLayout>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFocusEvent>
#include <QFormLayout>
#include <QHash>
#include <QJsonArray>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QRegularExpression>
#include <QVBoxLayout>

#include <algorithm>
#include <functional>

namespace semhap {

namespace {

constexpr double Unbounded = 1e6;

QString fieldName(const QString &key)
{
    return QStringLiteral("field:") + key;
}

/** `[[0, 0], [0.5, 1]]` as `0:0, 0.5:1`, short enough for one line. */
QString pointsText(const QJsonArray &points)
{
    QStringList parts;
    for (const QJsonValue &p : points)
        parts.append(QStringLiteral("%1:%2").arg(p[0].toDouble()).arg(p[1].toDouble()));
    return parts.join(QStringLiteral(", "));
}

QJsonValue pointsJson(const QString &text)
{
    QJsonArray points;
    for (const QString &part : text.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        const QStringList tv = part.split(QLatin1Char(':'));
        bool okT = false;
        bool okV = false;
        const double t = tv.value(0).trimmed().toDouble(&okT);
        const double v = tv.value(1).trimmed().toDouble(&okV);
        if (tv.size() != 2 || !okT || !okV)
            return QJsonValue(QJsonValue::Null);
        points.append(QJsonArray{t, v});
    }
    return points;
}

/** Lines of text that wrap, for prose; `finished` runs when the keyboard leaves it. */
class TextBox : public QPlainTextEdit
{
public:
    TextBox(const QString &text, QWidget *parent) : QPlainTextEdit(text, parent)
    {
        setTabChangesFocus(true);
        setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
        setWordWrapMode(QTextOption::WrapAtWordBoundaryOrAnywhere);
        connect(document()->documentLayout(), &QAbstractTextDocumentLayout::documentSizeChanged,
                this, &TextBox::fitText);
    }

    std::function<void()> finished;

protected:
    void focusOutEvent(QFocusEvent *event) override
    {
        QPlainTextEdit::focusOutEvent(event);
        if (finished && event->reason() != Qt::PopupFocusReason)
            finished();
    }

    void resizeEvent(QResizeEvent *event) override
    {
        QPlainTextEdit::resizeEvent(event);
        fitText();
    }

private:
    /** As tall as its wrapped text, two to six lines: a description reads whole. */
    void fitText()
    {
        // A plain text layout measures its document in lines.
        const int lines = int(document()->documentLayout()->documentSize().height());
        setVerticalScrollBarPolicy(lines > MaxLines ? Qt::ScrollBarAsNeeded
                                                    : Qt::ScrollBarAlwaysOff);
        const int shown = std::clamp(lines, 2, MaxLines);
        const int height = shown * fontMetrics().lineSpacing() +
                           2 * (frameWidth() + int(document()->documentMargin()));
        if (height != this->height())
            setFixedHeight(height);
    }

    static constexpr int MaxLines = 6;
};

} // namespace

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
    auto *formHolder = new QWidget(this);
    m_form = new QFormLayout(formHolder);
    m_form->setContentsMargins(0, 0, 0, 0);
    m_form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    layout->addWidget(formHolder);
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
    QString focusField;
    QString focusChild;
    for (QWidget *w = focusWidget(); w && w != this; w = w->parentWidget()) {
        if (w->objectName().startsWith(QLatin1String("field:"))) {
            focusField = w->objectName();
            break;
        }
        focusChild = w->objectName();
    }
    while (m_form->rowCount() > 0)
        m_form->removeRow(0);

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

    if (focusField.isEmpty())
        return;
    if (auto *field = findChild<QWidget *>(focusField)) {
        QWidget *target = focusChild.isEmpty() ? field : field->findChild<QWidget *>(focusChild);
        (target ? target : field)->setFocus();
    }
}

void NodeInspector::addPatternFields()
{
    const QJsonObject &json = m_document.json();
    addText(QStringLiteral("name"), tr("Name"), json.value(QLatin1String("name")).toString(),
            [](const QString &text) { return QJsonValue(text.trimmed()); });
    addText(
        QStringLiteral("description"), tr("Description"),
        json.value(QLatin1String("description")).toString(),
        [](const QString &text) {
            return text.trimmed().isEmpty() ? QJsonValue(QJsonValue::Undefined)
                                            : QJsonValue(text.trimmed());
        },
        TextShape::Lines);
    QStringList params;
    const QJsonObject declared = json.value(QLatin1String("params")).toObject();
    for (auto it = declared.begin(); it != declared.end(); ++it)
        params.append(QStringLiteral("%1=%2").arg(it.key()).arg(it.value().toDouble()));
    addText(QStringLiteral("params"), tr("Parameters"), params.join(QStringLiteral(", ")),
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
    addText(QStringLiteral("channels"), tr("Channels"), channels.join(QStringLiteral(", ")),
            [](const QString &text) {
                QJsonArray out;
                for (const QString &name : text.split(QLatin1Char(','), Qt::SkipEmptyParts))
                    out.append(name.trimmed());
                return out.isEmpty() ? QJsonValue(QJsonArray{QStringLiteral("*")})
                                     : QJsonValue(out);
            });
    addNote(tr("* drives every channel of the model"));
}

void NodeInspector::addWaveformFields(const QJsonObject &node)
{
    auto *type = new QComboBox(this);
    type->setObjectName(fieldName(QStringLiteral("type")));
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
    bool inputs = false;
    for (const ParamSpec &field : kind->fields) {
        const QString label = fieldLabel(field);
        switch (field.kind) {
        case ParamKind::Number:
            addNumber(node, field, label);
            break;
        case ParamKind::ParamName: {
            auto *name = new QComboBox(this);
            name->setObjectName(fieldName(field.name));
            name->setToolTip(field.help);
            name->addItems(paramNames());
            name->setCurrentText(node.value(field.name).toString());
            connect(name, &QComboBox::activated, this,
                    [this, name, key = field.name] { edit(key, name->currentText()); });
            m_form->addRow(label, name);
            break;
        }
        case ParamKind::Points:
            addText(field.name, label + tr(" (t:v, …)"),
                    pointsText(node.value(field.name).toArray()), pointsJson);
            break;
        case ParamKind::Start:
            addStart(node);
            break;
        case ParamKind::Waveform:
        case ParamKind::Waveforms:
            inputs = true;
            break;
        default:
            break;
        }
    }
    if (inputs)
        addNote(tr("Its inputs are the children in the tree."));
}

QString NodeInspector::fieldLabel(const ParamSpec &field)
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
    };
    const char *name = names.value(field.name);
    const QString label = name ? tr(name) : field.name;
    return field.unit.isEmpty() ? label : tr("%1 (%2)").arg(label, field.unit);
}

void NodeInspector::addNumber(const QJsonObject &node, const ParamSpec &field,
                              const QString &label)
{
    auto *edit = new NumberEdit(this);
    const QString key = field.name;
    edit->setObjectName(fieldName(key));
    edit->setToolTip(field.help);
    const WaveformType *type = waveformType(node.value(QLatin1String("type")).toString());
    const bool plain = type && !type->bindsParams();
    edit->setNumber(node.contains(key) ? node.value(key) : QJsonValue(field.defaultNumber),
                    plain ? QStringList() : paramNames(), std::max(field.minimum, -Unbounded),
                    std::min(field.maximum, Unbounded));
    connect(edit, &NumberEdit::edited, this,
            [this, key](const QJsonValue &value) { this->edit(key, value); });
    m_form->addRow(label, edit);
}

void NodeInspector::addStart(const QJsonObject &node)
{
    auto *from = new QComboBox(this);
    from->setObjectName(fieldName(QStringLiteral("from")));
    from->addItem(tr("current value"), QStringLiteral("current"));
    from->addItem(tr("peak since begin"), QStringLiteral("peak"));
    from->addItem(tr("fixed value"), QStringLiteral("value"));
    const QJsonValue value = node.value(QLatin1String("from"));
    from->setCurrentIndex(value.isString() || value.isUndefined()
                              ? std::max(0, from->findData(value.toString()))
                              : 2);
    from->setToolTip(tr("Where the envelope starts: the track's value when it began, its "
                        "peak, or a fixed value"));
    connect(from, &QComboBox::activated, this, [this, from] {
        const QString choice = from->currentData().toString();
        edit(QStringLiteral("from"), choice == QLatin1String("current")
                                         ? QJsonValue(QJsonValue::Undefined)
                                     : choice == QLatin1String("peak") ? QJsonValue(choice)
                                                                       : QJsonValue(0.0));
    });
    m_form->addRow(tr("Starts from"), from);
    if (from->currentIndex() == 2)
        addNumber(node, ParamSpec::number(QStringLiteral("from"), 0, QString(), from->toolTip()),
                  tr("Start value"));
}

void NodeInspector::addText(const QString &key, const QString &label, const QString &text,
                            const std::function<QJsonValue(const QString &)> &toJson,
                            TextShape shape)
{
    QWidget *field = nullptr;
    std::function<QString()> typed;
    if (shape == TextShape::Lines) {
        auto *box = new TextBox(text, this);
        field = box;
        typed = [box] { return box->toPlainText(); };
    } else {
        auto *line = new QLineEdit(text, this);
        field = line;
        typed = [line] { return line->text(); };
    }
    field->setObjectName(fieldName(key));
    const auto commit = [this, key, field, typed, toJson, text] {
        if (typed() == text)
            return;
        const QJsonValue value = toJson(typed());
        if (value.isNull()) {
            field->setStyleSheet(QStringLiteral("%1 { border: 2px solid %2; }")
                                     .arg(QLatin1String(field->metaObject()->className()),
                                          colors::css(colors::Exception)));
            field->setToolTip(tr("Not understood; nothing was changed"));
            return;
        }
        edit(key, value);
    };
    if (auto *line = qobject_cast<QLineEdit *>(field))
        connect(line, &QLineEdit::editingFinished, this, commit);
    else
        static_cast<TextBox *>(field)->finished = commit;
    m_form->addRow(label, field);
}

void NodeInspector::addNote(const QString &text)
{
    // Wrapped: a note never makes the form wider than the inspector.
    auto *note = new QLabel(text, this);
    note->setWordWrap(true);
    m_form->addRow(QString(), note);
}

void NodeInspector::edit(const QString &key, const QJsonValue &value)
{
    m_document.setValue(m_pointer + QLatin1Char('/') + key, value);
}

} // namespace semhap
