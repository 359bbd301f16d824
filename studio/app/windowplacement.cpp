// SPDX-License-Identifier: MIT
#include "windowplacement.h"

#include <QEvent>
#include <QScreen>
#include <QTimer>
#include <QWidget>
#include <QWindow>

#include <algorithm>

namespace semhap {

namespace {

// Up to this room (a laptop's 1280×800, 1366×768, 1440×900, 1536×864) the window takes all
// of it: every pixel counts there. Beyond, it leaves a margin around itself.
constexpr int RoomyWidth = 1600;
constexpr int RoomyHeight = 1000;

int share(int room, int roomy)
{
    return room < roomy ? room : room * 9 / 10;
}

/** The frame around a shown window (zero until the window manager has framed it). */
QMargins frameOf(const QWidget *window)
{
    const QRect frame = window->frameGeometry();
    const QRect inner = window->geometry();
    return QMargins(inner.left() - frame.left(), inner.top() - frame.top(),
                    frame.right() - inner.right(), frame.bottom() - inner.bottom());
}

} // namespace

WindowPlacement::WindowPlacement(QWidget *window) : QObject(window), m_window(window)
{
    window->installEventFilter(this);
}

QRect WindowPlacement::defaultGeometry(const QRect &available, const QMargins &frame)
{
    const QRect room = available.marginsRemoved(frame);
    QRect geometry(0, 0, share(room.width(), RoomyWidth), share(room.height(), RoomyHeight));
    geometry.moveCenter(room.center());
    return geometry;
}

QMargins WindowPlacement::expectedFrame()
{
    // X11 window managers draw title bars of 20–40 px and borders of a few pixels.
    return QMargins(4, 40, 4, 4);
}

QRect WindowPlacement::defaultGeometry(const QWidget *window)
{
    return defaultGeometry(window->screen()->availableGeometry(), expectedFrame());
}

QRect WindowPlacement::centredOver(const QWidget *parent, const QSize &size)
{
    const QRect room = parent->screen()->availableGeometry().marginsRemoved(expectedFrame());
    QRect geometry(QPoint(), size.boundedTo(room.size()));
    geometry.moveCenter(parent->geometry().center());
    geometry.moveRight(std::min(geometry.right(), room.right()));
    geometry.moveBottom(std::min(geometry.bottom(), room.bottom()));
    geometry.moveLeft(std::max(geometry.left(), room.left()));
    geometry.moveTop(std::max(geometry.top(), room.top()));
    return geometry;
}

bool WindowPlacement::keepOnScreen(QWidget *window)
{
    const QScreen *screen = window->screen();
    if (!screen || window->isMaximized() || window->isFullScreen())
        return false;
    const QRect available = screen->availableGeometry();
    if (available.contains(window->frameGeometry()))
        return false;
    const QRect room = available.marginsRemoved(frameOf(window));
    QRect geometry = window->geometry();
    geometry.setSize(geometry.size().boundedTo(room.size()).expandedTo(window->minimumSize()));
    if (geometry.right() > room.right())
        geometry.moveRight(room.right());
    if (geometry.bottom() > room.bottom())
        geometry.moveBottom(room.bottom());
    if (geometry.left() < room.left())
        geometry.moveLeft(room.left());
    if (geometry.top() < room.top())
        geometry.moveTop(room.top());
    window->setGeometry(geometry);
    return true;
}

bool WindowPlacement::eventFilter(QObject *watched, QEvent *event)
{
    // The window manager frames the window between its showing and its first exposure.
    if (watched == m_window && event->type() == QEvent::Show && m_window->windowHandle()) {
        m_window->windowHandle()->installEventFilter(this);
    } else if (watched == m_window->windowHandle() && event->type() == QEvent::Expose &&
               m_window->windowHandle()->isExposed()) {
        watched->removeEventFilter(this);
        QTimer::singleShot(0, this, &WindowPlacement::place);
    }
    return QObject::eventFilter(watched, event);
}

void WindowPlacement::place()
{
    if (m_window->isMaximized() || m_window->isFullScreen())
        return;
    // Still where it was put without a saved geometry: there again, with the real frame.
    if (m_window->geometry() == defaultGeometry(m_window)) {
        const QRect placed =
            defaultGeometry(m_window->screen()->availableGeometry(), frameOf(m_window));
        if (placed != m_window->geometry())
            m_window->setGeometry(placed);
        return;
    }
    keepOnScreen(m_window);
}

} // namespace semhap
