// SPDX-License-Identifier: MIT
#include "distinctiveness.h"

#include "patternrender.h"
#include "router.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace semhap {

namespace {

/** Below this share of the range a duty cycle is as short as it gets (log of 0). */
constexpr double ShortestDuty = 0.01;

/** |ln(a / b)| in units of a Weber fraction: how many JNDs apart two magnitudes are. */
double weberSteps(double a, double b, double weber)
{
    return std::abs(std::log(a / b)) / std::log1p(weber);
}

/**
 * The earth mover's distance between two distributions over points on a circle (degrees):
 * the least stimulation that has to move, times how far. The cumulative surplus F_k is
 * carried across each gap; a constant carried all the way round is free, so the best one
 * is the gaps-weighted median of F.
 */
double circularEarthMover(std::vector<std::pair<double, double>> surplus) // angle, p - q
{
    std::sort(surplus.begin(), surplus.end());
    const size_t n = surplus.size();
    if (n < 2)
        return 0.0;
    std::vector<std::pair<double, double>> carried(n); // F_k, the gap after point k
    double cumulative = 0.0;
    for (size_t k = 0; k < n; ++k) {
        cumulative += surplus[k].second;
        const double next = k + 1 < n ? surplus[k + 1].first : surplus[0].first + 360.0;
        carried[k] = {cumulative, next - surplus[k].first};
    }
    std::vector<std::pair<double, double>> sorted = carried;
    std::sort(sorted.begin(), sorted.end());
    const double total = std::accumulate(sorted.begin(), sorted.end(), 0.0,
                                         [](double sum, const auto &f) { return sum + f.second; });
    double median = sorted.back().first;
    double weight = 0.0;
    for (const auto &[f, gap] : sorted) {
        weight += gap;
        if (weight >= total / 2.0) {
            median = f;
            break;
        }
    }
    double moved = 0.0;
    for (const auto &[f, gap] : carried)
        moved += gap * std::abs(f - median);
    return moved;
}

/** False with the reason when `model` names no modality: its output cannot be compared. */
bool hasModality(const DeviceModel &model, QString *reason)
{
    if (!model.modality().isEmpty())
        return true;
    *reason = QStringLiteral("%1: the model names no modality (%2)")
                  .arg(model.name(), DeviceModel::modalities().join(QStringLiteral(", ")));
    return false;
}

} // namespace

double PerceptionConstants::detection(const QString &modality) const
{
    if (modality == QLatin1String("pressure"))
        return pressureDetection;
    if (modality == QLatin1String("sight"))
        return sightDetection;
    return vibrationDetection;
}

bool Distinctiveness::perceive(const PatternPtr &pattern, const DeviceModel &model,
                               double intensity, Percept *percept, QString *reason) const
{
    std::vector<PlayerInput::Route> routes;
    return hasModality(model, reason) &&
           resolvePatternRoutes(*pattern, model, {}, &routes, reason) &&
           perceive(pattern, routes, model, intensity, percept, reason);
}

bool Distinctiveness::perceive(const PatternPtr &pattern,
                               const std::vector<PlayerInput::Route> &routes,
                               const DeviceModel &model, double intensity, Percept *percept,
                               QString *reason) const
{
    if (!hasModality(model, reason))
        return false;
    RenderOptions options;
    options.intensity = intensity;
    options.duration = Window;
    options.rate = Rate;
    RenderedPattern rendered;
    renderRoutedPattern(pattern, routes, model, options, &rendered);

    // What the band delivers, each channel as a share of its range.
    const int channels = model.channelCount();
    const size_t samples = rendered.t.size();
    std::vector<std::vector<double>> delivered;
    delivered.resize(size_t(channels));
    std::vector<double> envelope(samples, 0.0);
    for (int c = 0; c < channels; ++c) {
        const ChannelSpec &spec = model.channels()[size_t(c)];
        delivered[size_t(c)] = model.predict(rendered.values[size_t(c)], Rate);
        for (size_t k = 0; k < samples; ++k) {
            double &v = delivered[size_t(c)][k];
            v = std::clamp((v - spec.min) / (spec.max - spec.min), 0.0, 1.0);
            envelope[k] = std::max(envelope[k], v);
        }
    }

    *percept = Percept();
    percept->modality = model.modality();
    for (const ChannelSpec &spec : model.channels())
        percept->angle.push_back(spec.angle);
    percept->place.assign(size_t(channels), 0.0);
    const double level = samples ? *std::max_element(envelope.begin(), envelope.end()) : 0.0;
    if (level < m_constants.detection(model.modality()))
        return true; // not felt: nothing more to tell apart

    percept->level = level;
    size_t onset = 0;
    while (envelope[onset] < 0.1 * level)
        ++onset;
    size_t risen = onset;
    while (envelope[risen] < 0.9 * level)
        ++risen;
    percept->rise = double(risen - onset) / Rate;

    // Pulses: the rises through half the level.
    size_t above = 0;
    size_t pulses = 0;
    size_t firstPulse = onset;
    size_t lastPulse = onset;
    for (size_t k = onset; k < samples; ++k) {
        const bool high = envelope[k] >= 0.5 * level;
        above += high ? 1 : 0;
        if (high && (k == onset || envelope[k - 1] < 0.5 * level)) {
            if (pulses == 0)
                firstPulse = k;
            lastPulse = k;
            ++pulses;
        }
    }
    percept->duty = double(above) / double(samples - onset);
    if (pulses >= 2)
        percept->pulseRate = double(pulses - 1) * Rate / double(lastPulse - firstPulse);

    double energy = 0.0;
    for (int c = 0; c < channels; ++c) {
        for (double v : delivered[size_t(c)])
            percept->place[size_t(c)] += v * v;
        energy += percept->place[size_t(c)];
    }
    for (double &share : percept->place)
        share /= energy;
    return true;
}

PerceptDistance Distinctiveness::distance(const Percept &a, const Percept &b) const
{
    const PerceptionConstants &k = m_constants;
    PerceptDistance d;
    if (!a.felt() && !b.felt())
        return d;
    if (a.felt() && b.felt()) {
        // Rhythm and shape compare across senses too.
        d.rate = a.pulseRate > 0 && b.pulseRate > 0
                     ? weberSteps(a.pulseRate, b.pulseRate, k.rateWeber)
                     : 0.0;
        d.duty = weberSteps(std::max(a.duty, ShortestDuty), std::max(b.duty, ShortestDuty),
                            k.durationWeber);
        d.rise = weberSteps(std::max(a.rise, k.shortestRise), std::max(b.rise, k.shortestRise),
                            k.durationWeber);
    }
    if (a.modality != b.modality) {
        // Levels and places of two senses do not compare.
        d.total = std::max(k.otherModality, std::hypot(d.rate, d.duty, d.rise));
        return d;
    }

    // One not felt: it differs from the other by the level from the threshold up.
    const double detection = k.detection(a.modality);
    const double levelA = a.felt() ? a.level : detection;
    const double levelB = b.felt() ? b.level : detection;
    if (a.modality == QLatin1String("vibration"))
        d.level = std::abs(20.0 * std::log10(levelA / levelB)) / k.vibrationLevelJnd;
    else
        d.level = weberSteps(levelA, levelB,
                             a.modality == QLatin1String("pressure") ? k.pressureLevelWeber
                                                                     : k.sightLevelWeber);
    if (a.felt() && b.felt())
        d.place = placeDistance(a, b);
    d.total = std::sqrt(d.level * d.level + d.rate * d.rate + d.duty * d.duty + d.rise * d.rise +
                        d.place * d.place);
    return d;
}

double Distinctiveness::placeDistance(const Percept &a, const Percept &b) const
{
    // How far the stimulation moves around the wrist, in places told apart.
    const double placeJnd = 360.0 / m_constants.wristPlaces;
    const auto known = [](const Percept &p) {
        return std::none_of(p.angle.begin(), p.angle.end(),
                            [](double angle) { return std::isnan(angle); });
    };
    if (known(a) && known(b)) {
        std::vector<std::pair<double, double>> surplus;
        for (size_t c = 0; c < a.place.size(); ++c)
            surplus.emplace_back(a.angle[c], a.place[c]);
        for (size_t c = 0; c < b.place.size(); ++c)
            surplus.emplace_back(b.angle[c], -b.place[c]);
        return circularEarthMover(surplus) / placeJnd;
    }
    // Channels without a place: two of them are as far apart as opposite sides of the wrist;
    // the shares that differ move that far.
    double moved = a.place.size() == b.place.size() ? 0.0 : 1.0;
    if (a.place.size() == b.place.size()) {
        for (size_t c = 0; c < a.place.size(); ++c)
            moved += std::abs(a.place[c] - b.place[c]) / 2.0;
    }
    return moved * 180.0 / placeJnd;
}

bool Distinctiveness::bands(const Router &router, double intensity,
                            std::vector<BandDistinctiveness> *bands, QString *reason) const
{
    bands->clear();
    const Player &player = router.player();
    const std::vector<MessageRoute> routes = router.messageRoutes(intensity);
    for (int device = 0; device < player.deviceCount(); ++device) {
        BandDistinctiveness band;
        band.device = player.deviceName(device);
        band.model = player.deviceModel(device).name();
        std::vector<Percept> percepts;
        for (const MessageRoute &route : routes) {
            if (route.device != device)
                continue;
            Percept percept;
            if (!perceive(route.played, route.routes, player.deviceModel(device), route.intensity,
                          &percept, reason))
                return false;
            band.messages.append(router.nodeIds()[route.source] + QLatin1Char(':') +
                                 messageName(route.message.message));
            percepts.push_back(percept);
        }
        if (percepts.empty())
            continue;
        const size_t n = percepts.size();
        band.distance.assign(n, std::vector<double>(n, 0.0));
        for (size_t a = 0; a < n; ++a) {
            for (size_t b = a + 1; b < n; ++b) {
                const double d = distance(percepts[a], percepts[b]).total;
                band.distance[a][b] = band.distance[b][a] = d;
                if (d < 1.0)
                    band.confusable.push_back({int(a), int(b), d});
            }
        }
        std::stable_sort(band.confusable.begin(), band.confusable.end(),
                         [](const auto &x, const auto &y) { return x.distance < y.distance; });
        bands->push_back(std::move(band));
    }
    return true;
}

} // namespace semhap
