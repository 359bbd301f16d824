// SPDX-License-Identifier: MIT
#include "pattern.h"

#include "envelopes.h"
#include "jsonreader.h"
#include "waveformparser.h"

#include <QJsonArray>

#include <cmath>

namespace semhap {

namespace {

/** Fills `pattern`'s declared parameters from the optional `"params"` object. */
bool readParams(const QJsonObject &json, WaveformParser &reader, ParamTable &params)
{
    const QLatin1String key("params");
    if (!json.contains(key))
        return true;
    const QString pointer = jsonPointerChild(QString(), key);
    const QJsonValue value = json.value(key);
    if (!value.isObject())
        return reader.fail(pointer,
                           QStringLiteral("expected an object, got ") + jsonTypeName(value));
    const QJsonObject object = value.toObject();
    for (auto it = object.begin(); it != object.end(); ++it) {
        double defaultValue = 0.0;
        if (it.key().isEmpty())
            return reader.fail(pointer, QStringLiteral("a parameter name must not be empty"));
        if (!reader.finiteNumber(it.value(), jsonPointerChild(pointer, it.key()), &defaultValue)) {
            return false;
        }
        params.declare(it.key(), defaultValue);
    }
    return true;
}

bool readChannels(const QJsonObject &track, const QString &pointer, WaveformParser &reader,
                  QStringList *channels)
{
    const QLatin1String key("channels");
    if (!reader.require(track, pointer, key))
        return false;
    const QString at = jsonPointerChild(pointer, key);
    const QJsonValue value = track.value(key);
    if (!value.isArray())
        return reader.fail(at, QStringLiteral("expected an array, got ") + jsonTypeName(value));
    const QJsonArray array = value.toArray();
    if (array.isEmpty())
        return reader.fail(at, QStringLiteral("expected at least one channel"));
    for (int i = 0; i < array.size(); ++i) {
        const QString name = array.at(i).toString();
        if (name.isEmpty()) {
            return reader.fail(jsonPointerChild(at, i),
                               QStringLiteral("expected a channel name, got ") +
                                   jsonTypeName(array.at(i)));
        }
        channels->append(name);
    }
    return true;
}

/** Parses one of a track's waveforms; an absent one stays null. */
bool readWaveform(const QJsonObject &track, const QString &pointer, QLatin1String key,
                  WaveformParser &parser, WaveformPtr *out)
{
    if (!track.contains(key))
        return true;
    *out = parser.parse(track.value(key), jsonPointerChild(pointer, key));
    return *out != nullptr;
}

bool readTrack(const QJsonValue &json, const QString &pointer, WaveformParser &parser,
               const ParamTable &params, PatternTrack *track)
{
    if (!json.isObject())
        return parser.fail(pointer,
                           QStringLiteral("expected a track object, got ") + jsonTypeName(json));
    const QJsonObject object = json.toObject();
    const QLatin1String releaseKey("release");
    if (!parser.checkKeys(object, pointer,
                          {QLatin1String("channels"), QLatin1String("attack"),
                           QLatin1String("sustain"), releaseKey}) ||
        !readChannels(object, pointer, parser, &track->channels) ||
        !readWaveform(object, pointer, QLatin1String("attack"), parser, &track->attack) ||
        !readWaveform(object, pointer, QLatin1String("sustain"), parser, &track->sustain) ||
        !readWaveform(object, pointer, releaseKey, parser, &track->release)) {
        return false;
    }
    if (track->release && std::isinf(track->release->duration(params.defaults().data()))) {
        return parser.fail(jsonPointerChild(pointer, releaseKey),
                           QStringLiteral("a release must end, but this one lasts forever"));
    }
    if (!track->sustain)
        track->sustain = std::make_unique<ConstWaveform>(0.0);

    int stateSize = 0;
    for (const WaveformPtr *waveform : {&track->attack, &track->sustain, &track->release}) {
        if (*waveform)
            (*waveform)->assignState(stateSize);
    }
    track->stateSize = stateSize;
    return true;
}

} // namespace

std::shared_ptr<const Pattern> Pattern::fromJson(const QJsonObject &json, const QString &file,
                                                 LoadError *error)
{
    auto pattern = std::make_shared<Pattern>();
    WaveformParser parser(pattern->m_params, file);
    const QString root = QStringLiteral("");
    const QLatin1String formatKey("format");
    const QLatin1String descriptionKey("description");
    const QLatin1String tracksKey("tracks");
    const auto failed = [&]() {
        if (error)
            *error = parser.error();
        return nullptr;
    };

    if (!checkFormat(json, file, QLatin1String(Format), error))
        return nullptr;
    const QLatin1String sharpnessKey("sharpness");
    if (!parser.checkKeys(json, root,
                          {formatKey, QLatin1String("name"), QLatin1String("model"),
                           descriptionKey, sharpnessKey, QLatin1String("params"), tracksKey})) {
        return failed();
    }
    if (json.contains(sharpnessKey)) {
        double sharpness = 0.0;
        if (!parser.JsonReader::number(json, root, sharpnessKey, &sharpness))
            return failed();
        if (!(sharpness >= 0.0 && sharpness <= 1.0)) {
            parser.fail(jsonPointerChild(root, sharpnessKey),
                        QStringLiteral("must be within [0, 1], got %1").arg(sharpness));
            return failed();
        }
        pattern->m_sharpness = sharpness;
    }
    if (!parser.nonEmptyString(json, root, QLatin1String("name"), &pattern->m_name) ||
        !parser.nonEmptyString(json, root, QLatin1String("model"), &pattern->m_model)) {
        return failed();
    }
    if (json.contains(descriptionKey)) {
        const QJsonValue description = json.value(descriptionKey);
        if (!description.isString()) {
            parser.fail(jsonPointerChild(root, descriptionKey),
                        QStringLiteral("expected a string, got ") + jsonTypeName(description));
            return failed();
        }
        pattern->m_description = description.toString();
    }
    if (!readParams(json, parser, pattern->m_params) || !parser.require(json, root, tracksKey))
        return failed();

    const QString tracksPointer = jsonPointerChild(root, tracksKey);
    const QJsonValue tracks = json.value(tracksKey);
    if (!tracks.isArray()) {
        parser.fail(tracksPointer,
                    QStringLiteral("expected an array, got ") + jsonTypeName(tracks));
        return failed();
    }
    const QJsonArray array = tracks.toArray();
    if (array.isEmpty()) {
        parser.fail(tracksPointer, QStringLiteral("expected at least one track"));
        return failed();
    }
    if (array.size() > MaxTracks) {
        parser.fail(tracksPointer, QStringLiteral("%1 tracks, more than the %2 a pattern may have")
                                       .arg(array.size())
                                       .arg(MaxTracks));
        return failed();
    }
    pattern->m_tracks.resize(size_t(array.size()));
    for (int i = 0; i < array.size(); ++i) {
        PatternTrack &track = pattern->m_tracks[size_t(i)];
        if (!readTrack(array.at(i), jsonPointerChild(tracksPointer, i), parser, pattern->m_params,
                       &track)) {
            return failed();
        }
        pattern->m_stateSize += track.stateSize;
    }
    return pattern;
}

std::shared_ptr<const Pattern> Pattern::fromFile(const QString &path, LoadError *error)
{
    QJsonObject json;
    LoadError readError;
    if (!readJsonObjectFile(path, &json, &readError)) {
        if (error)
            *error = readError;
        return nullptr;
    }
    return fromJson(json, path, error);
}

QJsonObject Pattern::toJson() const
{
    QJsonObject params;
    for (int i = 0; i < m_params.size(); ++i) {
        if (i != ParamTable::Intensity || m_params.defaultValue(i) != 1.0)
            params.insert(m_params.name(i), m_params.defaultValue(i));
    }
    QJsonArray tracks;
    for (const PatternTrack &track : m_tracks) {
        QJsonObject object{
            {QStringLiteral("channels"), QJsonArray::fromStringList(track.channels)}};
        if (track.attack)
            object.insert(QStringLiteral("attack"), track.attack->toJson(m_params));
        object.insert(QStringLiteral("sustain"), track.sustain->toJson(m_params));
        if (track.release)
            object.insert(QStringLiteral("release"), track.release->toJson(m_params));
        tracks.append(object);
    }
    QJsonObject json{{QStringLiteral("format"), QLatin1String(Format)},
                     {QStringLiteral("name"), m_name},
                     {QStringLiteral("model"), m_model}};
    if (!m_description.isEmpty())
        json.insert(QStringLiteral("description"), m_description);
    if (m_sharpness >= 0.0)
        json.insert(QStringLiteral("sharpness"), m_sharpness);
    if (!params.isEmpty())
        json.insert(QStringLiteral("params"), params);
    json.insert(QStringLiteral("tracks"), tracks);
    return json;
}

} // namespace semhap
