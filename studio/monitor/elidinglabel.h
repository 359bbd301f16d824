// SPDX-License-Identifier: MIT
#pragma once

#include <QLabel>

namespace semhap {

/**
 * A one-line label that gives up room when its bar is short: it cuts its text at the left
 * (the words that matter end a line such as "Showing: re-routed through C1") with an
 * ellipsis and keeps the whole text in its tooltip.
 */
class ElidingLabel : public QLabel
{
    Q_OBJECT

public:
    explicit ElidingLabel(QWidget *parent = nullptr);

    /** Sets the text the label shows whole when it has the room. */
    void setFullText(const QString &text);
    /** The text the label shows whole when it has the room. */
    QString fullText() const { return m_fullText; }

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

protected:
    void resizeEvent(QResizeEvent *event) override;

private:
    void elide();

    QString m_fullText;
};

} // namespace semhap
