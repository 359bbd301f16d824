// SPDX-License-Identifier: MIT
#include "patternrender.h"

#include "voice.h"

#include <algorithm>
#include <cmath>

namespace semhap {

bool resolvePatternRoutes(const Pattern &pattern, const DeviceModel &model,
                          const QStringList &channels, std::vector<PlayerInput::Route> *routes,
                          QString *reason)
{
    if (pattern.model() != model.name()) {
        *reason = QStringLiteral("pattern '%1' is for model %2, not %3")
                      .arg(pattern.name(), pattern.model(), model.name());
        return false;
    }
    const auto &tracks = pattern.tracks();
    if (!channels.isEmpty() && tracks.size() != 1) {
        *reason = QStringLiteral("channels can only be remapped for a pattern with one track; "
                                 "'%1' has %2")
                      .arg(pattern.name())
                      .arg(tracks.size());
        return false;
    }
    routes->clear();
    for (size_t track = 0; track < tracks.size(); ++track) {
        QStringList names = channels.isEmpty() ? tracks[track].channels : channels;
        if (names == QStringList{QStringLiteral("*")})
            names = model.channelNames();
        for (const QString &name : names) {
            const int channel = model.channelIndex(name);
            if (channel < 0) {
                *reason = QStringLiteral("pattern '%1' drives channel '%2', which model %3 does "
                                         "not have (channels: %4)")
                              .arg(pattern.name(), name, model.name(),
                                   model.channelNames().join(QStringLiteral(", ")));
                return false;
            }
            routes->push_back({channel, int(track)});
        }
    }
    return true;
}

void mixVoice(const Voice &voice, const std::vector<PlayerInput::Route> &routes,
              const DeviceModel &model, double *values)
{
    std::fill(values, values + model.channelCount(), -std::numeric_limits<double>::infinity());
    for (const PlayerInput::Route &route : routes)
        values[route.channel] = std::max(values[route.channel], voice.value(route.slot));
    for (int c = 0; c < model.channelCount(); ++c)
        values[c] = model.clamp(c, std::isinf(values[c]) ? 0.0 : values[c]);
}

bool renderPattern(const PatternPtr &pattern, const DeviceModel &model,
                   const RenderOptions &options, RenderedPattern *result, QString *reason)
{
    std::vector<PlayerInput::Route> routes;
    if (!resolvePatternRoutes(*pattern, model, {}, &routes, reason))
        return false;
    renderRoutedPattern(pattern, routes, model, options, result);
    return true;
}

void renderRoutedPattern(const PatternPtr &pattern, const std::vector<PlayerInput::Route> &routes,
                         const DeviceModel &model, const RenderOptions &options,
                         RenderedPattern *result)
{
    const auto samples = size_t(std::max(0.0, std::round(options.duration * options.rate)));
    result->channels = model.channelNames();
    result->t.resize(samples);
    result->values.assign(size_t(model.channelCount()), std::vector<double>(samples, 0.0));

    Voice voice(pattern);
    std::vector<double> frame(size_t(model.channelCount()));
    voice.setParam(ParamTable::Intensity, options.intensity, 0.0);
    voice.begin(0.0);
    bool released = false;
    for (size_t k = 0; k < samples; ++k) {
        const double t = double(k) / options.rate;
        if (!released && t >= options.releaseAt) {
            voice.end(options.releaseAt);
            released = true;
        }
        voice.advance(t);
        result->t[k] = t;
        mixVoice(voice, routes, model, frame.data());
        for (int c = 0; c < model.channelCount(); ++c)
            result->values[size_t(c)][k] = frame[size_t(c)];
    }
}

} // namespace semhap
