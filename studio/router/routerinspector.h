// SPDX-License-Identifier: MIT
#pragma once

#include "routergraph.h"

#include <QWidget>

#include <functional>

class QFormLayout;
class QLabel;

namespace semhap {

class RouterEditor;

/**
 * The router editor's form of the selected node's parameters: a field per parameter of its
 * type, built from the specs (numbers, choices, lists, levels, points, names typed or
 * picked), each with its unit, its help and what an absent value means; an edit goes to the
 * editor as one undoable step, and a refused one is said on the editor's status line.
 */
class RouterInspector : public QWidget
{
    Q_OBJECT

public:
    RouterInspector(RouterEditor &editor, QWidget *parent = nullptr);

    /** Builds the form again at the next event loop turn: the selection or graph changed. */
    void schedule();
    /** Another document: the next form starts at its top. */
    void forget();
    /** The choices offered changed (another source): the fields are made again. */
    void refresh();

signals:
    /** What the editor's status line says: why an edit was refused. */
    void status(const QString &text, bool warning);

private:
    void rebuild();
    /** A field for parameter `key`, built from its spec (null: a parameter the type lacks). */
    void addField(QFormLayout *form, const RouterNode &node, const QString &key,
                  const ParamSpec *spec);
    /** What the field shows when the parameter is absent: "(default: 20)", "(any)"… */
    static QString absentText(const ParamSpec &spec);
    void commitText(const QString &id, const QString &key, const QString &text);
    /**
     * An editable combo for a name typed or picked (a signal, a new message), offering
     * `choices()` each time it opens.
     */
    void addNameCombo(QFormLayout *form, QLabel *label, const RouterNode &node, const QString &key,
                      const ParamSpec &spec, std::function<QStringList()> choices);

    RouterEditor &m_editor;
    QString m_inspected; ///< id of the node the form shows
    RouterNode m_inspectedNode;
    bool m_pending = false;
};

} // namespace semhap
