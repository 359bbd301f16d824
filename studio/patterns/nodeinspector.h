// SPDX-License-Identifier: MIT
#pragma once

#include "paramspec.h"

#include <QJsonObject>
#include <QWidget>

#include <functional>

class QFormLayout;
class QLabel;

namespace semhap {

class PatternDocument;

/**
 * The parameters of the node selected in the designer's waveform tree, as a form: the
 * pattern's name and description, a track's channels, or a waveform's type and fields
 * (numbers with their parameter bindings, start values, keyframes). Each committed edit
 * is one undoable change of the document.
 */
class NodeInspector : public QWidget
{
    Q_OBJECT

public:
    explicit NodeInspector(PatternDocument &document, QWidget *parent = nullptr);

    /** Shows the node at `pointer` ("" the pattern, "/tracks/0" a track, else a waveform). */
    void setTarget(const QString &pointer);
    const QString &target() const { return m_pointer; }

    /** The waveform types the designer offers, in menu order. */
    static QStringList waveformTypes();

private:
    void scheduleRebuild();
    void rebuild();
    void addPatternFields();
    void addTrackFields();
    void addWaveformFields(const QJsonObject &node);
    void addNumber(const QJsonObject &node, const ParamSpec &field, const QString &label);
    /** A field's translated display name and unit: "Frequency (Hz)". */
    static QString fieldLabel(const ParamSpec &field);
    void addStart(const QJsonObject &node);
    /** How a text field shows its text: one line, or lines that wrap (prose). */
    enum class TextShape
    {
        Line,
        Lines
    };
    /**
     * A text field that commits when the keyboard leaves it (a line also on Return);
     * `toJson` gives null for text it does not understand, undefined to remove.
     */
    void addText(const QString &key, const QString &label, const QString &text,
                 const std::function<QJsonValue(const QString &)> &toJson,
                 TextShape shape = TextShape::Line);
    /** A line of explanation under the fields. */
    void addNote(const QString &text);
    void edit(const QString &key, const QJsonValue &value);
    QStringList paramNames() const;

    PatternDocument &m_document;
    QString m_pointer;
    QFormLayout *m_form = nullptr;
    QLabel *m_heading = nullptr;
    bool m_rebuildPending = false;
};

} // namespace semhap
