// SPDX-License-Identifier: MIT
#pragma once

#include "routergraph.h"

#include <QWidget>

namespace semhap {

class ParamForm;
class RouterEditor;

/**
 * The router editor's form of the selected node's parameters: its id, and a ParamForm of
 * its type's specs whose name fields offer what the graph and the source know (patterns,
 * models, signals, new messages); an edit goes to the editor as one undoable step, and a
 * refused one is said on the editor's status line.
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
    /** What the node's name fields offer: its signals, new messages, patterns and models. */
    void offerChoices(ParamForm &form, const RouterNode &node) const;

    RouterEditor &m_editor;
    QString m_inspected; ///< id of the node the form shows
    RouterNode m_inspectedNode;
    bool m_pending = false;
};

} // namespace semhap
