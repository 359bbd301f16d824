// SPDX-License-Identifier: MIT
#pragma once

#include <QString>

namespace semhap {

/**
 * How a feature's panel docks in the main window by default: the dock's name (the key of
 * the layout the window saves), its title, its side of the window, and the dock it sits
 * behind as a tab. Each panel gives its own (`PlotPanel::dock()` …); the window makes the
 * docks from them in its order, so where a panel goes is written once, with the panel.
 */
struct PanelDock
{
    /** A side of the window. */
    enum class Side
    {
        Right, ///< the full height right of the viewport
        Bottom ///< under the viewport
    };

    QString name;
    QString title;
    Side side = Side::Right;
    QString tabbedWith; ///< the dock this one is a tab behind; empty: a place of its own
};

} // namespace semhap
