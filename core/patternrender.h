// SPDX-License-Identifier: MIT
#pragma once

#include "devicemodel.h"
#include "pattern.h"
#include "player.h"

#include <QString>
#include <QStringList>

#include <limits>
#include <vector>

namespace semhap {

/**
 * Which device channel each of a pattern's tracks drives on `model`: a route per (track,
 * channel). `channels`, when not empty, replaces the single track's channel list (router
 * pattern nodes remap this way). False with `reason` when a channel is not the model's.
 */
bool resolvePatternRoutes(const Pattern &pattern, const DeviceModel &model,
                          const QStringList &channels, std::vector<PlayerInput::Route> *routes,
                          QString *reason);

class Voice;

/**
 * One frame of a playing voice on `model`: each channel the largest value of the tracks
 * routed to it (0 when none is), clamped to the channel's limits. `values` holds
 * `model.channelCount()` doubles.
 */
void mixVoice(const Voice &voice, const std::vector<PlayerInput::Route> &routes,
              const DeviceModel &model, double *values);

/** How to render a pattern offline (the `render` command, the designer's preview). */
struct RenderOptions
{
    double intensity = 1.0;
    double releaseAt = std::numeric_limits<double>::infinity(); ///< time of the end, s
    double duration = 1.0;                                      ///< s
    double rate = 1000.0;                                       ///< samples per second
};

/** A rendered pattern: sample times and one column of values per model channel. */
struct RenderedPattern
{
    QStringList channels;
    std::vector<double> t;
    std::vector<std::vector<double>> values; ///< values[channel][sample]
};

/**
 * Plays `pattern` from a begin at t = 0 (and an end at releaseAt) and samples it at
 * t = k / rate for k = 0 … round(duration · rate) − 1, clamped to the model's limits; where
 * several tracks drive one channel, the largest value wins.
 */
bool renderPattern(const PatternPtr &pattern, const DeviceModel &model,
                   const RenderOptions &options, RenderedPattern *result, QString *reason);
/** As renderPattern, through `routes` resolved already (a router's pattern node's). */
void renderRoutedPattern(const PatternPtr &pattern, const std::vector<PlayerInput::Route> &routes,
                         const DeviceModel &model, const RenderOptions &options,
                         RenderedPattern *result);

} // namespace semhap
