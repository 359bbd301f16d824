// SPDX-License-Identifier: MIT
#pragma once

#include <QAbstractButton>
#include <QColor>
#include <QComboBox>
#include <QCoreApplication>
#include <QDockWidget>
#include <QEvent>
#include <QImage>
#include <QLabel>
#include <QStringList>
#include <QTabBar>
#include <QTest>
#include <QWidget>

#include <cstdlib>

/**
 * The texts a user cannot read whole: visible labels (not word-wrapped, not eliding rich
 * text) and buttons whose text is wider than the room they have, as `class 'text' (needs
 * W px, has H px)`. Screenshot tests fail on them, in every language.
 */
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
    const auto check = [&](const QWidget *widget, const QString &text, int room) {
        const QString plain = QString(text).remove(QLatin1Char('&'));
        const int needed = widget->fontMetrics().horizontalAdvance(plain);
        if (!plain.isEmpty() && needed > room)
            clipped.append(QStringLiteral("%1 %2 '%3' (needs %4 px, has %5 px)")
                               .arg(QString::fromLatin1(widget->metaObject()->className()),
                                    widgetPath(widget), plain)
                               .arg(needed)
                               .arg(room));
    };
    for (const QLabel *label : root->findChildren<QLabel *>()) {
        if (!showsIn(label, root) || label->wordWrap() || label->text().contains('<') ||
            label->text().contains('\n') || !label->pixmap().isNull())
            continue;
        check(label, label->text(), label->contentsRect().width() - 2 * label->margin());
    }
    for (const QAbstractButton *button : root->findChildren<QAbstractButton *>()) {
        if (!showsIn(button, root) || button->text().isEmpty())
            continue;
        // A button's own padding and icon take room: its size hint is what the style asks
        // for the whole text; less than that is a cut.
        const int needed = button->sizeHint().width();
        if (button->width() < needed - 1 && !qobject_cast<const QTabBar *>(button->parent()))
            clipped.append(QStringLiteral("%1 %2 '%3' (needs %4 px, has %5 px)")
                               .arg(QString::fromLatin1(button->metaObject()->className()),
                                    widgetPath(button), button->text())
                               .arg(needed)
                               .arg(button->width()));
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
