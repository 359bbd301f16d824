// SPDX-License-Identifier: MIT
#pragma once

#include "paramspec.h"

#include <QHash>
#include <QJsonValue>
#include <QList>
#include <QWidget>

#include <functional>

class QFormLayout;

namespace semhap {

/**
 * A form of parameters built from their specs: one field per ParamSpec, chosen by its kind
 * (a number, a level, a choice, a list, points, channels, a name typed or picked, where a
 * ramp starts), labelled with its unit, with its help as tooltip and what leaving it out
 * means as placeholder. A committed edit is emitted as the parameter's new JSON value;
 * where the form shows it is the owner's business (a router node, a waveform).
 */
class ParamForm : public QWidget
{
    Q_OBJECT

public:
    /** How the form edits numbers. */
    enum class Numbers
    {
        Typed, ///< a line in the user's locale; left empty, the parameter is absent
        Bound  ///< a NumberEdit: a constant, or a pattern parameter through gain and offset
    };
    /** An entry a name field offers; `value` is what picking it sets (a user pattern's file). */
    struct Choice
    {
        QString text;
        QString value;
    };
    /** Entries a field offers beyond its spec's choices, asked again each time it opens. */
    using Choices = std::function<QList<Choice>()>;
    /** How a text field shows its text: one line, or lines that wrap (prose). */
    enum class TextShape
    {
        Line,
        Lines
    };
    /** Where the keyboard is: the field's object name and the part of it (a spin box). */
    struct Focus
    {
        QString field;
        QString part;
    };

    explicit ParamForm(Numbers numbers, QWidget *parent = nullptr);

    /**
     * What name fields of `kind` offer beyond their spec's choices: patterns, models,
     * signals, parameter names, and for Choice and Choices the new names an open list takes.
     */
    void setChoices(ParamKind kind, Choices choices);
    /** The pattern parameters a Bound number may follow (none: constants only). */
    void setBindings(const QStringList &params);

    /** Removes every row. */
    void clear();
    /**
     * A field for `spec` showing `value` (undefined: absent), labelled `name` and its unit.
     * Waveform inputs get none: they are edited as the tree's children.
     */
    void addParam(const ParamSpec &spec, const QJsonValue &value, const QString &name);
    /** A field for a parameter no spec knows, in JSON, shown so that it can be cleared. */
    void addUnknown(const QString &key, const QJsonValue &value);
    /**
     * A text field that commits when the keyboard leaves it (a line also on Return);
     * `toJson` gives null for text it does not understand, undefined to remove.
     */
    void addText(const QString &key, const QString &label, const QString &text,
                 const std::function<QJsonValue(const QString &)> &toJson,
                 TextShape shape = TextShape::Line);
    /** A line of explanation under the fields. */
    void addNote(const QString &text);
    /** A row the owner makes itself (a title, a node's id). */
    void addRow(const QString &label, QWidget *field);
    void addRow(QWidget *row);

    Focus focus() const;
    /** Puts the keyboard back into the field (and part) it was in before a rebuild. */
    void restoreFocus(const Focus &focus);

    /** What a field shows when its parameter is absent: "(default: 20)", "(any)"… */
    static QString absentText(const ParamSpec &spec);
    /** The object name of parameter `key`'s field: "param:KEY". */
    static QString fieldName(const QString &key);

signals:
    /** The user committed `value` (undefined: leave it out) for parameter `key`. */
    void edited(const QString &key, const QJsonValue &value);

private:
    QWidget *numberField(const ParamSpec &spec, const QJsonValue &value);
    QWidget *choiceField(const ParamSpec &spec, const QJsonValue &value);
    QWidget *nameField(const ParamSpec &spec, const QJsonValue &value);
    void addStart(const ParamSpec &spec, const QJsonValue &value, const QString &name);
    QList<Choice> choicesOf(const ParamSpec &spec) const;
    void addLabelled(const ParamSpec &spec, const QString &name, QWidget *field);

    Numbers m_numbers;
    QFormLayout *m_form = nullptr;
    QHash<int, Choices> m_choices; ///< by ParamKind
    QStringList m_bindings;
};

} // namespace semhap
