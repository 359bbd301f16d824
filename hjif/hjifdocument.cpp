// SPDX-License-Identifier: MIT
#include "hjifdocument.h"

#include "jsonreader.h"

#include <QHash>
#include <QJsonArray>
#include <QRegularExpression>
#include <QSet>

#include <cmath>

namespace semhap {

namespace {

constexpr qint64 MaxInt = 2147483647; // the reference software reads 32-bit integers
constexpr double UnsignedMax = 4294967295.0;
/** A full turn either way, and the rounding of a phase kept as a float (as the reference). */
constexpr double PhaseLimit = 2 * M_PI + 1e-6;

/** Adds `id` to `ids`; false when it was there already. */
bool insertUnique(QSet<int> *ids, int id)
{
    const qsizetype before = ids->size();
    ids->insert(id);
    return ids->size() != before;
}

class HjifReader : public JsonReader
{
public:
    HjifReader(const QString &file, QStringList *warnings)
        : JsonReader(file), m_file(file), m_warnings(warnings)
    {}

    bool read(const QJsonObject &json, HjifDocument *document);
    /** Lists each unknown key once, with how many more places hold it. */
    void reportUnknownKeys() const;

private:
    /** Notes the keys of `object` not in `known`: ignored, as the standard's readers do. */
    void unknownKeys(const QJsonObject &object, const QString &pointer,
                     std::initializer_list<QLatin1String> known);
    /** An integral number of `key` within [min, max]. */
    bool integer(const QJsonObject &object, const QString &pointer, QLatin1String key, qint64 *out,
                 qint64 min, qint64 max, bool required);
    bool bounded(const QJsonObject &object, const QString &pointer, QLatin1String key, double *out,
                 double min, double max, bool required);
    bool oneOf(const QJsonObject &object, const QString &pointer, QLatin1String key,
               const QStringList &allowed, QString *out, bool required);
    bool objectAt(const QJsonArray &array, int index, const QString &pointer, QJsonObject *out);
    /** Counts `n` elements against MaxElements. */
    bool spend(qint64 n, const QString &pointer);

    bool readPerception(const QJsonObject &json, const QString &pointer, HjifPerception *out);
    bool readDevice(const QJsonObject &json, const QString &pointer, HjifReferenceDevice *out);
    bool readChannel(const QJsonObject &json, const QString &pointer, HjifChannel *out);
    bool readBand(const QJsonObject &json, const QString &pointer, HjifBand *out);
    bool readEffect(const QJsonObject &json, const QString &pointer, bool library,
                    HjifEffect *out);
    bool readKeyframes(const QJsonArray &json, const QString &pointer, HjifEffect *out);

    struct Unknown
    {
        QString pointer; ///< where it was first met
        qint64 count = 0;
    };

    QString m_file;
    QStringList *m_warnings;
    qint64 m_elements = 0;
    QHash<QString, Unknown> m_unknown;
    QStringList m_unknownOrder;
    QSet<int> m_deviceIds; ///< the reference devices of the perception being read
};

void HjifReader::unknownKeys(const QJsonObject &object, const QString &pointer,
                             std::initializer_list<QLatin1String> known)
{
    for (auto it = object.begin(); it != object.end(); ++it) {
        if (std::find(known.begin(), known.end(), it.key()) != known.end())
            continue;
        Unknown &unknown = m_unknown[it.key()];
        if (unknown.count++ == 0) {
            unknown.pointer = jsonPointerChild(pointer, it.key());
            m_unknownOrder.append(it.key());
        }
    }
}

void HjifReader::reportUnknownKeys() const
{
    if (!m_warnings)
        return;
    for (const QString &key : m_unknownOrder) {
        const Unknown &unknown = m_unknown.value(key);
        QString reason = QStringLiteral("ignored: unknown key");
        if (unknown.count > 1)
            reason += QStringLiteral(" (and in %1 more places)").arg(unknown.count - 1);
        m_warnings->append(LoadError::at(m_file, unknown.pointer, reason).toString());
    }
}

bool HjifReader::integer(const QJsonObject &object, const QString &pointer, QLatin1String key,
                         qint64 *out, qint64 min, qint64 max, bool required)
{
    double value = 0.0;
    if (!number(object, pointer, key, &value, required))
        return false;
    if (!object.contains(key))
        return true;
    const QString at = jsonPointerChild(pointer, key);
    if (value != std::floor(value))
        return fail(at, QStringLiteral("expected an integer, got %1").arg(value));
    if (value < double(min) || value > double(max))
        return fail(at, QStringLiteral("must be between %1 and %2, got %3")
                            .arg(min)
                            .arg(max)
                            .arg(value, 0, 'g', 17));
    *out = qint64(value);
    return true;
}

bool HjifReader::bounded(const QJsonObject &object, const QString &pointer, QLatin1String key,
                         double *out, double min, double max, bool required)
{
    if (!number(object, pointer, key, out, required))
        return false;
    if (object.contains(key) && !(*out >= min && *out <= max))
        return fail(
            jsonPointerChild(pointer, key),
            QStringLiteral("must be between %1 and %2, got %3").arg(min).arg(max).arg(*out));
    return true;
}

bool HjifReader::oneOf(const QJsonObject &object, const QString &pointer, QLatin1String key,
                       const QStringList &allowed, QString *out, bool required)
{
    if (!string(object, pointer, key, out, required))
        return false;
    if (object.contains(key) && !allowed.contains(*out))
        return fail(jsonPointerChild(pointer, key),
                    QStringLiteral("unknown %1 %2 (one of %3)")
                        .arg(key, quoted(*out), allowed.join(QStringLiteral(", "))));
    return true;
}

bool HjifReader::objectAt(const QJsonArray &array, int index, const QString &pointer,
                          QJsonObject *out)
{
    const QString at = jsonPointerChild(pointer, index);
    if (!array.at(index).isObject())
        return fail(at,
                    QStringLiteral("expected an object, got ") + jsonTypeName(array.at(index)));
    *out = array.at(index).toObject();
    return true;
}

bool HjifReader::spend(qint64 n, const QString &pointer)
{
    m_elements += n;
    if (m_elements > HjifDocument::MaxElements)
        return fail(pointer, QStringLiteral("more than %1 keyframes, effects, bands and channels "
                                            "in all: the file is refused")
                                 .arg(HjifDocument::MaxElements));
    return true;
}

bool HjifReader::read(const QJsonObject &json, HjifDocument *document)
{
    const QString root;
    unknownKeys(json, root,
                {QLatin1String("version"), QLatin1String("profile"), QLatin1String("level"),
                 QLatin1String("date"), QLatin1String("description"), QLatin1String("timescale"),
                 QLatin1String("avatars"), QLatin1String("perceptions"), QLatin1String("syncs")});
    qint64 level = 1;
    qint64 timescale = 1000;
    QJsonArray avatars;
    QJsonArray perceptions;
    if (!string(json, root, QLatin1String("version"), &document->version) ||
        !oneOf(json, root, QLatin1String("profile"),
               {QStringLiteral("Main"), QStringLiteral("Simple Parametric")}, &document->profile,
               true) ||
        !integer(json, root, QLatin1String("level"), &level, 1, 2, true) ||
        !string(json, root, QLatin1String("date"), &document->date) ||
        !string(json, root, QLatin1String("description"), &document->description) ||
        !integer(json, root, QLatin1String("timescale"), &timescale, 1, qint64(UnsignedMax),
                 true) ||
        !array(json, root, QLatin1String("avatars"), &avatars) ||
        !array(json, root, QLatin1String("perceptions"), &perceptions))
        return false;
    static const QRegularExpression versionForm(QStringLiteral("^[0-9]{4}(-[1-9][0-9]*)?$"));
    if (!versionForm.match(document->version).hasMatch() ||
        document->version.left(4).toInt() < 2023)
        return fail(QStringLiteral("/version"),
                    QStringLiteral("expected the year of the standard's edition (2023 or later), "
                                   "with -N for an amendment, got %1")
                        .arg(quoted(document->version)));
    document->level = int(level);
    document->timescale = timescale;
    if (perceptions.isEmpty())
        return fail(QStringLiteral("/perceptions"), QStringLiteral("expected at least one"));
    QSet<int> ids;
    for (int i = 0; i < perceptions.size(); ++i) {
        const QString at = jsonPointerChild(QStringLiteral("/perceptions"), i);
        QJsonObject object;
        HjifPerception perception;
        if (!spend(1, at) || !objectAt(perceptions, i, QStringLiteral("/perceptions"), &object) ||
            !readPerception(object, at, &perception))
            return false;
        if (!insertUnique(&ids, perception.id))
            return fail(at + QStringLiteral("/id"),
                        QStringLiteral("perception %1 is not unique").arg(perception.id));
        document->perceptions.push_back(std::move(perception));
    }
    return true;
}

bool HjifReader::readPerception(const QJsonObject &json, const QString &pointer,
                                HjifPerception *out)
{
    out->pointer = pointer;
    unknownKeys(json, pointer,
                {QLatin1String("id"), QLatin1String("avatar_id"), QLatin1String("description"),
                 QLatin1String("perception_modality"), QLatin1String("priority"),
                 QLatin1String("unit_exponent"), QLatin1String("perception_unit_exponent"),
                 QLatin1String("effect_semantic_scheme"), QLatin1String("effect_library"),
                 QLatin1String("reference_devices"), QLatin1String("channels")});
    qint64 id = 0;
    qint64 avatar = 0;
    QJsonArray library;
    QJsonArray devices;
    QJsonArray channels;
    if (!integer(json, pointer, QLatin1String("id"), &id, 0, MaxInt, true) ||
        !integer(json, pointer, QLatin1String("avatar_id"), &avatar, 0, MaxInt, false) ||
        !string(json, pointer, QLatin1String("description"), &out->description, false) ||
        !oneOf(json, pointer, QLatin1String("perception_modality"), HjifDocument::modalities(),
               &out->modality, true) ||
        !array(json, pointer, QLatin1String("effect_library"), &library, false) ||
        !array(json, pointer, QLatin1String("reference_devices"), &devices, false) ||
        !array(json, pointer, QLatin1String("channels"), &channels))
        return false;
    out->id = int(id);
    out->avatarId = int(avatar);
    const QString libraryAt = jsonPointerChild(pointer, QLatin1String("effect_library"));
    QSet<int> libraryIds;
    for (int i = 0; i < library.size(); ++i) {
        QJsonObject object;
        HjifEffect effect;
        if (!objectAt(library, i, libraryAt, &object) ||
            !readEffect(object, jsonPointerChild(libraryAt, i), true, &effect))
            return false;
        if (!insertUnique(&libraryIds, effect.id))
            return fail(jsonPointerChild(libraryAt, i) + QStringLiteral("/id"),
                        QStringLiteral("library effect %1 is not unique").arg(effect.id));
        out->library.push_back(std::move(effect));
    }
    const QString devicesAt = jsonPointerChild(pointer, QLatin1String("reference_devices"));
    m_deviceIds.clear();
    for (int i = 0; i < devices.size(); ++i) {
        QJsonObject object;
        HjifReferenceDevice device;
        if (!spend(1, devicesAt) || !objectAt(devices, i, devicesAt, &object) ||
            !readDevice(object, jsonPointerChild(devicesAt, i), &device))
            return false;
        if (!insertUnique(&m_deviceIds, device.id))
            return fail(jsonPointerChild(devicesAt, i) + QStringLiteral("/id"),
                        QStringLiteral("reference device %1 is not unique").arg(device.id));
        out->devices.push_back(std::move(device));
    }
    const QString channelsAt = jsonPointerChild(pointer, QLatin1String("channels"));
    if (channels.isEmpty())
        return fail(channelsAt, QStringLiteral("expected at least one channel"));
    QSet<int> channelIds;
    for (int i = 0; i < channels.size(); ++i) {
        QJsonObject object;
        HjifChannel channel;
        if (!spend(1, channelsAt) || !objectAt(channels, i, channelsAt, &object) ||
            !readChannel(object, jsonPointerChild(channelsAt, i), &channel))
            return false;
        if (!insertUnique(&channelIds, channel.id))
            return fail(jsonPointerChild(channelsAt, i) + QStringLiteral("/id"),
                        QStringLiteral("channel %1 is not unique").arg(channel.id));
        out->channels.push_back(std::move(channel));
    }
    return true;
}

bool HjifReader::readDevice(const QJsonObject &json, const QString &pointer,
                            HjifReferenceDevice *out)
{
    unknownKeys(json, pointer,
                {QLatin1String("id"), QLatin1String("name"), QLatin1String("body_part_mask"),
                 QLatin1String("maximum_frequency"), QLatin1String("minimum_frequency"),
                 QLatin1String("resonance_frequency"), QLatin1String("maximum_amplitude"),
                 QLatin1String("impedance"), QLatin1String("maximum_voltage"),
                 QLatin1String("maximum_current"), QLatin1String("maximum_displacement"),
                 QLatin1String("weight"), QLatin1String("size"), QLatin1String("custom"),
                 QLatin1String("type")});
    qint64 id = 0;
    qint64 mask = 0;
    if (!integer(json, pointer, QLatin1String("id"), &id, 1, MaxInt, true) ||
        !string(json, pointer, QLatin1String("name"), &out->name) ||
        !integer(json, pointer, QLatin1String("body_part_mask"), &mask, 0, qint64(UnsignedMax),
                 false) ||
        !oneOf(json, pointer, QLatin1String("type"), HjifDocument::actuatorTypes(), &out->type,
               false))
        return false;
    out->id = int(id);
    if (json.contains(QLatin1String("body_part_mask")))
        out->bodyPartMask = quint32(mask);
    const std::pair<QLatin1String, std::optional<double> *> numbers[] = {
        {QLatin1String("minimum_frequency"), &out->minimumFrequency},
        {QLatin1String("maximum_frequency"), &out->maximumFrequency},
        {QLatin1String("resonance_frequency"), &out->resonanceFrequency},
        {QLatin1String("maximum_amplitude"), &out->maximumAmplitude},
        {QLatin1String("maximum_displacement"), &out->maximumDisplacement},
        {QLatin1String("weight"), &out->weight},
        {QLatin1String("size"), &out->size}};
    for (const auto &[key, slot] : numbers) {
        double value = 0.0;
        if (!bounded(json, pointer, key, &value, 0.0, 1e12, false))
            return false;
        if (json.contains(key))
            *slot = value;
    }
    for (const QLatin1String key : {QLatin1String("impedance"), QLatin1String("maximum_voltage"),
                                    QLatin1String("maximum_current")}) {
        double ignored = 0.0;
        if (!bounded(json, pointer, key, &ignored, 0.0, 1e12, false))
            return false;
    }
    return true;
}

bool HjifReader::readChannel(const QJsonObject &json, const QString &pointer, HjifChannel *out)
{
    out->pointer = pointer;
    unknownKeys(json, pointer,
                {QLatin1String("id"), QLatin1String("description"), QLatin1String("gain"),
                 QLatin1String("mixing_coefficient"), QLatin1String("body_part_mask"),
                 QLatin1String("priority"), QLatin1String("reference_device_id"),
                 QLatin1String("direction"), QLatin1String("actuator_resolution"),
                 QLatin1String("body_part_target"), QLatin1String("actuator_target"),
                 QLatin1String("frequency_sampling"), QLatin1String("sample_count"),
                 QLatin1String("vertices"), QLatin1String("bands")});
    qint64 id = 0;
    qint64 mask = 0;
    qint64 device = 0;
    QJsonArray bands;
    if (!integer(json, pointer, QLatin1String("id"), &id, 0, MaxInt, true) ||
        !string(json, pointer, QLatin1String("description"), &out->description, false) ||
        !bounded(json, pointer, QLatin1String("gain"), &out->gain, 0.0, 1e6, false) ||
        !bounded(json, pointer, QLatin1String("mixing_coefficient"), &out->mixingCoefficient, 0.0,
                 1e6, false) ||
        !integer(json, pointer, QLatin1String("body_part_mask"), &mask, 0, qint64(UnsignedMax),
                 false) ||
        !integer(json, pointer, QLatin1String("reference_device_id"), &device, 0, MaxInt, false) ||
        !array(json, pointer, QLatin1String("bands"), &bands))
        return false;
    out->id = int(id);
    out->bodyPartMask = quint32(mask);
    if (json.contains(QLatin1String("reference_device_id"))) {
        if (!m_deviceIds.contains(int(device)))
            return fail(pointer + QStringLiteral("/reference_device_id"),
                        QStringLiteral("no reference device %1 in the perception").arg(device));
        out->referenceDevice = int(device);
    }
    const QString bandsAt = jsonPointerChild(pointer, QLatin1String("bands"));
    for (int i = 0; i < bands.size(); ++i) {
        QJsonObject object;
        HjifBand band;
        if (!spend(1, bandsAt) || !objectAt(bands, i, bandsAt, &object) ||
            !readBand(object, jsonPointerChild(bandsAt, i), &band))
            return false;
        out->bands.push_back(std::move(band));
    }
    return true;
}

bool HjifReader::readBand(const QJsonObject &json, const QString &pointer, HjifBand *out)
{
    out->pointer = pointer;
    unknownKeys(json, pointer,
                {QLatin1String("band_type"), QLatin1String("curve_type"),
                 QLatin1String("block_length"), QLatin1String("priority"),
                 QLatin1String("lower_frequency_limit"), QLatin1String("upper_frequency_limit"),
                 QLatin1String("effects")});
    QString type;
    qint64 lower = 0;
    qint64 upper = 0;
    QJsonArray effects;
    static const QStringList bandTypes{QStringLiteral("Transient"), QStringLiteral("Curve"),
                                       QStringLiteral("VectorialWave"),
                                       QStringLiteral("WaveletWave")};
    if (!oneOf(json, pointer, QLatin1String("band_type"), bandTypes, &type, true) ||
        !oneOf(json, pointer, QLatin1String("curve_type"), HjifDocument::curveTypes(),
               &out->curveType, false) ||
        !integer(json, pointer, QLatin1String("lower_frequency_limit"), &lower, 0, 65535, true) ||
        !integer(json, pointer, QLatin1String("upper_frequency_limit"), &upper, 0, 65535, true) ||
        !array(json, pointer, QLatin1String("effects"), &effects))
        return false;
    out->type = HjifBand::Type(bandTypes.indexOf(type));
    if (upper < lower)
        return fail(pointer + QStringLiteral("/upper_frequency_limit"),
                    QStringLiteral("%1 Hz is below the lower limit, %2 Hz").arg(upper).arg(lower));
    if (!out->curveType.isEmpty() && out->type != HjifBand::Type::Curve)
        return fail(pointer + QStringLiteral("/curve_type"),
                    QStringLiteral("only Curve bands have a curve type"));
    out->lowerFrequency = int(lower);
    out->upperFrequency = int(upper);
    const QString effectsAt = jsonPointerChild(pointer, QLatin1String("effects"));
    for (int i = 0; i < effects.size(); ++i) {
        QJsonObject object;
        HjifEffect effect;
        if (!objectAt(effects, i, effectsAt, &object) ||
            !readEffect(object, jsonPointerChild(effectsAt, i), false, &effect))
            return false;
        out->effects.push_back(std::move(effect));
    }
    return true;
}

bool HjifReader::readEffect(const QJsonObject &json, const QString &pointer, bool library,
                            HjifEffect *out)
{
    out->pointer = pointer;
    unknownKeys(json, pointer,
                {QLatin1String("effect_type"), QLatin1String("id"), QLatin1String("position"),
                 QLatin1String("phase"), QLatin1String("base_signal"),
                 QLatin1String("semantic_keywords"), QLatin1String("keyframes"),
                 QLatin1String("wavelet_stream")});
    static const QStringList types{QStringLiteral("Basis"), QStringLiteral("Reference"),
                                   QStringLiteral("Composite")};
    QString type = types.first();
    qint64 id = -1;
    QJsonArray keyframes;
    if (!spend(1, pointer) ||
        !oneOf(json, pointer, QLatin1String("effect_type"), types, &type, false))
        return false;
    out->type = HjifEffect::Type(types.indexOf(type));
    const bool needsId = library || out->type == HjifEffect::Type::Reference;
    if (!integer(json, pointer, QLatin1String("id"), &id, 0, MaxInt, needsId) ||
        !integer(json, pointer, QLatin1String("position"), &out->position, 0, MaxInt, true) ||
        !bounded(json, pointer, QLatin1String("phase"), &out->phase, -PhaseLimit, PhaseLimit,
                 false) ||
        !oneOf(json, pointer, QLatin1String("base_signal"), HjifDocument::baseSignals(),
               &out->baseSignal, false) ||
        !string(json, pointer, QLatin1String("semantic_keywords"), &out->semantic, false) ||
        !array(json, pointer, QLatin1String("keyframes"), &keyframes, false))
        return false;
    out->id = int(id);
    return readKeyframes(keyframes, jsonPointerChild(pointer, QLatin1String("keyframes")), out);
}

bool HjifReader::readKeyframes(const QJsonArray &json, const QString &pointer, HjifEffect *out)
{
    if (!spend(json.size(), pointer))
        return false;
    out->keyframes.reserve(size_t(json.size()));
    for (int i = 0; i < json.size(); ++i) {
        const QString at = jsonPointerChild(pointer, i);
        QJsonObject object;
        if (!objectAt(json, i, pointer, &object))
            return false;
        unknownKeys(object, at,
                    {QLatin1String("relative_position"), QLatin1String("amplitude_modulation"),
                     QLatin1String("frequency_modulation")});
        HjifKeyframe keyframe;
        double amplitude = 0.0;
        qint64 frequency = 0;
        if (!integer(object, at, QLatin1String("relative_position"), &keyframe.position, 0, MaxInt,
                     false) ||
            !bounded(object, at, QLatin1String("amplitude_modulation"), &amplitude, -1.0, 1.0,
                     false) ||
            !integer(object, at, QLatin1String("frequency_modulation"), &frequency, 0, 65535,
                     false))
            return false;
        if (!out->keyframes.empty() && keyframe.position < out->keyframes.back().position)
            return fail(at + QStringLiteral("/relative_position"),
                        QStringLiteral("keyframe positions must not decrease"));
        if (object.contains(QLatin1String("amplitude_modulation")))
            keyframe.amplitude = amplitude;
        if (object.contains(QLatin1String("frequency_modulation")))
            keyframe.frequency = int(frequency);
        out->keyframes.push_back(keyframe);
    }
    return true;
}

void insertKnown(QJsonObject *json, const QString &key, const std::optional<double> &value)
{
    if (value)
        json->insert(key, *value);
}

QJsonObject effectJson(const HjifEffect &effect, bool withId)
{
    QJsonObject json{{QStringLiteral("effect_type"), HjifDocument::effectTypeName(effect.type)},
                     {QStringLiteral("position"), effect.position}};
    if (withId || effect.type == HjifEffect::Type::Reference)
        json.insert(QStringLiteral("id"), effect.id);
    if (effect.type == HjifEffect::Type::Reference)
        return json;
    if (!effect.baseSignal.isEmpty())
        json.insert(QStringLiteral("base_signal"), effect.baseSignal);
    if (!effect.semantic.isEmpty())
        json.insert(QStringLiteral("semantic_keywords"), effect.semantic);
    QJsonArray keyframes;
    for (const HjifKeyframe &k : effect.keyframes) {
        QJsonObject keyframe{{QStringLiteral("relative_position"), k.position}};
        if (k.amplitude)
            keyframe.insert(QStringLiteral("amplitude_modulation"), *k.amplitude);
        if (k.frequency)
            keyframe.insert(QStringLiteral("frequency_modulation"), *k.frequency);
        keyframes.append(keyframe);
    }
    json.insert(QStringLiteral("keyframes"), keyframes);
    return json;
}

} // namespace

bool HjifDocument::fromJson(const QJsonObject &json, const QString &file, HjifDocument *document,
                            QStringList *warnings, LoadError *error)
{
    HjifReader reader(file, warnings);
    *document = HjifDocument();
    const bool read = reader.read(json, document);
    reader.reportUnknownKeys();
    if (read)
        return true;
    *error = reader.error();
    return false;
}

QJsonObject HjifDocument::toJson() const
{
    QJsonArray perceptionsJson;
    for (const HjifPerception &p : perceptions) {
        QJsonArray library;
        for (const HjifEffect &effect : p.library)
            library.append(effectJson(effect, true));
        QJsonArray devices;
        for (const HjifReferenceDevice &d : p.devices) {
            QJsonObject device{{QStringLiteral("id"), d.id}, {QStringLiteral("name"), d.name}};
            if (d.bodyPartMask)
                device.insert(QStringLiteral("body_part_mask"), qint64(*d.bodyPartMask));
            insertKnown(&device, QStringLiteral("minimum_frequency"), d.minimumFrequency);
            insertKnown(&device, QStringLiteral("maximum_frequency"), d.maximumFrequency);
            insertKnown(&device, QStringLiteral("resonance_frequency"), d.resonanceFrequency);
            insertKnown(&device, QStringLiteral("maximum_amplitude"), d.maximumAmplitude);
            insertKnown(&device, QStringLiteral("maximum_displacement"), d.maximumDisplacement);
            insertKnown(&device, QStringLiteral("weight"), d.weight);
            insertKnown(&device, QStringLiteral("size"), d.size);
            if (!d.type.isEmpty())
                device.insert(QStringLiteral("type"), d.type);
            devices.append(device);
        }
        QJsonArray channels;
        for (const HjifChannel &c : p.channels) {
            QJsonArray bands;
            for (const HjifBand &b : c.bands) {
                QJsonArray effects;
                for (const HjifEffect &effect : b.effects)
                    effects.append(effectJson(effect, false));
                QJsonObject band{{QStringLiteral("band_type"), bandTypeName(b.type)},
                                 {QStringLiteral("lower_frequency_limit"), b.lowerFrequency},
                                 {QStringLiteral("upper_frequency_limit"), b.upperFrequency},
                                 {QStringLiteral("effects"), effects}};
                if (!b.curveType.isEmpty())
                    band.insert(QStringLiteral("curve_type"), b.curveType);
                bands.append(band);
            }
            QJsonObject channel{{QStringLiteral("id"), c.id},
                                {QStringLiteral("description"), c.description},
                                {QStringLiteral("gain"), c.gain},
                                {QStringLiteral("mixing_coefficient"), c.mixingCoefficient},
                                {QStringLiteral("body_part_mask"), qint64(c.bodyPartMask)},
                                {QStringLiteral("bands"), bands}};
            if (c.referenceDevice)
                channel.insert(QStringLiteral("reference_device_id"), *c.referenceDevice);
            channels.append(channel);
        }
        perceptionsJson.append(QJsonObject{{QStringLiteral("id"), p.id},
                                           {QStringLiteral("avatar_id"), p.avatarId},
                                           {QStringLiteral("description"), p.description},
                                           {QStringLiteral("perception_modality"), p.modality},
                                           {QStringLiteral("reference_devices"), devices},
                                           {QStringLiteral("effect_library"), library},
                                           {QStringLiteral("channels"), channels}});
    }
    return {{QStringLiteral("version"), version},
            {QStringLiteral("profile"), profile},
            {QStringLiteral("level"), level},
            {QStringLiteral("date"), date},
            {QStringLiteral("description"), description},
            {QStringLiteral("timescale"), timescale},
            {QStringLiteral("avatars"), QJsonArray()},
            {QStringLiteral("perceptions"), perceptionsJson},
            {QStringLiteral("syncs"), QJsonArray()}};
}

const HjifPerception *HjifDocument::perception(int id) const
{
    for (const HjifPerception &p : perceptions) {
        if (p.id == id)
            return &p;
    }
    return nullptr;
}

QString HjifDocument::bandTypeName(HjifBand::Type type)
{
    switch (type) {
    case HjifBand::Type::Transient:
        return QStringLiteral("Transient");
    case HjifBand::Type::Curve:
        return QStringLiteral("Curve");
    case HjifBand::Type::VectorialWave:
        return QStringLiteral("VectorialWave");
    case HjifBand::Type::WaveletWave:
        break;
    }
    return QStringLiteral("WaveletWave");
}

QString HjifDocument::effectTypeName(HjifEffect::Type type)
{
    switch (type) {
    case HjifEffect::Type::Basis:
        return QStringLiteral("Basis");
    case HjifEffect::Type::Reference:
        return QStringLiteral("Reference");
    case HjifEffect::Type::Composite:
        break;
    }
    return QStringLiteral("Composite");
}

const QStringList &HjifDocument::modalities()
{
    static const QStringList names{
        QStringLiteral("Other"), QStringLiteral("Pressure"), QStringLiteral("Acceleration"),
        QStringLiteral("Velocity"), QStringLiteral("Position"), QStringLiteral("Temperature"),
        QStringLiteral("Vibrotactile"), QStringLiteral("Water"), QStringLiteral("Wind"),
        QStringLiteral("Force"), QStringLiteral("Vibrotactile Texture"),
        QStringLiteral("Stiffness"), QStringLiteral("Friction"), QStringLiteral("Electrotactile"),
        // Older spellings the reference software still reads.
        QStringLiteral("Vibration"), QStringLiteral("Kinesthetic"), QStringLiteral("Texture")};
    return names;
}

const QStringList &HjifDocument::baseSignals()
{
    static const QStringList names{QStringLiteral("Sine"), QStringLiteral("Square"),
                                   QStringLiteral("Triangle"), QStringLiteral("SawToothUp"),
                                   QStringLiteral("SawToothDown")};
    return names;
}

const QStringList &HjifDocument::curveTypes()
{
    static const QStringList names{QStringLiteral("Unknown"), QStringLiteral("Cubic"),
                                   QStringLiteral("Linear"),  QStringLiteral("Akima"),
                                   QStringLiteral("Bezier"),  QStringLiteral("Bspline")};
    return names;
}

const QStringList &HjifDocument::actuatorTypes()
{
    static const QStringList names{QStringLiteral("Unknown"), QStringLiteral("LRA"),
                                   QStringLiteral("VCA"), QStringLiteral("ERM"),
                                   QStringLiteral("Piezo")};
    return names;
}

} // namespace semhap
