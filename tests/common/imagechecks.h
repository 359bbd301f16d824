// SPDX-License-Identifier: MIT
#pragma once

#include <QColor>
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

/**
 * Whether a rendered image is exposed so that its surfaces keep their shading: at most
 * 0.5 % of its pixels burnt to white (every channel 250 or more). A highlight, an
 * overlay's text are white; a surface burnt white by the lights or a reflection, where
 * nothing is left to see, is more than that (0.5 % is a patch of 70 × 70 px at 1280 × 800).
 * `why` says how much is burnt otherwise.
 */
inline bool looksExposed(const QImage &image, QString *why)
{
    qint64 burnt = 0;
    qint64 all = 0;
    for (int y = 0; y < image.height(); y += 2) {
        for (int x = 0; x < image.width(); x += 2) {
            const QRgb pixel = image.pixel(x, y);
            burnt += qRed(pixel) >= 250 && qGreen(pixel) >= 250 && qBlue(pixel) >= 250 ? 1 : 0;
            ++all;
        }
    }
    const double share = all > 0 ? double(burnt) / double(all) : 0.0;
    *why = QStringLiteral("%1 % of the pixels are burnt to white").arg(100.0 * share, 0, 'f', 2);
    return share <= 0.005;
}

/** How many pixels of `image` show a free wrist target's ghost (SceneRenderer's cyan). */
inline int ghostPixels(const QImage &image)
{
    int count = 0;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            const QColor c = image.pixelColor(x, y);
            count += c.blue() > 150 && c.green() > 120 && c.red() < c.green() - 40 ? 1 : 0;
        }
    }
    return count;
}
