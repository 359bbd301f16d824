// SPDX-License-Identifier: MIT
#include "routerpalette.h"

#include "routernodeitem.h"
#include "routernodetype.h"
#include "routerscene.h"

#include <QMimeData>

#include <algorithm>

namespace semhap {

RouterPalette::RouterPalette(QWidget *parent) : QListWidget(parent)
{
    setObjectName(QStringLiteral("routerPalette"));
    setDragEnabled(true);
    setDragDropMode(DragOnly);
    setSelectionMode(SingleSelection);
    // Columns of entries: the types fit in a short strip beside the inspector.
    setFlow(TopToBottom);
    setWrapping(true);
    setResizeMode(Adjust);
    setSpacing(1);
    for (const RouterNodeType &type : routerNodeTypes()) {
        auto *item = new QListWidgetItem(type.type, this);
        item->setData(Qt::UserRole, type.type);
        item->setToolTip(type.description);
        QPixmap swatch(12, 12);
        swatch.fill(RouterNodeItem::kindColor(type.type));
        item->setIcon(QIcon(swatch));
    }
    setToolTip(tr("Drag a node type onto the canvas, or double-click it"));
    // Two columns of whole names, whatever the height: the splitter keeps it this wide.
    int widest = 0;
    for (int row = 0; row < count(); ++row)
        widest = std::max(widest, fontMetrics().horizontalAdvance(item(row)->text()));
    const int entry = widest + iconSize().width() + 24; // icon, gaps, spacing
    setMinimumWidth(2 * entry + 2 * frameWidth());
}

QStringList RouterPalette::mimeTypes() const
{
    return {QLatin1String(RouterScene::NodeTypeMime)};
}

QMimeData *RouterPalette::mimeData(const QList<QListWidgetItem *> &items) const
{
    if (items.isEmpty())
        return nullptr;
    auto *mime = new QMimeData;
    mime->setData(QLatin1String(RouterScene::NodeTypeMime),
                  items.front()->data(Qt::UserRole).toString().toUtf8());
    return mime;
}

} // namespace semhap
