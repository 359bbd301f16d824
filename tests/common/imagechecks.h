// SPDX-License-Identifier: MIT
#pragma once

#include <QImage>
#include <QSet>
#include <QString>

/**
 * Whether a rendered image shows something: many colours (not a blank clear) and every
 * pixel opaque (MuJoCo leaves alpha at 0 unless the renderer fixes it). `why` says what
 * is wrong otherwise.
 */
inline bool looksDrawn(const QImage &image, QString *why)
{
    QSet<QRgb> colours;
    for (int y = 0; y < image.height(); y += 4) {
        for (int x = 0; x < image.width(); x += 4) {
            const QRgb pixel = image.pixel(x, y);
            if (qAlpha(pixel) != 255) {
                *why = QStringLiteral("pixel (%1, %2) is not opaque").arg(x).arg(y);
                return false;
            }
            colours.insert(pixel & 0xffffff);
        }
    }
    if (colours.size() <= 100) {
        *why = QStringLiteral("the image is (nearly) uniform: nothing was drawn");
        return false;
    }
    return true;
}
