// SPDX-License-Identifier: MIT
#include "drawnicon.h"

#include <QPainter>
#include <QPixmap>

namespace semhap {

QIcon drawnIcon(const std::function<void(QPainter &)> &draw)
{
    QPixmap pixmap(32, 32);
    pixmap.fill(Qt::transparent);
    {
        QPainter painter(&pixmap);
        painter.setRenderHint(QPainter::Antialiasing);
        painter.setPen(Qt::NoPen);
        draw(painter);
    }
    return QIcon(pixmap);
}

} // namespace semhap
