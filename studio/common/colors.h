// SPDX-License-Identifier: MIT
#pragma once

#include "semanticevent.h"

#include <QColor>
#include <QString>

namespace semhap {

/**
 * The studio's colours in one place. The hues are the Okabe–Ito palette, which people with
 * the common colour-vision deficiencies tell apart; each meaning has one colour everywhere,
 * so a confirmation is the same blue in the plots, the log, the router editor and the
 * designer.
 */
namespace colors {

// The hues.
inline const QColor Blue{0x00, 0x72, 0xB2};
inline const QColor Orange{0xE6, 0x9F, 0x00};
inline const QColor Vermillion{0xD5, 0x5E, 0x00};
inline const QColor Green{0x00, 0x9E, 0x73};
inline const QColor Sky{0x56, 0xB4, 0xE9};
inline const QColor Purple{0xCC, 0x79, 0xA7};
inline const QColor Yellow{0xF0, 0xE4, 0x42};
inline const QColor Black{0x00, 0x00, 0x00};

// What they mean.
inline const QColor &Confirmation = Blue; ///< confirmations, a selection, what was commanded
inline const QColor &Exception = Orange;  ///< exceptions, a field that needs attention
inline const QColor &Error = Vermillion;  ///< errors, recording, stop-all, slip, predictions
inline const QColor &Ok = Green;          ///< connected, valid
inline const QColor &Activity = Yellow;   ///< something passing now, connecting
inline const QColor &Level = Sky;         ///< level meters
/** The colour of a message of `category`. */
QColor category(Category category);
/** How many colours series() has before it repeats. */
constexpr int SeriesCount = 8;
/** The `index`th colour of a plot's series (the channels of one device), repeating. */
QColor series(int index);
/** Error pressed, and error disabled (a button's states). */
inline const QColor ErrorDark{0xA0, 0x46, 0x00};
inline const QColor ErrorPale{0xE8, 0xB7, 0x9A};
/** The ground of a note about a confirmation (blue) or an exception (orange). */
inline const QColor ConfirmationWash{0xE3, 0xF0, 0xFA};
inline const QColor ExceptionWash{0xFF, 0xF3, 0xD6};

// Neutrals on light ground.
inline const QColor Text{0x33, 0x33, 0x33};
inline const QColor StrongText{0x22, 0x22, 0x22};
inline const QColor MutedText{0x55, 0x55, 0x55}; ///< secondary text, markers, outlines
inline const QColor Border{0xAA, 0xAA, 0xAA};
inline const QColor Inactive{0xDD, 0xDD, 0xDD}; ///< something not bound or not there
inline const QColor Canvas{0xF2, 0xF2, 0xF2};   ///< the router editor's ground
inline const QColor Card{0xFA, 0xFA, 0xFA};     ///< a node's face
/** White at `alpha` (0–255): the ground of legends and labels over a plot. */
QColor veil(int alpha);

// The viewport: light on dark.
inline const QColor SceneGround{0x2B, 0x2F, 0x33};
inline const QColor OverlayGround{0x20, 0x22, 0x25, 200};
inline const QColor OverlayText{0xDD, 0xDD, 0xDD};
inline const QColor OverlayCaption{0xE8, 0xE8, 0xE8};

/** `color` as `#RRGGBB`, for style sheets and rich text. */
QString css(const QColor &color);

} // namespace colors

} // namespace semhap
