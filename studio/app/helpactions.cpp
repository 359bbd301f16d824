// SPDX-License-Identifier: MIT
#include "helpactions.h"

#include "keymapdialog.h"
#include "manualwindow.h"
#include "studio.h"

#include <QAction>
#include <QMainWindow>
#include <QMenu>

namespace semhap {

HelpActions::HelpActions(QMainWindow *window, QMenu *help) : QObject(window), m_window(window)
{
    auto *keyMap = new QAction(tr("Key map"), window);
    keyMap->setObjectName(QStringLiteral("keyMapAction"));
    keyMap->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Slash));
    keyMap->setToolTip(tr("Every shortcut and drive key of the window"));
    connect(keyMap, &QAction::triggered, this, &HelpActions::showKeyMap);
    auto *manual = new QAction(tr("Documentation"), window);
    manual->setObjectName(QStringLiteral("documentationAction"));
    manual->setShortcut(QKeySequence::HelpContents);
    manual->setToolTip(tr("Open the studio's manual"));
    connect(manual, &QAction::triggered, this, &HelpActions::showManual);
    for (QAction *action : {keyMap, manual}) {
        window->addAction(action);
        help->addAction(action);
    }
    help->addSeparator();
}

void HelpActions::showKeyMap()
{
    // One map at a time; it stays open beside the window while the user drives.
    auto *dialog = m_window->findChild<KeyMapDialog *>();
    if (!dialog) {
        dialog = new KeyMapDialog(m_window);
        dialog->setAttribute(Qt::WA_DeleteOnClose);
    }
    dialog->show();
    dialog->raise();
    dialog->activateWindow();
}

void HelpActions::showManual()
{
    const QUrl url = Studio::manualUrl();
    if (url.isEmpty()) {
        emit problem(tr("The manual is not installed"),
                     tr("Read docs/studio.md in semhap's sources."));
        return;
    }
    // Read here: a desktop without a program for .md files opened nothing.
    auto *window = m_window->findChild<ManualWindow *>();
    if (!window) {
        window = new ManualWindow(m_window, url);
        window->setAttribute(Qt::WA_DeleteOnClose);
    }
    window->show();
    window->raise();
    window->activateWindow();
}

} // namespace semhap
