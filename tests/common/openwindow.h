// SPDX-License-Identifier: MIT
#pragma once

#include <QTest>
#include <QWidget>

/** Shows a window and makes it active: shortcuts go to the active window only. */
inline bool openWindow(QWidget &window)
{
    window.show();
    if (!QTest::qWaitForWindowExposed(&window))
        return false;
    window.activateWindow();
    return QTest::qWaitForWindowActive(&window);
}
