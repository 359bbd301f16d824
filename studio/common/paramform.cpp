// SPDX-License-Identifier: MIT
#include "paramform.h"

#include "colors.h"
#include "numberedit.h"

#include <QAbstractTextDocumentLayout>
#include <QApplication>
#include <QComboBox>
#include <QFocusEvent>
#include <QFormLayout>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QPlainTextEdit>
#include <QRegularExpression>

#include <algorithm>

namespace semhap {

namespace {

// NumberEdit's spin boxes take no infinite bounds.
constexpr double Unbounded = 1e6;

/** Numbers in the user's locale, without group separators that would read as decimals. */
QLocale numberLocale()
{
    QLocale locale;
    locale.setNumberOptions(QLocale::OmitGroupSeparator | QLocale::RejectGroupSeparator);
    return locale;
}

QString numberText(double number)
{
    return numberLocale().toString(number, 'g', 12);
}

/** A value as a field shows it: a string as itself, a number in the locale, else JSON. */
QString valueText(const QJsonValue &value)
{
    if (value.isUndefined() || value.isNull())
        return QString();
    if (value.isString())
        return value.toString();
    if (value.isDouble())
        return numberText(value.toDouble());
    const QJsonDocument doc =
        value.isArray() ? QJsonDocument(value.toArray()) : QJsonDocument(value.toObject());
    return QString::fromUtf8(doc.toJson(QJsonDocument::Compact));
}

/** What the user typed: a number in the locale, JSON, or a plain string; empty: absent. */
QJsonValue parseValue(const QString &text)
{
    const QString trimmed = text.trimmed();
    if (trimmed.isEmpty())
        return QJsonValue(QJsonValue::Undefined);
    bool ok = false;
    const double number = numberLocale().toDouble(trimmed, &ok);
    if (ok)
        return number;
    const QJsonDocument doc = QJsonDocument::fromJson(QByteArrayLiteral("[") + trimmed.toUtf8() +
                                                      QByteArrayLiteral("]"));
    if (doc.isArray() && doc.array().size() == 1)
        return doc.array().at(0);
    return trimmed;
}

/** What parts two numbers, or two points: `;` where the comma is the decimal point. */
QString pairSeparator()
{
    return numberLocale().decimalPoint() == QLatin1String(",") ? QStringLiteral("; ")
                                                               : QStringLiteral(", ");
}

/**
 * Text split into the parts of a range or a list of points: at `;` if it has one, else at
 * commas (only a comma and a space where the comma is the decimal point).
 */
QStringList splitPairs(const QString &text)
{
    if (text.contains(QLatin1Char(';')))
        return text.split(QLatin1Char(';'));
    if (numberLocale().decimalPoint() == QLatin1String(","))
        return text.split(QRegularExpression(QStringLiteral(",\\s+")));
    return text.split(QLatin1Char(','));
}

/** A level: `80`, or `[0.02, 0.08]` (`[0,02; 0,08]` in German). */
QString levelText(const QJsonValue &value)
{
    const QJsonArray pair = value.toArray();
    if (!value.isArray() || pair.size() != 2 || !pair.at(0).isDouble() || !pair.at(1).isDouble())
        return valueText(value);
    return QStringLiteral("[%1%2%3]")
        .arg(numberText(pair.at(0).toDouble()), pairSeparator(),
             numberText(pair.at(1).toDouble()));
}

/**
 * A level typed: a number, a JSON range `[0.02, 0.08]`, or two numbers in the user's
 * locale with or without brackets (`0.02, 0.08`; in German `0,02; 0,08` or `0,02, 0,08`);
 * else what parseValue() makes of it, for the loader to name what is wrong.
 */
QJsonValue parseLevel(const QString &text)
{
    const QJsonValue value = parseValue(text);
    if (!value.isString())
        return value;
    QString inner = value.toString();
    if (inner.startsWith(QLatin1Char('[')) && inner.endsWith(QLatin1Char(']')))
        inner = inner.mid(1, inner.size() - 2);
    const QStringList parts = splitPairs(inner);
    if (parts.size() != 2)
        return value;
    QJsonArray range;
    for (const QString &part : parts) {
        bool ok = false;
        const double number = numberLocale().toDouble(part.trimmed(), &ok);
        if (!ok)
            return value;
        range.append(number);
    }
    return range;
}

/** `[[0, 0], [0.5, 1]]` as `0:0, 0.5:1` (`0:0; 0,5:1` in German), short enough for a line. */
QString pointsText(const QJsonValue &value)
{
    QStringList parts;
    for (const QJsonValue &p : value.toArray()) {
        if (!p.isArray() || p.toArray().size() != 2)
            return valueText(value);
        parts.append(
            QStringLiteral("%1:%2").arg(numberText(p[0].toDouble()), numberText(p[1].toDouble())));
    }
    return parts.join(pairSeparator());
}

/** Points typed as `x:y` pairs or as JSON; null when neither. */
QJsonValue parsePoints(const QString &text)
{
    const QJsonValue value = parseValue(text);
    if (!value.isString())
        return value.isUndefined() || value.isArray() ? value : QJsonValue(QJsonValue::Null);
    QJsonArray points;
    for (const QString &part : splitPairs(value.toString())) {
        const QStringList xy = part.split(QLatin1Char(':'));
        bool okX = false;
        bool okY = false;
        const double x = numberLocale().toDouble(xy.value(0).trimmed(), &okX);
        const double y = numberLocale().toDouble(xy.value(1).trimmed(), &okY);
        if (xy.size() != 2 || !okX || !okY)
            return QJsonValue(QJsonValue::Null);
        points.append(QJsonArray{x, y});
    }
    return points;
}

/** Names typed into a list: `grasp, aligned` as a list, one name as itself. */
QJsonValue parseNames(const QString &text)
{
    const QJsonValue value = parseValue(text);
    if (!value.isString() || !value.toString().contains(QLatin1Char(',')))
        return value;
    QJsonArray names;
    for (const QString &name : value.toString().split(QLatin1Char(','), Qt::SkipEmptyParts))
        names.append(name.trimmed());
    return names;
}

/** Channels typed: `p0, p1` (always a list); empty: absent. */
QJsonValue parseChannels(const QString &text)
{
    QJsonArray names;
    for (const QString &name : text.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        if (!name.trimmed().isEmpty())
            names.append(name.trimmed());
    }
    return names.isEmpty() ? QJsonValue(QJsonValue::Undefined) : QJsonValue(names);
}

QString channelsText(const QJsonValue &value)
{
    if (!value.isArray())
        return valueText(value);
    QStringList names;
    for (const QJsonValue &name : value.toArray())
        names.append(name.toString());
    return names.join(QStringLiteral(", "));
}

/** Whether the field takes a name the user may type: a signal, a file, an open list. */
bool takesName(const ParamSpec &spec)
{
    switch (spec.kind) {
    case ParamKind::Signal:
    case ParamKind::Pattern:
    case ParamKind::Model:
        return true;
    case ParamKind::Choice:
    case ParamKind::Choices:
        return spec.openChoices;
    default:
        return false;
    }
}

/**
 * An editable list of names whose entries are worked out again each time it opens: a live
 * rig's signals grow, and the designer's files change, while the form shows a node.
 */
class NameCombo : public QComboBox
{
public:
    using Entries = std::function<QList<ParamForm::Choice>()>;

    NameCombo(Entries entries, QWidget *parent) : QComboBox(parent), m_entries(std::move(entries))
    {
        setEditable(true);
        setInsertPolicy(QComboBox::NoInsert);
        fill();
    }
    void showPopup() override
    {
        const QString typed = currentText();
        {
            const QSignalBlocker blocker(this);
            clear();
            fill();
            setEditText(typed);
        }
        QComboBox::showPopup();
    }
    /** What the typed text stands for: an entry's value, else the text itself. */
    QString chosen() const
    {
        const int i = findText(currentText());
        return i >= 0 ? itemData(i).toString() : currentText().trimmed();
    }

private:
    void fill()
    {
        for (const ParamForm::Choice &entry : m_entries()) {
            addItem(entry.text, entry.value);
            if (entry.value != entry.text && !entry.value.isEmpty())
                setItemData(count() - 1, entry.value, Qt::ToolTipRole);
        }
    }

    Entries m_entries;
};

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

ParamForm::ParamForm(Numbers numbers, QWidget *parent) : QWidget(parent), m_numbers(numbers)
{
    m_form = new QFormLayout(this);
    m_form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
}

void ParamForm::setChoices(ParamKind kind, Choices choices)
{
    m_choices.insert(int(kind), std::move(choices));
}

void ParamForm::setBindings(const QStringList &params)
{
    m_bindings = params;
}

void ParamForm::clear()
{
    while (m_form->rowCount() > 0)
        m_form->removeRow(0);
}

QString ParamForm::fieldName(const QString &key)
{
    return QStringLiteral("param:") + key;
}

QString ParamForm::absentText(const ParamSpec &spec)
{
    switch (spec.absent) {
    case ParamAbsent::Required:
        return tr("(none)");
    case ParamAbsent::Any:
        return tr("(any)");
    case ParamAbsent::Computed:
        return tr("(automatic)");
    case ParamAbsent::Default:
        break;
    }
    const QJsonValue standard = spec.defaultValue();
    if (standard.isDouble())
        return tr("(default: %1)").arg(QLocale().toString(standard.toDouble()));
    if (standard.isString())
        return tr("(default: %1)").arg(standard.toString());
    return tr("(default)");
}

QList<ParamForm::Choice> ParamForm::choicesOf(const ParamSpec &spec) const
{
    QList<Choice> entries;
    // A list that may be left out starts with the entry that leaves it out.
    if (spec.absent != ParamAbsent::Required)
        entries.append({absentText(spec), QString()});
    QStringList texts;
    const auto add = [&](const Choice &entry) {
        if (texts.contains(entry.text))
            return;
        texts.append(entry.text);
        entries.append(entry);
    };
    for (const QString &choice : spec.choices)
        add({choice, choice});
    const bool extra = takesName(spec) || spec.kind == ParamKind::ParamName;
    if (extra && m_choices.contains(int(spec.kind))) {
        for (const Choice &entry : m_choices.value(int(spec.kind))())
            add(entry);
    }
    return entries;
}

void ParamForm::addLabelled(const ParamSpec &spec, const QString &name, QWidget *field)
{
    auto *label =
        new QLabel(spec.unit.isEmpty() ? name : tr("%1 (%2)").arg(name, spec.unit), this);
    label->setToolTip(spec.help);
    field->setObjectName(fieldName(spec.name));
    field->setToolTip(spec.help);
    m_form->addRow(label, field);
}

void ParamForm::addParam(const ParamSpec &spec, const QJsonValue &value, const QString &name)
{
    switch (spec.kind) {
    case ParamKind::Waveform:
    case ParamKind::Waveforms:
        return;
    case ParamKind::Start:
        addStart(spec, value, name);
        return;
    case ParamKind::Number:
        if (m_numbers == Numbers::Bound) {
            addLabelled(spec, name, numberField(spec, value));
            return;
        }
        break;
    case ParamKind::Choice:
    case ParamKind::Choices:
    case ParamKind::ParamName:
        if (!takesName(spec)) {
            addLabelled(spec, name, choiceField(spec, value));
            return;
        }
        break;
    default:
        break;
    }
    if (takesName(spec)) {
        addLabelled(spec, name, nameField(spec, value));
        return;
    }
    // Typed: a number, a level, points, channels.
    std::function<QJsonValue(const QString &)> parse = parseValue;
    QString text = valueText(value);
    if (spec.kind == ParamKind::Level) {
        parse = parseLevel;
        text = levelText(value);
    } else if (spec.kind == ParamKind::Points) {
        parse = parsePoints;
        text = pointsText(value);
    } else if (spec.kind == ParamKind::Channels) {
        parse = parseChannels;
        text = channelsText(value);
    }
    QString label = spec.unit.isEmpty() ? name : tr("%1 (%2)").arg(name, spec.unit);
    if (spec.kind == ParamKind::Points)
        label = QStringLiteral("%1 (x:y%2…)").arg(label, pairSeparator());
    addText(spec.name, label, text, parse);
    auto *line = findChild<QLineEdit *>(fieldName(spec.name));
    line->setPlaceholderText(absentText(spec));
    line->setToolTip(spec.help);
    if (auto *labelWidget = qobject_cast<QLabel *>(m_form->labelForField(line)))
        labelWidget->setToolTip(spec.help);
}

void ParamForm::addUnknown(const QString &key, const QJsonValue &value)
{
    addText(key, key, valueText(value), parseValue);
    auto *line = findChild<QLineEdit *>(fieldName(key));
    line->setToolTip(tr("Not a parameter of this node: clear it"));
}

QWidget *ParamForm::numberField(const ParamSpec &spec, const QJsonValue &value)
{
    auto *edit = new NumberEdit(this);
    const bool absent = value.isUndefined() || value.isNull();
    edit->setNumber(absent ? QJsonValue(spec.defaultNumber) : value, m_bindings,
                    std::max(spec.minimum, -Unbounded), std::min(spec.maximum, Unbounded));
    connect(edit, &NumberEdit::edited, this,
            [this, key = spec.name](const QJsonValue &number) { emit edited(key, number); });
    return edit;
}

QWidget *ParamForm::choiceField(const ParamSpec &spec, const QJsonValue &value)
{
    auto *combo = new QComboBox(this);
    combo->setPlaceholderText(absentText(spec));
    for (const Choice &entry : choicesOf(spec))
        combo->addItem(entry.text, entry.value);
    const QString current = valueText(value);
    int at = combo->findData(current);
    if (at < 0 && !current.isEmpty()) {
        combo->addItem(current, current); // a list: shown as it is
        at = combo->count() - 1;
    }
    combo->setCurrentIndex(at);
    const bool list = spec.kind == ParamKind::Choices;
    connect(combo, &QComboBox::activated, this, [this, combo, list, key = spec.name](int i) {
        const QString picked = combo->itemData(i).toString();
        emit edited(key, picked.isEmpty() ? QJsonValue(QJsonValue::Undefined)
                         : list           ? parseNames(picked)
                                          : QJsonValue(picked));
    });
    return combo;
}

QWidget *ParamForm::nameField(const ParamSpec &spec, const QJsonValue &value)
{
    auto *combo = new NameCombo([this, spec] { return choicesOf(spec); }, this);
    const QString current = valueText(value);
    const int at = current.isEmpty() ? -1 : combo->findData(current);
    combo->setCurrentIndex(at);
    combo->setEditText(at >= 0 ? combo->itemText(at) : current);
    combo->lineEdit()->setPlaceholderText(absentText(spec));
    // A numeric-looking name is still a name; an open list takes several.
    const bool list = spec.kind == ParamKind::Choices;
    const auto commit = [this, list, key = spec.name](const QString &chosen) {
        emit edited(key, chosen.isEmpty() ? QJsonValue(QJsonValue::Undefined)
                         : list           ? parseNames(chosen)
                                          : QJsonValue(chosen));
    };
    connect(combo, &QComboBox::activated, this,
            [combo, commit](int i) { commit(combo->itemData(i).toString()); });
    connect(combo->lineEdit(), &QLineEdit::editingFinished, this,
            [combo, commit] { commit(combo->chosen()); });
    return combo;
}

void ParamForm::addStart(const ParamSpec &spec, const QJsonValue &value, const QString &name)
{
    auto *from = new QComboBox(this);
    from->addItem(tr("current value"), QStringLiteral("current"));
    from->addItem(tr("peak since begin"), QStringLiteral("peak"));
    from->addItem(tr("fixed value"), QStringLiteral("value"));
    const bool fixed = !value.isString() && !value.isUndefined();
    from->setCurrentIndex(fixed ? 2 : std::max(0, from->findData(value.toString())));
    connect(from, &QComboBox::activated, this, [this, from, key = spec.name](int i) {
        const QString choice = from->itemData(i).toString();
        emit edited(key, choice == QLatin1String("current") ? QJsonValue(QJsonValue::Undefined)
                         : choice == QLatin1String("peak")  ? QJsonValue(choice)
                                                            : QJsonValue(0.0));
    });
    addLabelled(spec, name, from);
    from->setToolTip(tr("Where the envelope starts: the track's value when it began, its "
                        "peak, or a fixed value"));
    if (fixed) {
        const ParamSpec start = ParamSpec::number(spec.name, 0, QString(), from->toolTip());
        addLabelled(start, tr("Start value"), numberField(start, value));
    }
}

void ParamForm::addText(const QString &key, const QString &label, const QString &text,
                        const std::function<QJsonValue(const QString &)> &toJson, TextShape shape)
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
        emit edited(key, value);
    };
    if (auto *line = qobject_cast<QLineEdit *>(field))
        connect(line, &QLineEdit::editingFinished, this, commit);
    else
        static_cast<TextBox *>(field)->finished = commit;
    m_form->addRow(label, field);
}

void ParamForm::addNote(const QString &text)
{
    // Wrapped: a note never makes the form wider than its dock.
    auto *note = new QLabel(text, this);
    note->setWordWrap(true);
    m_form->addRow(QString(), note);
}

void ParamForm::addRow(const QString &label, QWidget *field)
{
    field->setParent(this);
    m_form->addRow(label, field);
}

void ParamForm::addRow(QWidget *row)
{
    row->setParent(this);
    m_form->addRow(row);
}

ParamForm::Focus ParamForm::focus() const
{
    Focus focus;
    // The field is the form's own child; the part is what inside it has the keyboard.
    for (QWidget *w = QApplication::focusWidget(); w && w != this; w = w->parentWidget()) {
        if (w->parentWidget() == this) {
            focus.field = w->objectName();
            return focus;
        }
        focus.part = w->objectName();
    }
    return {};
}

void ParamForm::restoreFocus(const Focus &focus)
{
    if (focus.field.isEmpty())
        return;
    auto *field = findChild<QWidget *>(focus.field, Qt::FindDirectChildrenOnly);
    if (!field)
        return;
    QWidget *part = focus.part.isEmpty() ? nullptr : field->findChild<QWidget *>(focus.part);
    (part ? part : field)->setFocus(Qt::OtherFocusReason);
}

} // namespace semhap
