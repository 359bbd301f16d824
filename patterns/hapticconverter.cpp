// SPDX-License-Identifier: MIT
#include "hapticconverter.h"

#include "ahapformat.h"
#include "inputfile.h"
#include "jsonreader.h"
#include "metahapticformat.h"
#include "outputfile.h"
#include "pattern.h"
#include "voice.h"

#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>

#include <algorithm>
#include <cmath>

namespace semhap {

namespace {

const QLatin1String TrackParts[] = {QLatin1String("attack"), QLatin1String("sustain"),
                                    QLatin1String("release")};

/**
 * The amplitude modulation that stands for sharpness: 1 at the start, between 0 and 1 at
 * `freq` Hz. Its exact form marks it, so an export can take it off again.
 */
QJsonObject modulation(double freq)
{
    return {{QStringLiteral("type"), QStringLiteral("sine")},
            {QStringLiteral("freq"), freq},
            {QStringLiteral("amp"), 0.5},
            {QStringLiteral("offset"), 0.5},
            {QStringLiteral("phase"), 0.25}};
}

bool isModulation(const QJsonValue &json, double *freq)
{
    const QJsonObject o = json.toObject();
    if (o.size() != 5 || o.value(QLatin1String("type")) != QLatin1String("sine") ||
        !o.value(QLatin1String("freq")).isDouble())
        return false;
    *freq = o.value(QLatin1String("freq")).toDouble();
    return o == modulation(*freq);
}

/** The waveform without a modulation made by an import (the largest frequency in `freq`). */
QJsonValue withoutModulation(const QJsonValue &waveform, double *freq)
{
    const QJsonObject o = waveform.toObject();
    if (o.value(QLatin1String("type")) != QLatin1String("product"))
        return waveform;
    QJsonArray kept;
    for (const QJsonValue &child : o.value(QLatin1String("of")).toArray()) {
        double f = 0.0;
        if (isModulation(child, &f))
            *freq = std::max(*freq, f);
        else
            kept.append(child);
    }
    if (kept.size() == o.value(QLatin1String("of")).toArray().size() || kept.isEmpty())
        return waveform;
    if (kept.size() == 1)
        return kept.first();
    QJsonObject rest = o;
    rest.insert(QStringLiteral("of"), kept);
    return rest;
}

bool isSilent(const QJsonObject &track)
{
    const QJsonValue sustain = track.value(QLatin1String("sustain"));
    return sustain.isUndefined() ||
           (sustain.toObject().value(QLatin1String("type")) == QLatin1String("const") &&
            sustain.toObject().value(QLatin1String("value")) == QJsonValue(0));
}

QString describe(HapticFileFormat format)
{
    switch (format) {
    case HapticFileFormat::Ahap:
        return QStringLiteral("AHAP");
    case HapticFileFormat::MetaHaptic:
        return QStringLiteral(".haptic");
    case HapticFileFormat::Hjif:
        return QStringLiteral("HJIF");
    case HapticFileFormat::Semhap:
        break;
    }
    return QStringLiteral("semhap pattern");
}

/** HJIF needs device models, which live above this module. */
LoadError hjifElsewhere(const QString &file)
{
    return LoadError::at(file, QString(),
                         QStringLiteral("HJIF is converted by HjifConverter (the hjif module)"));
}

} // namespace

bool HapticConverter::formatOf(const QString &path, HapticFileFormat *format, LoadError *error)
{
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (suffix == QLatin1String("json"))
        *format = HapticFileFormat::Semhap;
    else if (suffix == QLatin1String("ahap"))
        *format = HapticFileFormat::Ahap;
    else if (suffix == QLatin1String("haptic"))
        *format = HapticFileFormat::MetaHaptic;
    else if (suffix == QLatin1String("hjif"))
        *format = HapticFileFormat::Hjif;
    else {
        *error =
            LoadError::at(path, QString(),
                          QStringLiteral("unknown file type %1: use .json (semhap pattern), "
                                         ".ahap (Apple Core Haptics), .haptic (Meta) or .hjif "
                                         "(MPEG haptics)")
                              .arg(quoted(suffix.isEmpty() ? path : QLatin1Char('.') + suffix)));
        return false;
    }
    return true;
}

bool HapticConverter::readPattern(const QString &path, const ConvertOptions &options,
                                  QJsonObject *pattern, QStringList *warnings, LoadError *error)
{
    HapticFileFormat format;
    if (!formatOf(path, &format, error))
        return false;
    QByteArray bytes;
    QString reason;
    if (!InputFile::readDocument(path, &bytes, &reason)) {
        *error = LoadError::at(path, QString(), QStringLiteral("cannot read: ") + reason);
        return false;
    }
    return parsePattern(bytes, path, options, pattern, warnings, error);
}

bool HapticConverter::parsePattern(const QByteArray &bytes, const QString &file,
                                   const ConvertOptions &options, QJsonObject *pattern,
                                   QStringList *warnings, LoadError *error)
{
    HapticFileFormat format;
    QJsonObject json;
    if (!formatOf(file, &format, error) || !parseJsonObject(bytes, file, &json, error))
        return false;
    HapticTimeline timeline;
    switch (format) {
    case HapticFileFormat::Hjif:
        *error = hjifElsewhere(file);
        return false;
    case HapticFileFormat::Semhap:
        if (!Pattern::fromJson(json, file, error))
            return false;
        *pattern = json;
        return true;
    case HapticFileFormat::Ahap:
        if (!AhapFormat::read(json, file, &timeline, warnings, error))
            return false;
        break;
    case HapticFileFormat::MetaHaptic:
        if (!MetaHapticFormat::read(json, file, &timeline, warnings, error))
            return false;
        break;
    }
    ConvertOptions named = options;
    if (named.name.isEmpty())
        named.name = QFileInfo(file).completeBaseName();
    *pattern = timelineToPattern(
        timeline, named,
        QStringLiteral("%1 %2").arg(describe(format), QFileInfo(file).fileName()));
    return true;
}

bool HapticConverter::writePattern(const QJsonObject &pattern, const QString &path,
                                   const ConvertOptions &options, QStringList *warnings,
                                   LoadError *error)
{
    HapticFileFormat format;
    QByteArray bytes;
    if (!formatOf(path, &format, error) ||
        !serialize(pattern, format, path, options, &bytes, warnings, error))
        return false;
    return OutputFile::write(path, bytes, error);
}

bool HapticConverter::serialize(const QJsonObject &pattern, HapticFileFormat format,
                                const QString &file, const ConvertOptions &options,
                                QByteArray *bytes, QStringList *warnings, LoadError *error)
{
    if (format == HapticFileFormat::Semhap) {
        if (!Pattern::fromJson(pattern, file, error))
            return false;
        *bytes = QJsonDocument(pattern).toJson(QJsonDocument::Indented);
        return true;
    }
    if (format == HapticFileFormat::Hjif) {
        *error = hjifElsewhere(file);
        return false;
    }
    HapticTimeline timeline;
    if (!patternToTimeline(pattern, file, options, &timeline, warnings, error))
        return false;
    const QString description =
        QStringLiteral("semhap pattern %1").arg(pattern.value(QLatin1String("name")).toString());
    const QJsonObject out = format == HapticFileFormat::Ahap
                                ? AhapFormat::write(timeline, description)
                                : MetaHapticFormat::write(timeline, description);
    *bytes = QJsonDocument(out).toJson(QJsonDocument::Indented);
    return true;
}

QJsonObject HapticConverter::keyframes(const EnvelopeCurve &curve)
{
    QJsonArray points;
    if (curve.isEmpty() || curve.startTime() > 0)
        points.append(QJsonArray{0.0, curve.isEmpty() ? 0.0 : curve.points().front().v});
    for (const EnvelopePoint &p : curve.points())
        points.append(QJsonArray{p.t, p.v});
    return {{QStringLiteral("type"), QStringLiteral("keyframes")},
            {QStringLiteral("points"), points}};
}

QJsonObject HapticConverter::oneShotTrack(const QStringList &channels, const QJsonValue &attack)
{
    return {
        {QStringLiteral("channels"), QJsonArray::fromStringList(channels)},
        {QStringLiteral("attack"), attack},
        {QStringLiteral("sustain"), QJsonObject{{QStringLiteral("type"), QStringLiteral("const")},
                                                {QStringLiteral("value"), 0}}}};
}

QJsonObject HapticConverter::oneShotPattern(const QJsonArray &tracks,
                                            const ConvertOptions &options,
                                            const QString &description)
{
    return {{QStringLiteral("format"), QString::fromLatin1(Pattern::Format)},
            {QStringLiteral("name"),
             options.name.isEmpty() ? QStringLiteral("imported") : options.name},
            {QStringLiteral("model"),
             options.model.isEmpty() ? QStringLiteral("lra4") : options.model},
            {QStringLiteral("description"), description},
            {QStringLiteral("tracks"), tracks}};
}

QJsonObject HapticConverter::timelineToPattern(const HapticTimeline &timeline,
                                               const ConvertOptions &options,
                                               const QString &source)
{
    const QJsonObject envelope = keyframes(timeline.intensity);
    QJsonValue attack = envelope;
    QString description =
        QStringLiteral("Imported from %1: its envelope plays once on begin").arg(source);
    if (timeline.sharpness >= 0)
        description += QStringLiteral("; sharpness %1").arg(timeline.sharpness, 0, 'g', 3);
    if (timeline.sharpness > 0 && options.modulationLimit > 0) {
        const double freq = timeline.sharpness * options.modulationLimit;
        attack = QJsonObject{{QStringLiteral("type"), QStringLiteral("product")},
                             {QStringLiteral("of"), QJsonArray{envelope, modulation(freq)}}};
        description += QStringLiteral(" as a %1 Hz modulation").arg(freq, 0, 'g', 3);
    }
    const QString channel = options.channel.isEmpty() ? QStringLiteral("*") : options.channel;
    QJsonObject pattern = oneShotPattern(QJsonArray{oneShotTrack(QStringList{channel}, attack)},
                                         options, description + QLatin1Char('.'));
    if (timeline.sharpness >= 0)
        pattern.insert(QStringLiteral("sharpness"), timeline.sharpness);
    return pattern;
}

bool HapticConverter::span(const QJsonObject &pattern, const QString &file,
                           const ConvertOptions &options, const std::vector<int> &tracks,
                           double *releaseAtOut, double *durationOut, QStringList *warnings,
                           LoadError *error)
{
    const PatternPtr parsed = Pattern::fromJson(pattern, file, error);
    if (!parsed)
        return false;
    const auto warn = [&](const QString &pointer, const QString &reason) {
        if (warnings)
            warnings->append(LoadError::at(file, pointer, reason).toString());
    };
    const QJsonArray json = pattern.value(QLatin1String("tracks")).toArray();
    // When to end: after the attack, and after a while of sustain if the sustain plays.
    const double *params = parsed->params().defaults().data();
    double attackEnd = 0.0;
    double releaseLength = 0.0;
    bool silent = true;
    for (const int i : tracks) {
        const PatternTrack &track = parsed->tracks()[size_t(i)];
        const QString at = jsonPointerChild(QStringLiteral("/tracks"), i);
        if (track.attack) {
            double length = track.attack->duration(params);
            if (!std::isfinite(length)) {
                warn(jsonPointerChild(at, QLatin1String("attack")),
                     QStringLiteral("the attack never ends: rendered for %1 s").arg(DefaultHold));
                length = DefaultHold;
            }
            attackEnd = std::max(attackEnd, length);
        }
        if (track.release)
            releaseLength = std::max(releaseLength, track.release->duration(params));
        silent = silent && isSilent(json.at(i).toObject());
    }
    double releaseAt = options.releaseAt;
    if (releaseAt < 0) {
        releaseAt = attackEnd;
        if (!silent) {
            releaseAt += DefaultHold;
            warn(QString(), QStringLiteral("the sustain is rendered for %1 s; choose the end "
                                           "with --release-at")
                                .arg(DefaultHold));
        }
    }
    const double duration = options.duration >= 0 ? options.duration : releaseAt + releaseLength;
    if (duration > MaxDuration) {
        *error = LoadError::at(file, QString(),
                               QStringLiteral("renders for %1 s, more than %2 s: choose a shorter "
                                              "end or duration")
                                   .arg(duration)
                                   .arg(MaxDuration));
        return false;
    }

    *releaseAtOut = releaseAt;
    *durationOut = duration;
    return true;
}

bool HapticConverter::patternToTimeline(const QJsonObject &pattern, const QString &file,
                                        const ConvertOptions &options, HapticTimeline *timeline,
                                        QStringList *warnings, LoadError *error)
{
    if (!Pattern::fromJson(pattern, file, error))
        return false;
    const auto warn = [&](const QString &pointer, const QString &reason) {
        if (warnings)
            warnings->append(LoadError::at(file, pointer, reason).toString());
    };

    // Take a modulation that stands for sharpness off, so the envelope is exported as such:
    // when the pattern keeps its sharpness (an import made the modulation from it) or the
    // export is asked to read one as sharpness.
    const double kept = pattern.value(QLatin1String("sharpness")).toDouble(-1.0);
    QJsonObject bare = pattern;
    QJsonArray tracks = pattern.value(QLatin1String("tracks")).toArray();
    double freq = 0.0;
    for (int i = 0; i < tracks.size(); ++i) {
        QJsonObject track = tracks.at(i).toObject();
        for (const QLatin1String part : TrackParts) {
            if (track.contains(part))
                track.insert(part, withoutModulation(track.value(part), &freq));
        }
        tracks[i] = track;
    }
    if (options.modulationLimit > 0 || kept >= 0)
        bare.insert(QStringLiteral("tracks"), tracks);
    if (kept >= 0)
        timeline->sharpness = kept;
    else if (options.modulationLimit > 0 && freq > 0)
        timeline->sharpness = std::min(1.0, freq / options.modulationLimit);
    else
        timeline->sharpness = -1.0;
    const PatternPtr parsed = Pattern::fromJson(bare, file, error);
    if (!parsed)
        return false;

    std::vector<int> selected;
    for (int i = 0; i < int(parsed->tracks().size()); ++i) {
        const QStringList &channels = parsed->tracks()[size_t(i)].channels;
        if (options.channel.isEmpty() || channels.contains(options.channel) ||
            channels == QStringList{QStringLiteral("*")})
            selected.push_back(i);
    }
    if (selected.empty()) {
        *error = LoadError::at(
            file, QStringLiteral("/tracks"),
            QStringLiteral("no track drives channel %1").arg(quoted(options.channel)));
        return false;
    }
    if (selected.size() > 1)
        warn(QStringLiteral("/tracks"),
             QStringLiteral("%1 tracks collapse into one envelope (the loudest at each instant); "
                            "choose one with --channel")
                 .arg(selected.size()));
    if (parsed->params().size() > 1)
        warn(QStringLiteral("/params"),
             QStringLiteral("rendered with every parameter at its default"));

    double releaseAt = 0.0;
    double duration = 0.0;
    if (!span(bare, file, options, selected, &releaseAt, &duration, warnings, error))
        return false;

    Voice voice(parsed);
    voice.begin(0.0);
    EnvelopeCurve rendered;
    bool clipped = false;
    bool released = false;
    const auto samples = static_cast<long long>(std::llround(duration * RenderRate));
    for (long long k = 0; k <= samples; ++k) {
        const double t = double(k) / RenderRate;
        if (!released && t >= releaseAt) {
            voice.end(releaseAt);
            released = true;
        }
        voice.advance(t);
        double v = 0.0;
        for (const int i : selected)
            v = std::max(v, voice.value(i));
        clipped = clipped || v > 1.0 || v < 0.0;
        rendered.append(t, std::clamp(v, 0.0, 1.0));
    }
    if (clipped)
        warn(QStringLiteral("/tracks"), QStringLiteral("values outside [0, 1] were clipped"));
    timeline->intensity = rendered.simplified(HapticTimeline::SimplifyTolerance);
    return true;
}

} // namespace semhap
