// SPDX-License-Identifier: MIT
#pragma once

#include <QDialog>

class QMainWindow;
class QTreeWidget;

namespace semhap {

/**
 * Help → Key map: every shortcut of a window's actions, grouped by where it works (anywhere
 * in the window, in the viewport, in each dock), and the viewport's drive keys from
 * HandDrive::keyTable(). Read from the live actions and the drive's table when it opens, so
 * it never disagrees with them. Not modal: the run and the driving go on beside it.
 */
class KeyMapDialog : public QDialog
{
    Q_OBJECT

public:
    explicit KeyMapDialog(QMainWindow *window);

    /** The map: a top-level item per group, a child per key row (keys, what they do). */
    QTreeWidget *tree() const { return m_tree; }

private:
    QTreeWidget *m_tree = nullptr;
};

} // namespace semhap
