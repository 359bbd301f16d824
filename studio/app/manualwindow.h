// SPDX-License-Identifier: MIT
#pragma once

#include <QDialog>
#include <QUrl>

class QLabel;
class QLineEdit;
class QTextBrowser;

namespace semhap {

/**
 * Help → Documentation: the studio's manual (Markdown, as installed) read inside the
 * studio, so it opens where no program opens `.md` files. Links to the other pages open
 * here too, with Back and Forward; web links go to the desktop's browser; the search field
 * finds the next match as you type (Enter: the next one, wrapping round). Not modal: the
 * run and the driving go on beside it.
 */
class ManualWindow : public QDialog
{
    Q_OBJECT

public:
    /** Over `window`, showing the page at `url` (a local file). */
    ManualWindow(QWidget *window, const QUrl &url);

    QTextBrowser *browser() const { return m_browser; }
    QLineEdit *searchField() const { return m_search; }
    /** Finds `text` after the selection, wrapping round to the top; false when absent. */
    bool find(const QString &text);

private:
    QTextBrowser *m_browser = nullptr;
    QLineEdit *m_search = nullptr;
    QLabel *m_found = nullptr;
};

} // namespace semhap
