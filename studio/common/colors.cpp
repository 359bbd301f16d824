// SPDX-License-Identifier: MIT
#include "colors.h"

namespace semhap::colors {

QColor category(Category category)
{
    return category == Category::Confirmation ? Confirmation : Exception;
}

QColor series(int index)
{
    static const QColor order[SeriesCount] = {Blue, Orange, Green, Vermillion,
                                              Sky,  Purple, Black, Yellow};
    return order[size_t(index) % SeriesCount];
}

QColor veil(int alpha)
{
    return QColor(255, 255, 255, alpha);
}

QString css(const QColor &color)
{
    return color.name(QColor::HexRgb).toUpper();
}

} // namespace semhap::colors
