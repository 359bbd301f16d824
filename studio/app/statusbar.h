// SPDX-License-Identifier: MIT
#pragma once

#include <QStatusBar>

namespace semhap {

/**
 * The window's status bar: a message that does not fit beside the permanent readouts ends in
 * "…" a space before them, and its tooltip is the whole message. QStatusBar cut it off
 * mid-letter against the first readout, so the two ran into each other.
 */
class StatusBar : public QStatusBar
{
    Q_OBJECT

public:
    explicit StatusBar(QWidget *parent = nullptr);

    /** Where the message is drawn: from the left edge to a space before the first readout. */
    QRect messageRect() const;
    /** The message as drawn: elided to messageRect(); empty without a message. */
    QString shownMessage() const;

protected:
    bool event(QEvent *event) override;
    void paintEvent(QPaintEvent *event) override;
};

} // namespace semhap
