// SPDX-License-Identifier: MIT
#include "hjifrenderer.h"

#include "jsonreader.h"

#include <algorithm>
#include <cmath>

namespace semhap {

namespace {

/** One period of a base signal at phase x (cycles), −1…1, as the standard defines them. */
double baseSignal(const QString &name, double x)
{
    const double f = x - std::floor(x);
    if (name == QLatin1String("Square"))
        return f < 0.5 ? 1.0 : -1.0;
    if (name == QLatin1String("Triangle"))
        return 1.0 - 4.0 * std::abs(std::round(x - 0.25) - (x - 0.25));
    if (name == QLatin1String("SawToothUp"))
        return 2.0 * (x - std::floor(x + 0.5));
    if (name == QLatin1String("SawToothDown"))
        return 2.0 * (std::floor(x + 0.5) - x);
    return std::sin(2.0 * M_PI * x);
}

} // namespace

HjifRenderer::HjifRenderer(const HjifDocument &document, const HjifPerception &perception,
                           const DeviceModel &model, const QString &file, QStringList *warnings)
    : m_document(document), m_perception(perception), m_carrier(model.actuator().hasCarrier()),
      m_followLimit(model.modulationLimit()), m_file(file), m_warnings(warnings)
{}

bool HjifRenderer::render(const HjifChannel &channel, int effectId, EnvelopeCurve *out,
                          bool *found, LoadError *error)
{
    std::vector<EnvelopeCurve> curves;
    *found = false;
    for (const HjifBand &band : channel.bands) {
        if (band.type == HjifBand::Type::WaveletWave) {
            warnOnce(QStringLiteral("wavelet"), band.pointer,
                     QStringLiteral("ignored: WaveletWave bands are coded signals semhap does "
                                    "not decode"));
            continue;
        }
        for (const HjifEffect &e : band.effects) {
            const bool chosen = e.type == HjifEffect::Type::Reference && e.id == effectId;
            if (effectId >= 0 && (!chosen || *found))
                continue; // chosen by its effect, the pattern is the effect's first use
            // Chosen by its effect, the pattern starts where the effect does.
            const double offset =
                effectId >= 0 ? -double(e.position) / double(m_document.timescale) : 0.0;
            if (!effect(band, e, offset, &curves)) {
                *error = m_error;
                return false;
            }
            *found = true;
        }
    }
    *out = EnvelopeCurve::maximum(std::move(curves));
    return true;
}

bool HjifRenderer::effect(const HjifBand &band, const HjifEffect &e, double offset,
                          std::vector<EnvelopeCurve> *out)
{
    const double start = offset + double(e.position) / double(m_document.timescale);
    if (e.type == HjifEffect::Type::Composite) {
        warnOnce(QStringLiteral("composite"), e.pointer,
                 QStringLiteral("ignored: composite effects are not converted"));
        return true;
    }
    if (e.type == HjifEffect::Type::Basis)
        return basis(band, e, start, out);
    // A reference plays the library effect of its id, moved by its position.
    const HjifEffect *target = nullptr;
    for (const HjifEffect &candidate : m_perception.library) {
        if (candidate.id == e.id)
            target = &candidate;
    }
    if (!target) {
        m_error = LoadError::at(
            m_file, e.pointer + QStringLiteral("/id"),
            QStringLiteral("no effect %1 in the perception's effect_library").arg(e.id));
        return false;
    }
    if (target->type == HjifEffect::Type::Reference) {
        // In the library an effect's id is its own: a reference there names itself.
        m_error = LoadError::at(m_file, target->pointer + QStringLiteral("/id"),
                                QStringLiteral("library effect %1 refers to itself").arg(e.id));
        return false;
    }
    // The reference places the library effect: its own position is not added (as the
    // reference software linearises a library).
    return basis(band, *target, start, out);
}

bool HjifRenderer::basis(const HjifBand &band, const HjifEffect &e, double start,
                         std::vector<EnvelopeCurve> *out)
{
    // Every keyframe costs work, with an amplitude or not, each time a reference plays it.
    if (!spend(qint64(e.keyframes.size()), e.pointer))
        return false;
    const double scale = double(m_document.timescale);
    EnvelopeCurve curve;
    switch (band.type) {
    case HjifBand::Type::WaveletWave:
        return true; // render() leaves these bands out, with a warning
    case HjifBand::Type::Transient:
        for (const HjifKeyframe &k : e.keyframes) {
            if (!k.amplitude)
                continue;
            const double t = start + double(k.position) / scale;
            if (!spend(4, e.pointer) || !checkEnd(t + TransientWidth, e.pointer))
                return false;
            EnvelopeCurve pulse;
            pulse.append(t, 0.0);
            pulse.append(t, std::abs(*k.amplitude));
            pulse.append(t + TransientWidth, std::abs(*k.amplitude));
            pulse.append(t + TransientWidth, 0.0);
            out->push_back(std::move(pulse));
        }
        return true;
    case HjifBand::Type::VectorialWave:
        if (!wave(e, start, &curve))
            return false;
        break;
    case HjifBand::Type::Curve:
        if (!curveOf(band, e, start, &curve))
            return false;
        break;
    }
    if (curve.isEmpty())
        return true;
    curve.append(curve.endTime(), 0.0);
    out->push_back(std::move(curve));
    return true;
}

bool HjifRenderer::curveOf(const HjifBand &band, const HjifEffect &e, double start,
                           EnvelopeCurve *curve)
{
    const double scale = double(m_document.timescale);
    // The reference software's default curve (none given, or Unknown) is its cubic.
    const QString &type = band.curveType;
    const bool cubic =
        type.isEmpty() || type == QLatin1String("Unknown") || type == QLatin1String("Cubic");
    if (!cubic && type != QLatin1String("Linear"))
        warnOnce(QStringLiteral("curve ") + type, band.pointer,
                 QStringLiteral("curve_type %1 is read as Linear").arg(quoted(type)));
    // A device with a carrier takes a level: the curve's magnitude. One without takes the
    // curve, and cannot go below nothing.
    const auto level = [&](double a) {
        if (m_carrier)
            return std::abs(a);
        if (a < 0.0)
            warnOnce(QStringLiteral("negative"), e.pointer,
                     QStringLiteral("negative amplitudes are played as 0"));
        return std::max(0.0, a);
    };
    const HjifKeyframe *previous = nullptr;
    for (const HjifKeyframe &k : e.keyframes) {
        if (!k.amplitude)
            continue;
        const double t = start + double(k.position) / scale;
        if (!checkEnd(t, e.pointer))
            return false;
        if (!previous) {
            // Until its first keyframe an effect holds that keyframe's value.
            curve->append(start, 0.0);
            curve->append(start, level(*k.amplitude));
        } else if (cubic) {
            // The reference software's cubic: a smooth step between two keyframes.
            const double t0 = start + double(previous->position) / scale;
            const double a0 = *previous->amplitude;
            const double a1 = *k.amplitude;
            const auto steps = qint64(std::floor((t - t0) / Step));
            if (!spend(steps, e.pointer))
                return false;
            for (qint64 i = 1; i < steps; ++i) {
                const double u = double(i) * Step / (t - t0);
                curve->append(t0 + double(i) * Step,
                              level(a0 + (a1 - a0) * u * u * (3.0 - 2.0 * u)));
            }
        }
        curve->append(t, level(*k.amplitude));
        previous = &k;
    }
    return true;
}

bool HjifRenderer::wave(const HjifEffect &e, double start, EnvelopeCurve *out)
{
    const double scale = double(m_document.timescale);
    std::vector<EnvelopePoint> amplitudes;
    std::vector<EnvelopePoint> frequencies;
    double end = start;
    for (const HjifKeyframe &k : e.keyframes) {
        const double t = start + double(k.position) / scale;
        end = std::max(end, t);
        if (k.amplitude)
            amplitudes.push_back({t, std::abs(*k.amplitude)});
        if (k.frequency)
            frequencies.push_back({t, double(*k.frequency)});
    }
    if (e.keyframes.empty())
        return true;
    if (!checkEnd(end, e.pointer))
        return false;
    // No amplitude keyframe: the wave plays at full amplitude, as the reference software has
    // it; until the first, at the first's.
    if (amplitudes.empty())
        amplitudes.push_back({start, 1.0});
    else if (amplitudes.front().t > start)
        amplitudes.insert(amplitudes.begin(), {start, amplitudes.front().v});
    const EnvelopeCurve amplitude(std::move(amplitudes));
    const EnvelopeCurve frequency(std::move(frequencies));
    if (m_carrier) {
        // The device makes the carrier: it takes the amplitude, and its frequency is its own.
        for (const EnvelopePoint &f : frequency.points()) {
            const HjifReferenceDevice *device =
                m_perception.devices.empty() ? nullptr : &m_perception.devices.front();
            if (device && device->minimumFrequency && device->maximumFrequency &&
                (f.v < *device->minimumFrequency || f.v > *device->maximumFrequency))
                warnOnce(QStringLiteral("carrier"), e.pointer,
                         QStringLiteral("a %1 Hz wave plays at the band's own carrier").arg(f.v));
        }
        if (!spend(qint64(amplitude.points().size()) + 2, e.pointer))
            return false;
        out->append(start, 0.0);
        for (const EnvelopePoint &p : amplitude.points())
            out->append(p.t, p.v);
        if (out->endTime() < end)
            out->append(end, out->points().back().v);
        return true;
    }
    // A device without a carrier plays the wave itself, raised to 0…amplitude; one faster
    // than it follows (or than the samples could show) as its mean level.
    double fastest = 0.0;
    for (const EnvelopePoint &f : frequency.points())
        fastest = std::max(fastest, f.v);
    if (fastest > m_followLimit) {
        warnOnce(QStringLiteral("fast"), e.pointer,
                 QStringLiteral("a %1 Hz wave is faster than the device follows (%2 Hz): "
                                "played as its mean level")
                     .arg(fastest)
                     .arg(m_followLimit, 0, 'g', 3));
        if (!spend(qint64(amplitude.points().size()) + 2, e.pointer))
            return false;
        out->append(start, 0.0);
        for (const EnvelopePoint &p : amplitude.points())
            out->append(p.t, 0.5 * p.v);
        if (out->endTime() < end)
            out->append(end, out->points().back().v);
        return true;
    }
    const auto steps = qint64(std::floor((end - start) / Step));
    if (!spend(steps + 2, e.pointer))
        return false;
    double cycles = e.phase / (2.0 * M_PI);
    out->append(start, 0.0);
    for (qint64 i = 0; i <= steps; ++i) {
        const double t = start + double(i) * Step;
        const double a = amplitude.value(t);
        out->append(t, a * (0.5 + 0.5 * baseSignal(e.baseSignal, cycles)));
        cycles += frequency.value(t) * Step;
    }
    return true;
}

bool HjifRenderer::spend(qint64 points, const QString &pointer)
{
    m_points += points;
    if (m_points <= MaxPoints)
        return true;
    m_error = LoadError::at(
        m_file, pointer,
        QStringLiteral("renders to more than %1 points: the file is refused").arg(MaxPoints));
    return false;
}

bool HjifRenderer::checkEnd(double t, const QString &pointer)
{
    if (t <= MaxDuration)
        return true;
    m_error = LoadError::at(
        m_file, pointer,
        QStringLiteral("plays until %1 s, more than %2 s").arg(t, 0, 'g', 6).arg(MaxDuration));
    return false;
}

void HjifRenderer::warnOnce(const QString &key, const QString &pointer, const QString &reason)
{
    if (m_warned.contains(key))
        return;
    m_warned.append(key);
    if (m_warnings)
        m_warnings->append(LoadError::at(m_file, pointer, reason).toString());
}

} // namespace semhap
