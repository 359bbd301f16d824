// SPDX-License-Identifier: MIT
#pragma once

#include "paramspec.h"

#include <QJsonObject>
#include <QWidget>

class QLabel;

namespace semhap {

class ParamForm;
class PatternDocument;

/**
 * The parameters of the node selected in the designer's waveform tree, as a ParamForm: the
 * pattern's name and description, a track's channels, or a waveform's type and the fields
 * of its type's specs (numbers with their parameter bindings, start values, keyframes).
 * Each committed edit is one undoable change of the document.
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
    /** A field's translated display name: "Frequency". */
    static QString fieldLabel(const QString &key);
    void edit(const QString &key, const QJsonValue &value);
    QStringList paramNames() const;

    PatternDocument &m_document;
    QString m_pointer;
    ParamForm *m_form = nullptr;
    QLabel *m_heading = nullptr;
    bool m_rebuildPending = false;
};

} // namespace semhap
