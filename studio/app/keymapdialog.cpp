// SPDX-License-Identifier: MIT
#include "keymapdialog.h"

#include "handdrive.h"
#include "simviewport.h"
#include "windowplacement.h"

#include <QAction>
#include <QDialogButtonBox>
#include <QDockWidget>
#include <QHeaderView>
#include <QMainWindow>
#include <QMetaEnum>
#include <QScrollBar>
#include <QTreeWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <map>
#include <vector>

namespace semhap {

namespace {

/** A group of the map: its heading and its rows (keys, what they do). */
struct Group
{
    QString title;
    std::vector<std::pair<QString, QString>> rows;
};

/**
 * The keys shown for an action: a standard key's first binding stands for it, its other
 * bindings on this platform (Undo's F14, Copy's Ctrl+Ins) are left out.
 */
QList<QKeySequence> shownKeys(const QAction *action)
{
    QList<QKeySequence> keys = action->shortcuts();
    const QMetaEnum standard = QMetaEnum::fromType<QKeySequence::StandardKey>();
    for (int i = 0; i < standard.keyCount(); ++i) {
        const QList<QKeySequence> bindings =
            QKeySequence::keyBindings(QKeySequence::StandardKey(standard.value(i)));
        if (bindings.isEmpty() || !keys.contains(bindings.first()))
            continue;
        for (qsizetype b = 1; b < bindings.size(); ++b)
            keys.removeAll(bindings[b]);
    }
    return keys;
}

QString keysText(const QList<QKeySequence> &keys)
{
    QStringList texts;
    for (const QKeySequence &key : keys)
        texts.append(key.toString(QKeySequence::NativeText));
    return texts.join(QStringLiteral(", "));
}

/** The widget an action belongs to: the first widget among its owners. */
QWidget *ownerOf(const QAction *action)
{
    for (QObject *o = action->parent(); o; o = o->parent()) {
        if (auto *widget = qobject_cast<QWidget *>(o))
            return widget;
    }
    return nullptr;
}

} // namespace

KeyMapDialog::KeyMapDialog(QMainWindow *window) : QDialog(window)
{
    setObjectName(QStringLiteral("keyMapDialog"));
    setWindowTitle(tr("Key map"));

    // Groups in the order a reader looks: the window, the viewport, then each dock.
    QWidget *viewport = window->centralWidget();
    Group everywhere{tr("Anywhere in the window"), {}};
    Group inViewport{tr("In the viewport (click it first)"), {}};
    std::map<QDockWidget *, Group> inDocks;
    std::vector<QDockWidget *> dockOrder;
    for (QAction *action : window->findChildren<QAction *>()) {
        if (action->shortcuts().isEmpty())
            continue;
        QString text = action->iconText();
        if (text.endsWith(QChar(0x2026)))
            text.chop(1);
        const std::pair<QString, QString> row{keysText(shownKeys(action)), text};
        QWidget *owner = ownerOf(action);
        QDockWidget *dock = nullptr;
        for (QWidget *w = owner; w && !dock; w = w->parentWidget())
            dock = qobject_cast<QDockWidget *>(w);
        // A window's or the application's shortcut works anywhere, whoever owns it.
        const bool anywhere = action->shortcutContext() == Qt::WindowShortcut ||
                              action->shortcutContext() == Qt::ApplicationShortcut;
        if (anywhere) {
            everywhere.rows.push_back(row);
        } else if (owner && viewport && (owner == viewport || viewport->isAncestorOf(owner))) {
            inViewport.rows.push_back(row);
        } else if (dock) {
            if (!inDocks.count(dock)) {
                inDocks[dock].title = tr("In the %1 panel").arg(dock->windowTitle());
                dockOrder.push_back(dock);
            }
            inDocks[dock].rows.push_back(row);
        } else {
            everywhere.rows.push_back(row);
        }
    }
    if (auto *sim = qobject_cast<SimViewport *>(viewport)) {
        for (const auto &[key, what] : sim->ownKeys())
            inViewport.rows.emplace_back(keysText({key}), what);
    }
    // The drive keys, one row per thing they do, in the drive's own order.
    std::vector<DriveKeyAction> actions;
    std::map<DriveKeyAction, QList<QKeySequence>> keys;
    for (const DriveKey &entry : HandDrive::keyTable()) {
        if (!keys.count(entry.action))
            actions.push_back(entry.action);
        keys[entry.action].append(QKeySequence(entry.key));
    }
    for (DriveKeyAction action : actions)
        inViewport.rows.emplace_back(keysText(keys[action]), HandDrive::actionText(action));

    m_tree = new QTreeWidget(this);
    m_tree->setObjectName(QStringLiteral("keyMap"));
    m_tree->setColumnCount(2);
    m_tree->setHeaderLabels({tr("Keys"), tr("What they do")});
    m_tree->setRootIsDecorated(false);
    m_tree->setSelectionMode(QAbstractItemView::NoSelection);
    m_tree->header()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    std::vector<const Group *> groups{&everywhere, &inViewport};
    for (QDockWidget *dock : dockOrder)
        groups.push_back(&inDocks[dock]);
    for (const Group *group : groups) {
        auto *heading = new QTreeWidgetItem(m_tree, {group->title});
        heading->setFirstColumnSpanned(true);
        QFont bold = heading->font(0);
        bold.setBold(true);
        heading->setFont(0, bold);
        for (const auto &[keysText, what] : group->rows)
            new QTreeWidgetItem(heading, {keysText, what});
    }
    m_tree->expandAll();

    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::close);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_tree, 1);
    layout->addWidget(buttons);
    // Wide enough for the longest row in any language, as far as the screen allows.
    m_tree->resizeColumnToContents(1);
    const int wide = m_tree->columnWidth(0) + m_tree->columnWidth(1) +
                     m_tree->verticalScrollBar()->sizeHint().width() + 4 * m_tree->frameWidth() +
                     layout->contentsMargins().left() + layout->contentsMargins().right() + 16;
    // Over the window it maps, on its screen (a dialog left to the window manager opened
    // in a corner of another screen); kept there once framed.
    setGeometry(WindowPlacement::centredOver(window, QSize(std::max(560, wide), 720)));
    new WindowPlacement(this);
}

} // namespace semhap
