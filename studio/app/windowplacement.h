// SPDX-License-Identifier: MIT
#pragma once

#include <QMargins>
#include <QObject>
#include <QRect>

class QWidget;

namespace semhap {

/**
 * Keeps a top-level window where all of it can be seen: inside its screen's available area
 * (the screen without panels and docks), title bar and frame included. A window manager
 * frames a window only once it is shown, so the window is placed with an expected frame
 * first and again once it is first exposed, with the real one.
 */
class WindowPlacement : public QObject
{
    Q_OBJECT

public:
    /** Watches `window` (also the parent): each time it is shown, it is kept on screen. */
    explicit WindowPlacement(QWidget *window);

    /**
     * The geometry (without frame) of a window opened without a saved or asked-for size on
     * a screen whose available area is `available`, the window manager's frame around it
     * being `frame`: all of the area on a laptop's screen, most of it, centred, on a large
     * one.
     */
    static QRect defaultGeometry(const QRect &available, const QMargins &frame);
    /** The frame a window manager will likely put around a window not yet shown. */
    static QMargins expectedFrame();
    /**
     * The geometry (without frame) of a window of `size` opened over `parent`: centred on
     * it, shrunk and moved so that it lies inside the parent's screen's available area with
     * the expected frame.
     */
    static QRect centredOver(const QWidget *parent, const QSize &size);
    /** The default geometry on `window`'s screen, for a window not yet shown. */
    static QRect defaultGeometry(const QWidget *window);
    /**
     * Shrinks and moves the shown `window` so that its frame lies inside its screen's
     * available area (a geometry saved on a larger screen, a frame larger than expected);
     * whether it had to.
     */
    static bool keepOnScreen(QWidget *window);

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    /** Once framed: the default geometry again with the real frame, else kept on screen. */
    void place();

    QWidget *m_window;
};

} // namespace semhap
