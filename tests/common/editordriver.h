// SPDX-License-Identifier: MIT
#pragma once

#include "routereditor.h"
#include "routernodeitem.h"
#include "routerscene.h"

#include <QAbstractItemView>
#include <QComboBox>
#include <QCoreApplication>
#include <QGraphicsView>
#include <QLineEdit>
#include <QListWidget>
#include <QTest>

/**
 * Drives a router editor as a user does: palette double-clicks, clicks on nodes, typing
 * and picking in the inspector, wires dragged from port to port. What the editor's own
 * tests and the studio's walk-through share.
 */
class EditorDriver
{
public:
    explicit EditorDriver(semhap::RouterEditor *editor = nullptr) : m_editor(editor) {}
    void setEditor(semhap::RouterEditor *editor) { m_editor = editor; }

    QPoint at(const QPointF &scenePos) const { return m_editor->view()->mapFromScene(scenePos); }
    QWidget *canvas() const { return m_editor->view()->viewport(); }

    /** Double-clicks a node type in the palette; the new node's id. */
    QString addFromPalette(const QString &type)
    {
        QListWidget *palette = m_editor->palette();
        const QList<QListWidgetItem *> items = palette->findItems(type, Qt::MatchExactly);
        if (items.size() != 1)
            qFatal("no palette entry %s", qPrintable(type));
        palette->scrollToItem(items.front());
        const QPoint center = palette->visualItemRect(items.front()).center();
        // A double-click is a click and a second press within the interval.
        QTest::mouseClick(palette->viewport(), Qt::LeftButton, {}, center);
        QTest::mouseDClick(palette->viewport(), Qt::LeftButton, {}, center);
        settle();
        const QStringList selected = m_editor->scene()->selectedNodeIds();
        return selected.size() == 1 ? selected.front() : QString();
    }

    /** Clicks a node's title, which selects it and shows it in the inspector. */
    void select(const QString &id)
    {
        semhap::RouterNodeItem *item = m_editor->scene()->nodeItem(id);
        m_editor->view()->ensureVisible(item);
        QTest::mouseClick(canvas(), Qt::LeftButton, {}, at(item->mapToScene(QPointF(60, 10))));
        settle();
    }

    /** Types `text` into an inspector field and presses Return. */
    void type(const QString &field, const QString &text)
    {
        QWidget *widget = m_editor->inspector()->findChild<QWidget *>(field);
        if (!widget)
            qFatal("no inspector field %s", qPrintable(field));
        auto *combo = qobject_cast<QComboBox *>(widget);
        QWidget *target = combo && combo->isEditable() ? combo->lineEdit() : widget;
        target->setFocus();
        if (!combo || combo->isEditable())
            QTest::keyClick(target, Qt::Key_A, Qt::ControlModifier);
        QTest::keyClicks(target, text);
        if (!combo || combo->isEditable())
            QTest::keyClick(target, Qt::Key_Return);
        settle();
    }

    /** Opens an inspector combo's list and clicks the entry `text`; false without one. */
    bool pick(const QString &field, const QString &text)
    {
        auto *combo = m_editor->inspector()->findChild<QComboBox *>(field);
        if (!combo)
            qFatal("no inspector combo %s", qPrintable(field));
        // Opened first: what the list offers may be worked out as it opens.
        combo->showPopup();
        QAbstractItemView *list = combo->view();
        if (!QTest::qWaitForWindowExposed(list->window()))
            return false;
        const int row = combo->findText(text);
        if (row < 0) {
            combo->hidePopup();
            return false;
        }
        const QModelIndex index = list->model()->index(row, 0);
        list->scrollTo(index);
        QTest::mouseClick(list->viewport(), Qt::LeftButton, {}, list->visualRect(index).center());
        settle();
        return true;
    }

    /** Drags a wire from one port to another. */
    void drag(const QPointF &from, const QPointF &to)
    {
        const QPoint a = at(from);
        const QPoint b = at(to);
        QTest::mousePress(canvas(), Qt::LeftButton, {}, a);
        QTest::mouseMove(canvas(), (a + b) / 2);
        QTest::mouseMove(canvas(), b);
        QTest::mouseRelease(canvas(), Qt::LeftButton, {}, b);
        settle();
    }
    void wire(const QString &from, const QString &fromPort, const QString &to,
              const QString &toPort, bool toOutput = false)
    {
        semhap::RouterScene *scene = m_editor->scene();
        drag(scene->nodeItem(from)->portScenePos(fromPort, true),
             scene->nodeItem(to)->portScenePos(toPort, toOutput));
    }

    static void settle()
    {
        for (int i = 0; i < 3; ++i)
            QCoreApplication::processEvents();
    }

private:
    semhap::RouterEditor *m_editor;
};
