// SPDX-License-Identifier: MIT
#include "elidinglabel.h"

#include <QLayout>

#include <algorithm>

namespace semhap {

namespace {

/** What the label keeps at its narrowest: an ellipsis and a few letters of its end. */
const QString Narrowest = QStringLiteral("…xxxxxxxx");

} // namespace

ElidingLabel::ElidingLabel(QWidget *parent) : QLabel(parent) {}

void ElidingLabel::setFullText(const QString &text)
{
    m_fullText = text;
    updateGeometry(); // its size hint is the whole text's
    // Laid out now, not on the next pass, so that the text is cut only when the bar has no
    // room for it (text() is what a reader of the label gets, at once).
    if (QWidget *holder = parentWidget(); holder && holder->layout())
        holder->layout()->activate();
    elide();
}

QSize ElidingLabel::sizeHint() const
{
    const QMargins margins = contentsMargins();
    return {fontMetrics().horizontalAdvance(m_fullText) + 2 * margin() + margins.left() +
                margins.right(),
            QLabel::sizeHint().height()};
}

QSize ElidingLabel::minimumSizeHint() const
{
    const QSize whole = sizeHint();
    return {std::min(whole.width(), fontMetrics().horizontalAdvance(Narrowest)), whole.height()};
}

void ElidingLabel::resizeEvent(QResizeEvent *event)
{
    QLabel::resizeEvent(event);
    elide();
}

void ElidingLabel::elide()
{
    const int room = contentsRect().width() - 2 * margin();
    // Measured as sizeHint() measures: elidedText() rounds differently and cut a pixel short.
    const QString shown = fontMetrics().horizontalAdvance(m_fullText) <= room
                              ? m_fullText
                              : fontMetrics().elidedText(m_fullText, Qt::ElideLeft, room);
    setText(shown);
    setToolTip(shown == m_fullText ? QString() : m_fullText);
}

} // namespace semhap
