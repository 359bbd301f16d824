// SPDX-License-Identifier: MIT
#pragma once

#include <QIcon>

#include <functional>

class QPainter;

namespace semhap {

/** A 32×32 icon of filled shapes (no outlines) that `draw` paints. */
QIcon drawnIcon(const std::function<void(QPainter &)> &draw);

} // namespace semhap
