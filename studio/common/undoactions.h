// SPDX-License-Identifier: MIT
#pragma once

#include <QCoreApplication>

class QAction;
class QUndoStack;
class QWidget;

namespace semhap {

/**
 * Undo and redo for an editor's toolbar that keep their short names ("Undo", "Redo")
 * whatever the stack holds, with what they would undo or redo in their tooltips. QUndoStack's
 * own actions grow to "Undo Arrange" and push a dock's toolbar into its overflow menu.
 */
class UndoActions
{
    Q_DECLARE_TR_FUNCTIONS(UndoActions)

public:
    /** Undoes `stack`'s last command; Ctrl+Z while the focus is in `owner`, which holds it. */
    static QAction *undo(QUndoStack *stack, QWidget *owner);
    /**
     * Redoes `stack`'s next command; the platform's redo keys and Ctrl+Y while the focus is
     * in `owner`.
     */
    static QAction *redo(QUndoStack *stack, QWidget *owner);
};

} // namespace semhap
