// SPDX-License-Identifier: MIT
#pragma once

#include <QObject>

class QMainWindow;
class QMenu;

namespace semhap {

/**
 * The Help menu's own actions, on the window so their shortcuts work anywhere in it: the key
 * map (Ctrl+/), a window that stays open beside the studio while the user drives, and the
 * manual (F1), read in a window of the studio's own.
 */
class HelpActions : public QObject
{
    Q_OBJECT

public:
    /** Adds the actions to `window` and, followed by a separator, to `help`. */
    HelpActions(QMainWindow *window, QMenu *help);

signals:
    /** The manual could not be shown: what failed and why. */
    void problem(const QString &what, const QString &error);

private:
    void showKeyMap();
    void showManual();

    QMainWindow *m_window;
};

} // namespace semhap
