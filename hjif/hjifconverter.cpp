// SPDX-License-Identifier: MIT
#include "hjifconverter.h"

#include "hjifrenderer.h"
#include "inputfile.h"
#include "jsonreader.h"
#include "outputfile.h"
#include "pattern.h"
#include "patternrender.h"
#include "router.h"

#include <QDate>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>

#include <cmath>
#include <numeric>

namespace semhap {

namespace {

QString perceptionModality(const DeviceModel &model)
{
    if (model.modality() == QLatin1String("vibration"))
        return QStringLiteral("Vibrotactile");
    if (model.modality() == QLatin1String("pressure"))
        return QStringLiteral("Pressure");
    return QString();
}

quint32 bodyPartMask(const DeviceModel &model, const QString &hand)
{
    const QString &body = model.actuator().body;
    quint32 left = 0;
    quint32 right = 0;
    if (body == QLatin1String("wrist")) {
        left = HjifDocument::LeftWrist;
        right = HjifDocument::RightWrist;
    } else if (body == QLatin1String("fingers")) {
        left = HjifDocument::LeftFingers;
        right = HjifDocument::RightFingers;
    }
    if (hand == QLatin1String("left"))
        return left;
    if (hand == QLatin1String("right"))
        return right;
    return left | right;
}

HjifReferenceDevice referenceDevice(const DeviceModel &model, quint32 mask)
{
    const Actuator &a = model.actuator();
    HjifReferenceDevice device;
    device.id = 1;
    device.name = model.name();
    if (mask)
        device.bodyPartMask = mask;
    const auto known = [](double v) { return std::isnan(v) ? std::optional<double>() : v; };
    device.minimumFrequency = known(a.minFrequency);
    device.maximumFrequency = known(a.maxFrequency);
    if (a.hasCarrier())
        device.resonanceFrequency = a.resonance;
    device.maximumAmplitude = known(a.maxAmplitude);
    device.maximumDisplacement = known(a.maxDisplacement);
    device.weight = known(a.weight);
    device.size = known(a.size);
    if (a.type == QLatin1String("piezo"))
        device.type = QStringLiteral("Piezo");
    else if (HjifDocument::actuatorTypes().contains(a.type))
        device.type = a.type;
    else if (!a.type.isEmpty())
        device.type = QStringLiteral("Unknown"); // bellows: the standard names no such kind
    return device;
}

/** The band a channel of `model` plays in: on its carrier, or as levels. */
HjifBand emptyBand(const DeviceModel &model)
{
    const Actuator &a = model.actuator();
    HjifBand band;
    band.type = a.hasCarrier() ? HjifBand::Type::VectorialWave : HjifBand::Type::Curve;
    if (!a.hasCarrier())
        band.curveType = QStringLiteral("Linear");
    const double low =
        std::isnan(a.minFrequency) ? (a.hasCarrier() ? a.resonance : 0.0) : a.minFrequency;
    const double high = std::isnan(a.maxFrequency)
                            ? (a.hasCarrier() ? a.resonance : model.modulationLimit())
                            : a.maxFrequency;
    band.lowerFrequency = int(std::floor(low));
    band.upperFrequency = int(std::ceil(high));
    return band;
}

/** An envelope of one channel as keyframes from 0, on the carrier when there is one. */
std::vector<HjifKeyframe> keyframesOf(const EnvelopeCurve &curve, double carrier)
{
    std::vector<HjifKeyframe> keyframes;
    for (const EnvelopePoint &p : curve.points()) {
        HjifKeyframe k;
        k.position = std::llround(p.t * double(HjifConverter::Timescale));
        k.amplitude = std::round(std::clamp(p.v, 0.0, 1.0) * 1e6) / 1e6;
        if (keyframes.empty() && carrier > 0)
            k.frequency = int(std::lround(carrier));
        keyframes.push_back(k);
    }
    return keyframes;
}

/** A channel's envelope as an effect at 0, on the carrier when the device has one. */
HjifEffect effectOf(const EnvelopeCurve &envelope, double carrier)
{
    HjifEffect effect;
    if (carrier > 0)
        effect.baseSignal = QStringLiteral("Sine");
    effect.keyframes = keyframesOf(envelope, carrier);
    return effect;
}

/**
 * How an export renders `pattern` (all its tracks, as HapticConverter::span says) at 1 kHz,
 * with a last sample at the end; `length` (when given) is the span without it.
 */
bool exportRender(const Pattern &pattern, const QString &file, const ConvertOptions &options,
                  RenderOptions *render, double *length, QStringList *warnings, LoadError *error)
{
    std::vector<int> all(pattern.tracks().size());
    std::iota(all.begin(), all.end(), 0);
    if (!HapticConverter::span(pattern.toJson(), file, options, all, &render->releaseAt,
                               &render->duration, warnings, error))
        return false;
    if (length)
        *length = render->duration;
    render->rate = 1000.0;
    render->duration += 1.0 / render->rate; // the render takes its last sample at the end too
    return true;
}

bool sameKeyframes(const std::vector<HjifKeyframe> &a, const std::vector<HjifKeyframe> &b)
{
    return std::equal(a.begin(), a.end(), b.begin(), b.end(),
                      [](const HjifKeyframe &x, const HjifKeyframe &y) {
                          return x.position == y.position && x.amplitude == y.amplitude &&
                                 x.frequency == y.frequency;
                      });
}

/** Each channel of a render as an envelope, reduced to breakpoints; silent ones empty. */
std::vector<EnvelopeCurve> channelEnvelopes(const RenderedPattern &rendered)
{
    std::vector<EnvelopeCurve> out;
    for (const std::vector<double> &values : rendered.values) {
        EnvelopeCurve curve;
        bool felt = false;
        for (size_t k = 0; k < values.size(); ++k) {
            curve.append(rendered.t[k], values[k]);
            felt = felt || values[k] > 0.0;
        }
        out.push_back(felt ? curve.simplified(HapticTimeline::SimplifyTolerance)
                           : EnvelopeCurve());
    }
    return out;
}

HjifDocument newDocument(const QString &description)
{
    HjifDocument document;
    document.date = QDate::currentDate().toString(Qt::ISODate);
    document.description = description;
    document.timescale = HjifConverter::Timescale;
    return document;
}

HjifPerception newPerception(int id, const DeviceModel &model, const QString &hand,
                             const QString &description)
{
    HjifPerception perception;
    perception.id = id;
    perception.description = description;
    perception.modality = perceptionModality(model);
    const quint32 mask = bodyPartMask(model, hand);
    perception.devices.push_back(referenceDevice(model, mask));
    for (int c = 0; c < model.channelCount(); ++c) {
        HjifChannel channel;
        channel.id = c;
        channel.description = model.channels()[size_t(c)].name;
        channel.bodyPartMask = mask;
        channel.referenceDevice = 1;
        channel.bands.push_back(emptyBand(model));
        perception.channels.push_back(std::move(channel));
    }
    return perception;
}

bool hapticModel(const DeviceModel &model, const QString &file, LoadError *error)
{
    if (!perceptionModality(model).isEmpty())
        return true;
    *error = LoadError::at(file, QStringLiteral("/model"),
                           QStringLiteral("model %1 is %2, not felt: HJIF carries haptics")
                               .arg(quoted(model.name()), model.modality().isEmpty()
                                                              ? QStringLiteral("of no modality")
                                                              : model.modality()));
    return false;
}

/**
 * An envelope as a pattern keeps it: reduced to breakpoints, and no finer than semhap plays
 * (a sample a millisecond), so a file of dense keyframes makes a pattern of bounded size.
 */
EnvelopeCurve playable(const EnvelopeCurve &curve)
{
    const double step = 0.001;
    const auto samples = qint64(std::ceil(curve.endTime() / step));
    if (qint64(curve.points().size()) <= 2 * (samples + 1))
        return curve.simplified(HapticTimeline::SimplifyTolerance / 4);
    EnvelopeCurve sampled;
    for (qint64 k = 0; k <= samples; ++k)
        sampled.append(double(k) * step, curve.value(double(k) * step));
    return sampled.simplified(HapticTimeline::SimplifyTolerance / 4);
}

/** The model an import plays on: the one asked for, the reference device's, or the sense's. */
DeviceModelPtr importModel(const HjifPerception &perception, const QString &asked)
{
    if (!asked.isEmpty())
        return DeviceModelLibrary::builtin(asked);
    for (const HjifReferenceDevice &device : perception.devices) {
        if (const DeviceModelPtr model = DeviceModelLibrary::builtin(device.name))
            return model;
    }
    const QString modality = HjifConverter::modalityOf(perception.modality);
    if (modality == QLatin1String("vibration"))
        return DeviceModelLibrary::builtin(QStringLiteral("lra4"));
    if (modality == QLatin1String("pressure"))
        return DeviceModelLibrary::builtin(QStringLiteral("pneumatic6"));
    return nullptr;
}

} // namespace

QString HjifConverter::modalityOf(const QString &perceptionModality)
{
    if (perceptionModality == QLatin1String("Vibrotactile") ||
        perceptionModality == QLatin1String("Vibration"))
        return QStringLiteral("vibration");
    if (perceptionModality == QLatin1String("Pressure"))
        return QStringLiteral("pressure");
    return QString();
}

QString HjifConverter::semanticKeyword(Message message, Category category)
{
    if (message == Message::Grasp)
        return QStringLiteral("UX/Confirmation");
    if (message == Message::Break || message == Message::Slip)
        return QStringLiteral("UX/Alarm");
    return category == Category::Confirmation ? QStringLiteral("UX/Confirmation")
                                              : QStringLiteral("UX/Alarm");
}

bool HjifConverter::readPattern(const QString &path, const ConvertOptions &options,
                                QJsonObject *pattern, QStringList *warnings, LoadError *error)
{
    QByteArray bytes;
    QString reason;
    if (!InputFile::readDocument(path, &bytes, &reason)) {
        *error = LoadError::at(path, QString(), QStringLiteral("cannot read: ") + reason);
        return false;
    }
    return parsePattern(bytes, path, options, pattern, warnings, error);
}

bool HjifConverter::parsePattern(const QByteArray &bytes, const QString &file,
                                 const ConvertOptions &options, QJsonObject *pattern,
                                 QStringList *warnings, LoadError *error)
{
    QJsonObject json;
    HjifDocument document;
    return parseJsonObject(bytes, file, &json, error) &&
           HjifDocument::fromJson(json, file, &document, warnings, error) &&
           documentToPattern(document, file, options, pattern, warnings, error);
}

bool HjifConverter::documentToPattern(const HjifDocument &document, const QString &file,
                                      const ConvertOptions &options, QJsonObject *pattern,
                                      QStringList *warnings, LoadError *error)
{
    const auto warn = [&](const QString &pointer, const QString &reason) {
        if (warnings)
            warnings->append(LoadError::at(file, pointer, reason).toString());
    };
    // The perception: the one asked for, or the first the model (or any semhap device) plays.
    const HjifPerception *perception = nullptr;
    if (options.perception >= 0) {
        perception = document.perception(options.perception);
        if (!perception) {
            QStringList ids;
            for (const HjifPerception &p : document.perceptions)
                ids.append(QString::number(p.id));
            *error = LoadError::at(file, QStringLiteral("/perceptions"),
                                   QStringLiteral("no perception %1 (perceptions: %2)")
                                       .arg(options.perception)
                                       .arg(ids.join(QStringLiteral(", "))));
            return false;
        }
    } else {
        const DeviceModelPtr asked =
            options.model.isEmpty() ? nullptr : DeviceModelLibrary::builtin(options.model);
        for (const HjifPerception &p : document.perceptions) {
            const QString modality = modalityOf(p.modality);
            if (!modality.isEmpty() && (!asked || asked->modality() == modality)) {
                perception = &p;
                break;
            }
        }
        if (!perception)
            perception = &document.perceptions.front();
    }
    if (document.perceptions.size() > 1 && options.perception < 0)
        warn(perception->pointer,
             QStringLiteral("read this one of %1 perceptions; choose another with --perception")
                 .arg(document.perceptions.size()));
    const DeviceModelPtr model = importModel(*perception, options.model);
    if (!model) {
        *error = LoadError::at(file, perception->pointer + QStringLiteral("/perception_modality"),
                               QStringLiteral("%1 has no semhap device: choose one with --device")
                                   .arg(quoted(perception->modality)));
        return false;
    }
    if (!modalityOf(perception->modality).isEmpty() &&
        modalityOf(perception->modality) != model->modality())
        warn(perception->pointer + QStringLiteral("/perception_modality"),
             QStringLiteral("%1 played as %2 on %3")
                 .arg(quoted(perception->modality), model->modality(), model->name()));
    const HjifEffect *chosen = nullptr;
    if (options.effect >= 0) {
        for (const HjifEffect &e : perception->library) {
            if (e.id == options.effect)
                chosen = &e;
        }
        if (!chosen) {
            *error = LoadError::at(file, perception->pointer + QStringLiteral("/effect_library"),
                                   QStringLiteral("no effect %1 in perception %2's library")
                                       .arg(options.effect)
                                       .arg(perception->id));
            return false;
        }
    }

    // Channels go to the model's channel of their description's name, else in order.
    HjifRenderer renderer(document, *perception, *model, file, warnings);
    std::vector<EnvelopeCurve> envelopes(size_t(model->channelCount()));
    std::vector<bool> taken(size_t(model->channelCount()), false);
    bool anyFound = false;
    for (size_t i = 0; i < perception->channels.size(); ++i) {
        const HjifChannel &channel = perception->channels[i];
        int target = model->channelIndex(channel.description);
        if (target < 0 || taken[size_t(target)]) {
            // Otherwise the channel of its place, or the first still free.
            target = int(i) < model->channelCount() && !taken[i]
                         ? int(i)
                         : int(std::find(taken.begin(), taken.end(), false) - taken.begin());
        }
        if (target >= model->channelCount()) {
            warn(channel.pointer,
                 QStringLiteral("ignored: %1 has no channel left for it").arg(model->name()));
            continue;
        }
        taken[size_t(target)] = true;
        bool found = false;
        if (!renderer.render(channel, options.effect, &envelopes[size_t(target)], &found, error))
            return false;
        anyFound = anyFound || found;
    }
    if (chosen && !anyFound) {
        *error = LoadError::at(file, chosen->pointer,
                               QStringLiteral("no channel plays effect %1: nothing says where it "
                                              "plays")
                                   .arg(chosen->id));
        return false;
    }

    // Channels that play alike share a track; all of them alike are one track on "*".
    QJsonArray tracks;
    std::vector<bool> done(envelopes.size(), false);
    for (size_t c = 0; c < envelopes.size(); ++c) {
        if (done[c] || envelopes[c].isEmpty())
            continue;
        const EnvelopeCurve curve = playable(envelopes[c]);
        QStringList channels;
        for (size_t d = c; d < envelopes.size(); ++d) {
            if (!done[d] && envelopes[d].points().size() == envelopes[c].points().size() &&
                std::equal(envelopes[c].points().begin(), envelopes[c].points().end(),
                           envelopes[d].points().begin(),
                           [](const EnvelopePoint &a, const EnvelopePoint &b) {
                               return a.t == b.t && a.v == b.v;
                           })) {
                done[d] = true;
                channels.append(model->channels()[d].name);
            }
        }
        if (channels.size() == model->channelCount())
            channels = QStringList{QStringLiteral("*")};
        tracks.append(HapticConverter::oneShotTrack(channels, HapticConverter::keyframes(curve)));
    }
    if (tracks.isEmpty()) {
        warn(perception->pointer, QStringLiteral("nothing in it plays on %1").arg(model->name()));
        tracks.append(HapticConverter::oneShotTrack(QStringList{QStringLiteral("*")},
                                                    HapticConverter::keyframes(EnvelopeCurve())));
    }

    QString source = QStringLiteral("HJIF %1, perception %2")
                         .arg(QFileInfo(file).fileName())
                         .arg(perception->id);
    QString about = perception->description;
    while (about.endsWith(QLatin1Char('.')))
        about.chop(1);
    if (!about.isEmpty())
        source += QStringLiteral(" (%1)").arg(about);
    if (chosen) {
        source += QStringLiteral(", effect %1").arg(chosen->id);
        if (!chosen->semantic.isEmpty())
            source += QStringLiteral(" (%1)").arg(chosen->semantic);
    }
    ConvertOptions named = options;
    named.model = model->name();
    if (named.name.isEmpty())
        named.name = QFileInfo(file).completeBaseName();
    *pattern = HapticConverter::oneShotPattern(
        tracks, named, QStringLiteral("Imported from %1: it plays once on begin.").arg(source));
    return true;
}

bool HjifConverter::patternToDocument(const QJsonObject &pattern, const QString &file,
                                      const ConvertOptions &options, HjifDocument *document,
                                      QStringList *warnings, LoadError *error)
{
    const PatternPtr parsed = Pattern::fromJson(pattern, file, error);
    if (!parsed)
        return false;
    const DeviceModelPtr model = DeviceModelLibrary::load(parsed->model(), error);
    if (!model || !hapticModel(*model, file, error))
        return false;
    RenderOptions render;
    if (!exportRender(*parsed, file, options, &render, nullptr, warnings, error))
        return false;
    if (warnings && parsed->params().size() > 1)
        warnings->append(LoadError::at(file, QStringLiteral("/params"),
                                       QStringLiteral("rendered with every parameter at its "
                                                      "default"))
                             .toString());
    if (warnings && pattern.contains(QLatin1String("sharpness")))
        warnings->append(LoadError::at(file, QStringLiteral("/sharpness"),
                                       QStringLiteral("not carried: HJIF has no sharpness"))
                             .toString());
    RenderedPattern rendered;
    QString reason;
    if (!renderPattern(parsed, *model, render, &rendered, &reason)) {
        *error = LoadError::at(file, QString(), reason);
        return false;
    }
    *document = newDocument(QStringLiteral("semhap pattern %1").arg(parsed->name()));
    HjifPerception perception = newPerception(
        0, *model, options.hand, QStringLiteral("%1 on %2").arg(parsed->name(), model->name()));
    const double carrier = model->actuator().resonance;
    const std::vector<EnvelopeCurve> envelopes = channelEnvelopes(rendered);
    for (size_t c = 0; c < envelopes.size(); ++c) {
        if (envelopes[c].isEmpty())
            continue;
        perception.channels[c].bands.front().effects.push_back(effectOf(envelopes[c], carrier));
    }
    document->perceptions.push_back(std::move(perception));
    return true;
}

bool HjifConverter::routerToDocument(const Router &router, const QString &file,
                                     const ConvertOptions &options, HjifDocument *document,
                                     QStringList *warnings, LoadError *error)
{
    const Player &player = router.player();
    const std::vector<MessageRoute> routes = router.messageRoutes(1.0);
    const QString name =
        router.graph().name.isEmpty() ? QFileInfo(file).completeBaseName() : router.graph().name;
    *document = newDocument(QStringLiteral("semhap router %1: each message's pattern").arg(name));
    for (int device = 0; device < player.deviceCount(); ++device) {
        const DeviceModel &model = player.deviceModel(device);
        std::vector<const MessageRoute *> here;
        for (const MessageRoute &route : routes) {
            if (route.device == device)
                here.push_back(&route);
        }
        if (here.empty())
            continue;
        if (perceptionModality(model).isEmpty()) {
            if (warnings)
                warnings->append(
                    LoadError::at(file, QString(),
                                  QStringLiteral("device %1 (%2) is %3, not felt: its %4 "
                                                 "message(s) are left out")
                                      .arg(quoted(player.deviceName(device)), model.name(),
                                           model.modality().isEmpty() ? QStringLiteral("unsensed")
                                                                      : model.modality())
                                      .arg(here.size()))
                        .toString());
            continue;
        }
        Gripper hand;
        const QString handName = router.deviceHand(device, &hand) ? gripperName(hand) : QString();
        HjifPerception perception =
            newPerception(int(document->perceptions.size()), model, handName, QString());
        const double carrier = model.actuator().resonance;
        QStringList played;
        double slot = 0.0;
        for (const MessageRoute *route : here) {
            const QString source = router.nodeIds()[route->source] + QLatin1Char(':') +
                                   messageName(route->message.message);
            const QString via = router.nodeIds()[route->pattern];
            const QString where =
                QStringLiteral("%1 (%2 on %3)").arg(file, via, player.deviceName(device));
            RenderOptions render;
            render.intensity = route->intensity;
            double length = 0.0;
            if (!exportRender(*route->played, where, options, &render, &length, warnings, error))
                return false;
            RenderedPattern rendered;
            renderRoutedPattern(route->played, route->routes, model, render, &rendered);
            const QString keyword =
                semanticKeyword(route->message.message, route->message.category);
            QStringList ids;
            const std::vector<EnvelopeCurve> envelopes = channelEnvelopes(rendered);
            for (size_t c = 0; c < envelopes.size(); ++c) {
                if (envelopes[c].isEmpty())
                    continue;
                HjifEffect effect = effectOf(envelopes[c], carrier);
                effect.semantic = keyword;
                int id = -1;
                for (const HjifEffect &e : perception.library) {
                    if (e.semantic == keyword && e.baseSignal == effect.baseSignal &&
                        sameKeyframes(e.keyframes, effect.keyframes))
                        id = e.id;
                }
                if (id < 0) {
                    id = int(perception.library.size());
                    effect.id = id;
                    perception.library.push_back(std::move(effect));
                }
                if (!ids.contains(QString::number(id)))
                    ids.append(QString::number(id));
                HjifEffect use;
                use.type = HjifEffect::Type::Reference;
                use.id = id;
                use.position = std::llround(slot * double(Timescale));
                perception.channels[c].bands.front().effects.push_back(use);
            }
            played.append(QStringLiteral("at %1 s %2 through %3 (%4; effect %5)")
                              .arg(slot, 0, 'g', 6)
                              .arg(source, via, keyword,
                                   ids.isEmpty() ? QStringLiteral("none: silent")
                                                 : ids.join(QStringLiteral(", "))));
            slot += length + Gap;
        }
        perception.description =
            QStringLiteral("Router %1, device %2 (%3%4): each message's pattern in turn, %5 s "
                           "apart: %6.")
                .arg(name, player.deviceName(device), model.name(),
                     handName.isEmpty() ? QString() : QStringLiteral(", %1 hand").arg(handName))
                .arg(Gap)
                .arg(played.join(QStringLiteral("; ")));
        document->perceptions.push_back(std::move(perception));
    }
    if (document->perceptions.empty()) {
        *error = LoadError::at(file, QString(),
                               QStringLiteral("no message plays on a device that is felt"));
        return false;
    }
    return true;
}

bool HjifConverter::writePattern(const QJsonObject &pattern, const QString &path,
                                 const ConvertOptions &options, QStringList *warnings,
                                 LoadError *error)
{
    HjifDocument document;
    return patternToDocument(pattern, path, options, &document, warnings, error) &&
           OutputFile::write(path, serialize(document), error);
}

QByteArray HjifConverter::serialize(const HjifDocument &document)
{
    return QJsonDocument(document.toJson()).toJson(QJsonDocument::Indented);
}

} // namespace semhap
