// SPDX-License-Identifier: MIT
#pragma once

#include <QAbstractButton>
#include <QAbstractScrollArea>
#include <QAbstractSpinBox>
#include <QColor>
#include <QComboBox>
#include <QCoreApplication>
#include <QDockWidget>
#include <QEvent>
#include <QImage>
#include <QLabel>
#include <QLineEdit>
#include <QStringList>
#include <QStyle>
#include <QStyleOptionComboBox>
#include <QStyleOptionFrame>
#include <QTabBar>
#include <QTest>
#include <QTreeView>
#include <QWidget>

#include <algorithm>
#include <cstdlib>

/** Where a widget sits, by the object names of it and its ancestors: `plotsDock/…/label`. */
inline QString widgetPath(const QWidget *widget)
{
    QStringList names;
    for (const QObject *o = widget; o; o = o->parent()) {
        if (!o->objectName().isEmpty() && !o->objectName().startsWith(QLatin1String("qt_")))
            names.prepend(o->objectName());
    }
    return names.join(QLatin1Char('/'));
}

/**
 * The part of `widget` its ancestors up to `root` show, in its own coordinates. A scroll
 * area's viewport cuts only sideways: scrolling down to a field is fine, scrolling sideways
 * to read it is not.
 */
inline QRect shownPart(const QWidget *widget, const QWidget *root)
{
    QRect shown = widget->rect();
    QPoint offset;
    bool scrolls = false; // vertically, inside a scroll area
    for (const QWidget *w = widget; w && w != root && w->parentWidget(); w = w->parentWidget()) {
        const QWidget *parent = w->parentWidget();
        offset += w->pos();
        QRect room = parent->rect().translated(-offset);
        const auto *area = qobject_cast<const QAbstractScrollArea *>(parent->parentWidget());
        scrolls = scrolls || (area && area->viewport() == parent);
        if (scrolls) {
            room.setTop(shown.top());
            room.setBottom(shown.bottom());
        }
        shown &= room;
    }
    return shown;
}

/**
 * The texts and fields a user cannot read whole, as `class path 'text' (needs W px, has H
 * px)`: visible labels (not word-wrapped, not eliding rich text) and buttons whose text is
 * wider than the room they have; line edits whose text or placeholder, combo boxes and spin
 * boxes whose current text does not fit; the cells of tree views' rows in view that are
 * elided; and any of them what holds it cuts (a scroll area only sideways). Screenshot
 * tests fail on them, in every language.
 */
/**
 * Whether `widget` shows when `root` does: visible to it, and not in a dock behind another
 * dock's tab (such a dock is moved out of the window, keeping a size it does not show).
 */
inline bool showsIn(const QWidget *widget, const QWidget *root)
{
    if (!widget->isVisibleTo(root))
        return false;
    for (const QWidget *w = widget; w && w != root; w = w->parentWidget()) {
        if (qobject_cast<const QDockWidget *>(w) && w->parentWidget() &&
            !w->parentWidget()->rect().intersects(w->geometry()))
            return false;
    }
    return true;
}

inline QStringList clippedTexts(const QWidget *root)
{
    // A label whose text just changed is laid out on the next pass: let it.
    QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
    QStringList clipped;
    const auto report = [&](const QWidget *widget, const QString &text, int needed, int room) {
        clipped.append(QStringLiteral("%1 %2 '%3' (needs %4 px, has %5 px)")
                           .arg(QString::fromLatin1(widget->metaObject()->className()),
                                widgetPath(widget), text)
                           .arg(needed)
                           .arg(room));
    };
    const auto check = [&](const QWidget *widget, const QString &text, int room) {
        const QString plain = QString(text).remove(QLatin1Char('&'));
        const int needed = widget->fontMetrics().horizontalAdvance(plain);
        if (!plain.isEmpty() && needed > room)
            report(widget, plain, needed, room);
    };
    const auto cut = [&](const QWidget *widget, const QString &text) {
        const QRect shown = shownPart(widget, root);
        if (shown != widget->rect())
            report(widget, text + QStringLiteral(" [cut by what holds it]"), widget->width(),
                   shown.width());
    };
    for (const QLabel *label : root->findChildren<QLabel *>()) {
        if (!showsIn(label, root))
            continue;
        cut(label, label->text());
        if (label->wordWrap() || label->text().contains('<') || label->text().contains('\n') ||
            !label->pixmap().isNull())
            continue;
        check(label, label->text(), label->contentsRect().width() - 2 * label->margin());
    }
    for (const QAbstractButton *button : root->findChildren<QAbstractButton *>()) {
        if (!showsIn(button, root) || button->text().isEmpty())
            continue;
        cut(button, button->text());
        // A button's own padding and icon take room: its size hint is what the style asks
        // for the whole text; less than that is a cut.
        const int needed = button->sizeHint().width();
        if (button->width() < needed - 1 && !qobject_cast<const QTabBar *>(button->parent()))
            report(button, button->text(), needed, button->width());
    }
    for (const QLineEdit *edit : root->findChildren<QLineEdit *>()) {
        // A combo box's or spin box's editor is checked with it.
        if (!showsIn(edit, root) || qobject_cast<const QComboBox *>(edit->parentWidget()) ||
            qobject_cast<const QAbstractSpinBox *>(edit->parentWidget()))
            continue;
        cut(edit, edit->text());
        // The room for text: the field less its frame and margins, as the style draws it.
        QStyleOptionFrame option;
        option.initFrom(edit);
        option.rect = edit->rect();
        option.lineWidth =
            edit->hasFrame()
                ? edit->style()->pixelMetric(QStyle::PM_DefaultFrameWidth, &option, edit)
                : 0;
        const QRect area =
            edit->style()->subElementRect(QStyle::SE_LineEditContents, &option, edit) -
            edit->textMargins();
        const int room = area.width() - 4; // QLineEdit's own horizontal margin, 2 px a side
        check(edit, edit->text().isEmpty() ? edit->placeholderText() : edit->text(), room);
    }
    for (const QComboBox *combo : root->findChildren<QComboBox *>()) {
        if (!showsIn(combo, root))
            continue;
        cut(combo, combo->currentText());
        QStyleOptionComboBox option;
        option.initFrom(combo);
        option.rect = combo->rect();
        option.editable = combo->isEditable();
        const QRect area = combo->style()->subControlRect(QStyle::CC_ComboBox, &option,
                                                          QStyle::SC_ComboBoxEditField, combo);
        const int icon =
            combo->itemIcon(combo->currentIndex()).isNull() ? 0 : combo->iconSize().width() + 4;
        check(combo, combo->currentText(), area.width() - icon - (combo->isEditable() ? 4 : 0));
    }
    for (const QAbstractSpinBox *spin : root->findChildren<QAbstractSpinBox *>()) {
        if (!showsIn(spin, root))
            continue;
        cut(spin, spin->text());
        // Its text is drawn by a line edit inside it, with QLineEdit's 2 px a side.
        if (const QLineEdit *edit = spin->findChild<QLineEdit *>())
            check(spin, spin->text(), edit->width() - 4);
    }
    for (const QTreeView *tree : root->findChildren<QTreeView *>()) {
        if (!showsIn(tree, root))
            continue;
        // Each row shown, each column: the delegate elides what its cell lacks room for
        // (the cell less the style's text margins, a focus frame's and a pixel a side).
        const int margins =
            2 * (tree->style()->pixelMetric(QStyle::PM_FocusFrameHMargin, nullptr, tree) + 1);
        const QAbstractItemModel *model = tree->model();
        for (QModelIndex row = tree->indexAt(QPoint(1, 1)); row.isValid();
             row = tree->indexBelow(row)) {
            for (int column = 0; column < model->columnCount(row.parent()); ++column) {
                const QModelIndex cell = row.siblingAtColumn(column);
                const QString text = cell.data(Qt::DisplayRole).toString();
                if (tree->isColumnHidden(column) || text.isEmpty() ||
                    tree->isFirstColumnSpanned(row.row(), row.parent()))
                    continue;
                const QVariant font = cell.data(Qt::FontRole);
                const QFontMetrics metrics(font.isValid() ? font.value<QFont>() : tree->font());
                const int needed = metrics.horizontalAdvance(text);
                const int room = tree->visualRect(cell).width() - margins;
                if (needed > room)
                    report(tree, text, needed, room);
            }
        }
    }
    return clipped;
}

/** How many pixels of `image` are within `tolerance` (per channel) of `colour`. */
inline int pixelsOfColour(const QImage &image, const QColor &colour, int tolerance = 24)
{
    int count = 0;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            const QColor pixel = image.pixelColor(x, y);
            if (std::abs(pixel.red() - colour.red()) <= tolerance &&
                std::abs(pixel.green() - colour.green()) <= tolerance &&
                std::abs(pixel.blue() - colour.blue()) <= tolerance)
                ++count;
        }
    }
    return count;
}

/** Picks `text` in a combo box (editable too) with the arrow keys, as a user would. */
inline bool choose(QComboBox *box, const QString &text)
{
    box->setFocus();
    for (const Qt::Key key : {Qt::Key_Up, Qt::Key_Down}) {
        for (int i = 0; i <= box->count(); ++i) {
            if (box->currentText() == text)
                return true;
            QTest::keyClick(box, key);
        }
    }
    return box->currentText() == text;
}
