// SPDX-License-Identifier: MIT
#include "undoactions.h"

#include <QAction>
#include <QUndoStack>
#include <QWidget>

namespace semhap {

namespace {

QAction *makeAction(QUndoStack *stack, QWidget *owner, bool redo)
{
    auto *action = new QAction(redo ? UndoActions::tr("Redo") : UndoActions::tr("Undo"), owner);
    QList<QKeySequence> keys =
        QKeySequence::keyBindings(redo ? QKeySequence::Redo : QKeySequence::Undo);
    // Ctrl+Y redoes on every platform, as it does on some (the manual promises it).
    const QKeySequence redoY(Qt::CTRL | Qt::Key_Y);
    if (redo && !keys.contains(redoY))
        keys.append(redoY);
    action->setShortcuts(keys);
    action->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    const QString key = action->shortcut().toString(QKeySequence::NativeText);
    const auto describe = [action, key, redo](const QString &command) {
        const QString what =
            command.isEmpty()
                ? action->text()
                : (redo ? UndoActions::tr("Redo: %1") : UndoActions::tr("Undo: %1")).arg(command);
        action->setToolTip(QStringLiteral("%1 (%2)").arg(what, key));
    };
    describe(redo ? stack->redoText() : stack->undoText());
    action->setEnabled(redo ? stack->canRedo() : stack->canUndo());
    if (redo) {
        QObject::connect(action, &QAction::triggered, stack, &QUndoStack::redo);
        QObject::connect(stack, &QUndoStack::canRedoChanged, action, &QAction::setEnabled);
        QObject::connect(stack, &QUndoStack::redoTextChanged, action, describe);
    } else {
        QObject::connect(action, &QAction::triggered, stack, &QUndoStack::undo);
        QObject::connect(stack, &QUndoStack::canUndoChanged, action, &QAction::setEnabled);
        QObject::connect(stack, &QUndoStack::undoTextChanged, action, describe);
    }
    owner->addAction(action);
    return action;
}

} // namespace

QAction *UndoActions::undo(QUndoStack *stack, QWidget *owner)
{
    return makeAction(stack, owner, false);
}

QAction *UndoActions::redo(QUndoStack *stack, QWidget *owner)
{
    return makeAction(stack, owner, true);
}

} // namespace semhap
