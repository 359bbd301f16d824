// SPDX-License-Identifier: MIT
#pragma once

#include <QListWidget>

namespace semhap {

/**
 * The router editor's palette: an entry per node type of the table, with its description
 * and its kind's colour, dragged onto the canvas as the type's name. Two columns of whole
 * names, whatever the height.
 */
class RouterPalette : public QListWidget
{
    Q_OBJECT

public:
    explicit RouterPalette(QWidget *parent = nullptr);

protected:
    QStringList mimeTypes() const override;
    QMimeData *mimeData(const QList<QListWidgetItem *> &items) const override;
};

} // namespace semhap
