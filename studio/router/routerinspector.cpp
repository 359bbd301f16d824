// SPDX-License-Identifier: MIT
#include "routerinspector.h"

#include "patternlibrary.h"
#include "routereditor.h"
#include "routerscene.h"
#include "userpatterns.h"

#include <QApplication>
#include <QComboBox>
#include <QFormLayout>
#include <QJsonArray>
#include <QJsonDocument>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QRegularExpression>
#include <QScrollArea>
#include <QScrollBar>
#include <QTimer>
#include <QVBoxLayout>

#include <algorithm>
#include <optional>

namespace semhap {

namespace {

/**
 * An editable list of names whose entries are worked out again each time it opens: a live
 * rig's signals grow while the inspector shows a node.
 */
class NameCombo : public QComboBox
{
public:
    using Choices = std::function<QStringList()>;

    NameCombo(const QString &absent, Choices choices, QWidget *parent)
        : QComboBox(parent), m_absent(absent), m_choices(std::move(choices))
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

private:
    /** The first entry leaves the parameter out; typed, its text means the same. */
    void fill()
    {
        addItem(m_absent, QString());
        for (const QString &choice : m_choices())
            addItem(choice, choice);
    }

    QString m_absent;
    Choices m_choices;
};

/** Numbers in the user's locale, without group separators that would read as decimals. */
QLocale numberLocale()
{
    QLocale locale;
    locale.setNumberOptions(QLocale::OmitGroupSeparator | QLocale::RejectGroupSeparator);
    return locale;
}

/** A parameter's value as the inspector shows it. */
QString valueText(const QJsonValue &value)
{
    if (value.isUndefined() || value.isNull())
        return QString();
    if (value.isString())
        return value.toString();
    if (value.isDouble())
        return numberLocale().toString(value.toDouble(), 'g', 12);
    const QJsonDocument doc =
        value.isArray() ? QJsonDocument(value.toArray()) : QJsonDocument(value.toObject());
    return QString::fromUtf8(doc.toJson(QJsonDocument::Compact));
}

/** What the user typed as a parameter: a number, JSON, or a plain string; empty: unset. */
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

/** The separator of a range's two numbers: `;` where the comma is the decimal point. */
QString rangeSeparator()
{
    return numberLocale().decimalPoint() == QLatin1String(",") ? QStringLiteral("; ")
                                                               : QStringLiteral(", ");
}

/** A level as the inspector shows it: `80`, or `[0.02, 0.08]` (`[0,02; 0,08]` in German). */
QString levelText(const QJsonValue &value)
{
    const QJsonArray pair = value.toArray();
    if (!value.isArray() || pair.size() != 2 || !pair.at(0).isDouble() || !pair.at(1).isDouble())
        return valueText(value);
    const QLocale locale = numberLocale();
    return QStringLiteral("[%1%2%3]")
        .arg(locale.toString(pair.at(0).toDouble(), 'g', 12), rangeSeparator(),
             locale.toString(pair.at(1).toDouble(), 'g', 12));
}

/**
 * A level typed: a number, a JSON range `[0.02, 0.08]`, or two numbers in the user's
 * locale with or without brackets (`0.02, 0.08`; in German `0,02; 0,08` or `0,02, 0,08`);
 * else what parseValue() makes of it, for the compiler to name what is wrong.
 */
QJsonValue parseLevel(const QString &text)
{
    const QJsonValue value = parseValue(text);
    if (!value.isString())
        return value;
    QString inner = value.toString();
    if (inner.startsWith(QLatin1Char('[')) && inner.endsWith(QLatin1Char(']')))
        inner = inner.mid(1, inner.size() - 2);
    // A comma with a space after it parts the numbers even where it is the decimal point.
    const QStringList parts = inner.contains(QLatin1Char(';'))
                                  ? inner.split(QLatin1Char(';'))
                                  : inner.split(QRegularExpression(QStringLiteral(",\\s+")));
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

/** Names typed into a list field: `grasp, aligned` as a list, one name as itself. */
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

/** Whether the field takes a name the user may type: a signal, an open message list. */
bool takesTypedName(const ParamSpec &spec)
{
    return spec.kind == ParamKind::Signal ||
           (spec.openChoices &&
            (spec.kind == ParamKind::Choice || spec.kind == ParamKind::Choices));
}

} // namespace

RouterInspector::RouterInspector(RouterEditor &editor, QWidget *parent)
    : QWidget(parent), m_editor(editor)
{
    setObjectName(QStringLiteral("routerInspector"));
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    auto *scroll = new QScrollArea(this);
    scroll->setObjectName(QStringLiteral("inspectorScroll"));
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    layout->addWidget(scroll);
}

void RouterInspector::forget()
{
    m_inspected.clear();
    schedule();
}

void RouterInspector::refresh()
{
    m_inspectedNode = RouterNode();
    schedule();
}

void RouterInspector::schedule()
{
    if (m_pending)
        return;
    m_pending = true;
    // Later: the field that made the edit may still be inside its signal.
    QTimer::singleShot(0, this, [this] {
        m_pending = false;
        rebuild();
    });
}

void RouterInspector::rebuild()
{
    const QStringList ids = m_editor.scene()->selectedNodeIds();
    const int index = ids.size() == 1 ? m_editor.graph().nodeIndex(ids.front()) : -1;
    auto *scroll = findChild<QScrollArea *>(QStringLiteral("inspectorScroll"));
    // The same node edited: the new fields show where the old ones were scrolled to, with
    // the focus in the field it was in (an edit jumped back to the top).
    int keptScroll = 0;
    QString keptFocus;
    if (index >= 0 && m_inspected == m_editor.graph().nodes[size_t(index)].id &&
        scroll->widget()) {
        keptScroll = scroll->verticalScrollBar()->value();
        if (QWidget *focus = QApplication::focusWidget();
            focus && scroll->widget()->isAncestorOf(focus)) {
            for (QWidget *w = focus; w != scroll->widget(); w = w->parentWidget()) {
                if (w->objectName().startsWith(QLatin1String("param:")) ||
                    w->objectName() == QLatin1String("nodeId")) {
                    keptFocus = w->objectName();
                    break;
                }
            }
        }
    }
    if (index >= 0) {
        const RouterNode &node = m_editor.graph().nodes[size_t(index)];
        // Unchanged: keep the fields, and the focus the user is typing in.
        if (scroll->widget() && m_inspected == node.id && m_inspectedNode.type == node.type &&
            m_inspectedNode.params == node.params)
            return;
        m_inspected = node.id;
        m_inspectedNode = node;
    } else {
        m_inspected.clear();
    }

    auto *page = new QWidget;
    auto *form = new QFormLayout(page);
    form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    if (index < 0) {
        auto *hint = new QLabel(ids.isEmpty() ? tr("Select a node to edit its parameters.")
                                              : tr("%n nodes selected.", nullptr, int(ids.size())),
                                page);
        hint->setWordWrap(true);
        form->addRow(hint);
        scroll->setWidget(page);
        return;
    }
    const RouterNode &node = m_editor.graph().nodes[size_t(index)];
    const RouterNodeType *type = routerNodeType(node.type);
    auto *title = new QLabel(
        type ? QStringLiteral("<b>%1</b> — %2").arg(node.type, type->description) : node.type,
        page);
    title->setWordWrap(true);
    form->addRow(title);
    auto *idEdit = new QLineEdit(node.id, page);
    idEdit->setObjectName(QStringLiteral("nodeId"));
    idEdit->setToolTip(tr("The name events and devices carry"));
    const QString id = node.id;
    connect(idEdit, &QLineEdit::editingFinished, this, [this, idEdit, id] {
        QString reason;
        if (!m_editor.renameNode(id, idEdit->text().trimmed(), &reason)) {
            emit status(reason, true);
            idEdit->setText(id);
        }
    });
    form->addRow(tr("id"), idEdit);

    const std::vector<ParamSpec> specs = m_editor.graph().paramsOf(node);
    for (const ParamSpec &spec : specs)
        addField(form, node, spec.name, &spec);
    for (auto it = node.params.begin(); it != node.params.end(); ++it) {
        if (!findParamSpec(specs, it.key()))
            addField(form, node, it.key(), nullptr); // unknown: shown so it can be cleared
    }
    scroll->setWidget(page);
    if (keptScroll > 0) {
        page->adjustSize(); // the scroll range follows the new page at once
        scroll->verticalScrollBar()->setValue(keptScroll);
    }
    if (!keptFocus.isEmpty()) {
        if (auto *field = page->findChild<QWidget *>(keptFocus))
            field->setFocus(Qt::OtherFocusReason);
    }
}

void RouterInspector::addField(QFormLayout *form, const RouterNode &node, const QString &key,
                               const ParamSpec *spec)
{
    const QJsonValue value = node.params.value(key);
    const ParamKind kind = spec ? spec->kind : ParamKind::Points;
    const bool name = kind == ParamKind::Pattern || kind == ParamKind::Model;
    const QString id = node.id;
    const QString objectName = QStringLiteral("param:") + key;
    const QString help = spec ? spec->help : tr("Not a parameter of this node: clear it");
    auto *label = new QLabel(
        spec && !spec->unit.isEmpty() ? QStringLiteral("%1 (%2)").arg(key, spec->unit) : key,
        form->parentWidget());
    label->setToolTip(help);
    if (spec && kind == ParamKind::Signal) {
        // The built-in quantities, then what the source's frames carry for the node's
        // gripper (both grippers' while it has none).
        const QString hand = node.params.value(QStringLiteral("gripper")).toString();
        addNameCombo(form, label, node, key, *spec, [this, builtin = spec->choices, hand] {
            QStringList choices = builtin;
            const RouterContext source = m_editor.context();
            for (Gripper gripper : {Gripper::Left, Gripper::Right}) {
                if (hand.isEmpty() || hand == gripperName(gripper))
                    choices.append(source.signalNames[size_t(gripper)]);
            }
            choices.removeDuplicates();
            return choices;
        });
        return;
    }
    if (spec && takesTypedName(*spec)) {
        // The built-in messages, then the new ones other nodes of the graph name.
        addNameCombo(form, label, node, key, *spec, [this, builtin = spec->choices] {
            QStringList choices = builtin + m_editor.newMessageNames();
            choices.removeDuplicates();
            return choices;
        });
        return;
    }
    if (kind == ParamKind::Choice || kind == ParamKind::Choices || name) {
        QStringList choices = spec->choices;
        if (kind == ParamKind::Pattern) {
            for (const PatternPtr &pattern : m_editor.graph().patterns)
                choices.append(pattern->name());
            choices.append(PatternLibrary::builtinNames());
        } else if (kind == ParamKind::Model) {
            for (const DeviceModelPtr &model : m_editor.graph().models)
                choices.append(model->name());
            choices.append(DeviceModelLibrary::builtinNames());
        }
        auto *combo = new QComboBox(form->parentWidget());
        combo->setObjectName(objectName);
        combo->setToolTip(help);
        combo->setEditable(name);
        combo->setInsertPolicy(QComboBox::NoInsert);
        if (!name)
            combo->addItem(absentText(*spec), QString());
        for (const QString &choice : choices)
            combo->addItem(choice, choice);
        if (kind == ParamKind::Pattern) {
            // The designer's saved patterns, by name; the node names the file, which the
            // router loads (and a self-contained save embeds).
            for (const UserPattern &pattern : userPatterns()) {
                const bool taken = combo->findText(pattern.name) >= 0;
                combo->addItem(taken ? tr("%1 (your file)").arg(pattern.name) : pattern.name,
                               pattern.path);
                combo->setItemData(combo->count() - 1, pattern.path, Qt::ToolTipRole);
            }
        }
        const QString current = valueText(value);
        int at = combo->findData(current);
        if (at < 0 && !current.isEmpty()) {
            combo->addItem(current, current); // a list, a path: shown as it is
            at = combo->count() - 1;
        }
        if (name) {
            combo->setCurrentIndex(std::max(at, 0));
            combo->setEditText(at >= 0 ? combo->itemText(at) : current);
            // What an entry stands for (a file for the user's patterns), or what was typed.
            const auto chosen = [combo](const QString &text) {
                const int i = combo->findText(text);
                return i >= 0 ? combo->itemData(i).toString() : text;
            };
            connect(combo, &QComboBox::activated, this, [this, id, key, combo](int i) {
                commitText(id, key, combo->itemData(i).toString());
            });
            connect(combo->lineEdit(), &QLineEdit::editingFinished, this,
                    [this, id, key, combo, chosen] {
                        commitText(id, key, chosen(combo->currentText()));
                    });
        } else {
            combo->setCurrentIndex(std::max(at, 0));
            connect(combo, &QComboBox::activated, this, [this, id, key, combo](int i) {
                commitText(id, key, combo->itemData(i).toString());
            });
        }
        form->addRow(label, combo);
        return;
    }
    auto *edit = new QLineEdit(kind == ParamKind::Level ? levelText(value) : valueText(value),
                               form->parentWidget());
    edit->setObjectName(objectName);
    edit->setPlaceholderText(spec ? absentText(*spec) : QString());
    edit->setToolTip(help);
    connect(edit, &QLineEdit::editingFinished, this,
            [this, id, key, edit] { commitText(id, key, edit->text()); });
    form->addRow(label, edit);
}

void RouterInspector::addNameCombo(QFormLayout *form, QLabel *label, const RouterNode &node,
                                   const QString &key, const ParamSpec &spec,
                                   std::function<QStringList()> choices)
{
    auto *combo = new NameCombo(absentText(spec), std::move(choices), form->parentWidget());
    combo->setObjectName(QStringLiteral("param:") + key);
    combo->setToolTip(spec.help);
    const QString current = valueText(node.params.value(key));
    const int at = current.isEmpty() ? 0 : combo->findData(current);
    combo->setCurrentIndex(std::max(at, 0));
    combo->setEditText(at >= 0 ? combo->itemText(at) : current);
    if (QLineEdit *line = combo->lineEdit())
        line->setPlaceholderText(absentText(spec));
    const QString id = node.id;
    connect(combo, &QComboBox::activated, this,
            [this, id, key, combo](int i) { commitText(id, key, combo->itemData(i).toString()); });
    connect(combo->lineEdit(), &QLineEdit::editingFinished, this, [this, id, key, combo] {
        const int i = combo->findText(combo->currentText());
        commitText(id, key, i >= 0 ? combo->itemData(i).toString() : combo->currentText());
    });
    form->addRow(label, combo);
}

QString RouterInspector::absentText(const ParamSpec &spec)
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

void RouterInspector::commitText(const QString &id, const QString &key, const QString &text)
{
    const int index = m_editor.graph().nodeIndex(id);
    if (index < 0)
        return;
    const ParamSpec *spec =
        findParamSpec(m_editor.graph().paramsOf(m_editor.graph().nodes[size_t(index)]), key);
    const ParamKind kind = spec ? spec->kind : ParamKind::Points;
    QJsonValue value = parseValue(text);
    if (kind == ParamKind::Level)
        value = parseLevel(text);
    else if (kind == ParamKind::Choices && spec->openChoices)
        value = parseNames(text);
    // A numeric-looking pattern, model, signal or message name is still a name.
    const bool name = kind == ParamKind::Pattern || kind == ParamKind::Model ||
                      (spec && kind != ParamKind::Choices && takesTypedName(*spec));
    m_editor.setParam(id, key, name && !value.isUndefined() ? QJsonValue(text.trimmed()) : value);
}

} // namespace semhap
