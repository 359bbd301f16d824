// SPDX-License-Identifier: MIT
#include "ahapformat.h"

#include "jsonreader.h"

#include <QJsonArray>

#include <algorithm>
#include <cmath>

namespace semhap {

namespace {

/** One haptic event's parameters, with Core Haptics' defaults. */
struct EventParameters
{
    double intensity = 1.0;
    double sharpness = -1.0; ///< < 0: the event says nothing of it
    double attack = 0.0;
    double decay = 0.0;
    double release = 0.0;
    bool sustained = true;
};

/** A change of the intensity control: a step (Parameter) or a curve from its start. */
struct Control
{
    double start = 0.0;
    EnvelopeCurve curve;
};

class AhapReader : public JsonReader
{
public:
    AhapReader(const QString &file, QStringList *warnings)
        : JsonReader(file), m_file(file), m_warnings(warnings)
    {}

    bool read(const QJsonObject &json, HapticTimeline *timeline);

private:
    void warn(const QString &pointer, const QString &reason)
    {
        if (m_warnings)
            m_warnings->append(LoadError::at(m_file, pointer, reason).toString());
    }
    bool unit(const QJsonValue &value, const QString &pointer, double *out);
    bool nonNegative(const QJsonObject &object, const QString &pointer, QLatin1String key,
                     double *out, bool required);
    bool readEntry(const QJsonValue &json, const QString &pointer);
    bool readEvent(const QJsonObject &event, const QString &pointer);
    bool readParameters(const QJsonObject &event, const QString &pointer, EventParameters *out);
    bool readCurve(const QJsonObject &curve, const QString &pointer);
    bool readParameter(const QJsonObject &parameter, const QString &pointer);
    EnvelopeCurve controlCurve() const;

    QString m_file;
    QStringList *m_warnings;
    std::vector<EnvelopeCurve> m_events; ///< each event's shape, merged once all are read
    std::vector<Control> m_controls;
    double m_sharpnessWeight = 0.0;
    double m_sharpnessSum = 0.0;
};

bool AhapReader::unit(const QJsonValue &value, const QString &pointer, double *out)
{
    if (!finiteNumber(value, pointer, out))
        return false;
    if (*out < 0.0 || *out > 1.0)
        return fail(pointer, QStringLiteral("must be within [0, 1], got %1").arg(*out));
    return true;
}

bool AhapReader::nonNegative(const QJsonObject &object, const QString &pointer, QLatin1String key,
                             double *out, bool required)
{
    if (!number(object, pointer, key, out, required))
        return false;
    if (*out < 0.0)
        return fail(jsonPointerChild(pointer, key),
                    QStringLiteral("must not be negative, got %1").arg(*out));
    return true;
}

bool AhapReader::read(const QJsonObject &json, HapticTimeline *timeline)
{
    ignoreUnknownKeys(
        json, QString(),
        {QLatin1String("Version"), QLatin1String("Metadata"), QLatin1String("Pattern")},
        m_warnings);
    QJsonArray pattern;
    if (!array(json, QString(), QLatin1String("Pattern"), &pattern))
        return false;
    const QString at = QStringLiteral("/Pattern");
    for (int i = 0; i < pattern.size(); ++i) {
        if (!readEntry(pattern.at(i), jsonPointerChild(at, i)))
            return false;
    }
    std::stable_sort(m_controls.begin(), m_controls.end(),
                     [](const Control &a, const Control &b) { return a.start < b.start; });
    EnvelopeCurve envelope = EnvelopeCurve::combine(
        EnvelopeCurve::maximum(std::move(m_events)), controlCurve(), HapticTimeline::CombineStep,
        [](double event, double control) { return std::clamp(event * control, 0.0, 1.0); });
    timeline->intensity = envelope.simplified(HapticTimeline::SimplifyTolerance / 4);
    timeline->sharpness = m_sharpnessWeight > 0 ? m_sharpnessSum / m_sharpnessWeight : -1.0;
    return true;
}

bool AhapReader::readEntry(const QJsonValue &json, const QString &pointer)
{
    if (!json.isObject())
        return fail(pointer, QStringLiteral("expected an object, got ") + jsonTypeName(json));
    // Keys beside the element are ignored, as Core Haptics does; an element of none of the
    // three kinds (a misspelt "ParameterCurves") is an error, as in its own tests.
    const QJsonObject entry = json.toObject();
    const std::initializer_list<QLatin1String> kinds{
        QLatin1String("Event"), QLatin1String("ParameterCurve"), QLatin1String("Parameter")};
    ignoreUnknownKeys(entry, pointer, kinds, m_warnings);
    QString key;
    for (const QLatin1String kind : kinds) {
        if (!entry.contains(kind))
            continue;
        if (!key.isEmpty())
            return fail(pointer, QStringLiteral("holds both %1 and %2; an element is one of "
                                                "them")
                                     .arg(quoted(key), quoted(kind)));
        key = kind;
    }
    if (key.isEmpty()) {
        QStringList found;
        for (auto it = entry.begin(); it != entry.end(); ++it)
            found.append(quoted(it.key()));
        return fail(pointer, QStringLiteral("expected one of 'Event', 'ParameterCurve' or "
                                            "'Parameter'") +
                                 (found.isEmpty() ? QStringLiteral(", got an empty object")
                                                  : QStringLiteral(", got ") +
                                                        found.join(QStringLiteral(", "))));
    }
    const QString at = jsonPointerChild(pointer, key);
    const QJsonValue value = entry.value(key);
    if (!value.isObject())
        return fail(at, QStringLiteral("expected an object, got ") + jsonTypeName(value));
    if (key == QLatin1String("Event"))
        return readEvent(value.toObject(), at);
    if (key == QLatin1String("ParameterCurve"))
        return readCurve(value.toObject(), at);
    return readParameter(value.toObject(), at);
}

bool AhapReader::readEvent(const QJsonObject &event, const QString &pointer)
{
    ignoreUnknownKeys(event, pointer,
                      {QLatin1String("Time"), QLatin1String("EventType"),
                       QLatin1String("EventDuration"), QLatin1String("EventParameters"),
                       QLatin1String("EventWaveformPath"),
                       QLatin1String("EventWaveformUseVolumeEnvelope"),
                       QLatin1String("EventWaveformLoopEnabled")},
                      m_warnings);
    double time = 0.0;
    QString type;
    if (!nonNegative(event, pointer, QLatin1String("Time"), &time, true) ||
        !string(event, pointer, QLatin1String("EventType"), &type))
        return false;
    if (type == QLatin1String("AudioContinuous") || type == QLatin1String("AudioCustom")) {
        warn(pointer, QStringLiteral("ignored: audio events have no haptic equivalent"));
        return true;
    }
    const bool transient = type == QLatin1String("HapticTransient");
    if (!transient && type != QLatin1String("HapticContinuous"))
        return fail(jsonPointerChild(pointer, QLatin1String("EventType")),
                    QStringLiteral("unknown event type %1 (expected HapticTransient, "
                                   "HapticContinuous, AudioContinuous or AudioCustom)")
                        .arg(quoted(type)));
    double duration = HapticTimeline::TransientWidth;
    if (!transient &&
        !nonNegative(event, pointer, QLatin1String("EventDuration"), &duration, true))
        return false;
    EventParameters p;
    if (!readParameters(event, pointer, &p))
        return false;

    EnvelopeCurve shape;
    shape.append(time, 0.0);
    if (transient) {
        shape.append(time, p.intensity);
        shape.append(time + duration, p.intensity);
        shape.append(time + duration, 0.0);
    } else {
        // Attack, decay and release fall inside the event's duration.
        const double attack = std::min(p.attack, duration);
        shape.append(time + attack, p.intensity);
        if (p.sustained) {
            const double release = std::min(p.release, duration - attack);
            shape.append(time + duration - release, p.intensity);
        } else {
            shape.append(time + attack + std::min(p.decay, duration - attack), 0.0);
        }
        shape.append(time + duration, 0.0);
    }
    m_events.push_back(std::move(shape));
    if (p.sharpness >= 0.0) {
        m_sharpnessSum += p.sharpness * p.intensity * duration;
        m_sharpnessWeight += p.intensity * duration;
    }
    return true;
}

bool AhapReader::readParameters(const QJsonObject &event, const QString &pointer,
                                EventParameters *out)
{
    QJsonArray parameters;
    if (!array(event, pointer, QLatin1String("EventParameters"), &parameters, false))
        return false;
    const QString at = jsonPointerChild(pointer, QLatin1String("EventParameters"));
    for (int i = 0; i < parameters.size(); ++i) {
        const QString item = jsonPointerChild(at, i);
        if (!parameters.at(i).isObject())
            return fail(item, QStringLiteral("expected an object, got ") +
                                  jsonTypeName(parameters.at(i)));
        const QJsonObject parameter = parameters.at(i).toObject();
        QString id;
        double value = 0.0;
        ignoreUnknownKeys(parameter, item,
                          {QLatin1String("ParameterID"), QLatin1String("ParameterValue")},
                          m_warnings);
        if (!string(parameter, item, QLatin1String("ParameterID"), &id) ||
            !number(parameter, item, QLatin1String("ParameterValue"), &value))
            return false;
        const QString valueAt = jsonPointerChild(item, QLatin1String("ParameterValue"));
        if (id == QLatin1String("HapticIntensity")) {
            if (!unit(value, valueAt, &out->intensity))
                return false;
        } else if (id == QLatin1String("HapticSharpness")) {
            if (!unit(value, valueAt, &out->sharpness))
                return false;
        } else if (id == QLatin1String("AttackTime") || id == QLatin1String("DecayTime") ||
                   id == QLatin1String("ReleaseTime")) {
            if (value < 0)
                return fail(valueAt, QStringLiteral("must not be negative, got %1").arg(value));
            double &slot = id == QLatin1String("AttackTime")  ? out->attack
                           : id == QLatin1String("DecayTime") ? out->decay
                                                              : out->release;
            slot = value;
        } else if (id == QLatin1String("Sustained")) {
            out->sustained = value != 0.0;
        } else {
            warn(item,
                 QStringLiteral("ignored: parameter %1 has no haptic equivalent").arg(quoted(id)));
        }
    }
    return true;
}

bool AhapReader::readCurve(const QJsonObject &curve, const QString &pointer)
{
    QString id;
    double start = 0.0;
    QJsonArray points;
    ignoreUnknownKeys(curve, pointer,
                      {QLatin1String("ParameterID"), QLatin1String("Time"),
                       QLatin1String("ParameterCurveControlPoints")},
                      m_warnings);
    if (!string(curve, pointer, QLatin1String("ParameterID"), &id) ||
        !nonNegative(curve, pointer, QLatin1String("Time"), &start, true) ||
        !array(curve, pointer, QLatin1String("ParameterCurveControlPoints"), &points))
        return false;
    const QString at = jsonPointerChild(pointer, QLatin1String("ParameterCurveControlPoints"));
    if (points.isEmpty())
        return fail(at, QStringLiteral("expected at least one control point"));
    Control control{start, {}};
    for (int i = 0; i < points.size(); ++i) {
        const QString item = jsonPointerChild(at, i);
        if (!points.at(i).isObject())
            return fail(item,
                        QStringLiteral("expected an object, got ") + jsonTypeName(points.at(i)));
        const QJsonObject point = points.at(i).toObject();
        double t = 0.0;
        double value = 0.0;
        ignoreUnknownKeys(point, item, {QLatin1String("Time"), QLatin1String("ParameterValue")},
                          m_warnings);
        if (!nonNegative(point, item, QLatin1String("Time"), &t, true) ||
            !number(point, item, QLatin1String("ParameterValue"), &value))
            return false;
        if (!control.curve.isEmpty() && start + t < control.curve.endTime())
            return fail(jsonPointerChild(item, QLatin1String("Time")),
                        QStringLiteral("control point times must not decrease"));
        control.curve.append(start + t, value);
    }
    if (id != QLatin1String("HapticIntensityControl")) {
        warn(pointer, QStringLiteral("ignored: only HapticIntensityControl curves are "
                                     "converted, not %1")
                          .arg(quoted(id)));
        return true;
    }
    m_controls.push_back(std::move(control));
    return true;
}

bool AhapReader::readParameter(const QJsonObject &parameter, const QString &pointer)
{
    QString id;
    double time = 0.0;
    double value = 0.0;
    ignoreUnknownKeys(
        parameter, pointer,
        {QLatin1String("ParameterID"), QLatin1String("Time"), QLatin1String("ParameterValue")},
        m_warnings);
    if (!string(parameter, pointer, QLatin1String("ParameterID"), &id) ||
        !nonNegative(parameter, pointer, QLatin1String("Time"), &time, true) ||
        !number(parameter, pointer, QLatin1String("ParameterValue"), &value))
        return false;
    if (id != QLatin1String("HapticIntensityControl")) {
        warn(pointer, QStringLiteral("ignored: only HapticIntensityControl is converted, not %1")
                          .arg(quoted(id)));
        return true;
    }
    Control control{time, {}};
    control.curve.append(time, value);
    m_controls.push_back(std::move(control));
    return true;
}

EnvelopeCurve AhapReader::controlCurve() const
{
    // Each control holds from its start until the next one starts; before the first, 1.
    EnvelopeCurve out;
    out.append(0.0, 1.0);
    for (size_t i = 0; i < m_controls.size(); ++i) {
        const Control &control = m_controls[i];
        const bool last = i + 1 == m_controls.size();
        const double next = last ? 0.0 : m_controls[i + 1].start;
        out.append(control.start, out.value(control.start));
        for (const EnvelopePoint &p : control.curve.points()) {
            if (!last && p.t >= next)
                break;
            out.append(p.t, p.v);
        }
        if (!last)
            out.append(next, control.curve.value(next));
    }
    return out;
}

} // namespace

bool AhapFormat::read(const QJsonObject &json, const QString &file, HapticTimeline *timeline,
                      QStringList *warnings, LoadError *error)
{
    AhapReader reader(file, warnings);
    if (reader.read(json, timeline))
        return true;
    *error = reader.error();
    return false;
}

QJsonObject AhapFormat::write(const HapticTimeline &timeline, const QString &description)
{
    QJsonArray pattern;
    const std::vector<EnvelopePoint> &points = timeline.intensity.points();
    const double end = timeline.intensity.endTime();
    // Full-intensity continuous events carry the sharpness, when there is one (otherwise the
    // player's own default stands); the control curves shape them.
    QJsonArray parameters{
        QJsonObject{{QStringLiteral("ParameterID"), QStringLiteral("HapticIntensity")},
                    {QStringLiteral("ParameterValue"), 1.0}}};
    if (timeline.sharpness >= 0.0)
        parameters.append(
            QJsonObject{{QStringLiteral("ParameterID"), QStringLiteral("HapticSharpness")},
                        {QStringLiteral("ParameterValue"), timeline.sharpness}});
    for (double start = 0.0; !points.empty() && start < end; start += MaxEventDuration) {
        pattern.append(QJsonObject{
            {QStringLiteral("Event"),
             QJsonObject{
                 {QStringLiteral("Time"), start},
                 {QStringLiteral("EventType"), QStringLiteral("HapticContinuous")},
                 {QStringLiteral("EventDuration"), std::min(MaxEventDuration, end - start)},
                 {QStringLiteral("EventParameters"), parameters}}}});
    }
    // Consecutive curves share their boundary point, so the envelope has no gaps.
    for (size_t first = 0; first + 1 < points.size(); first += MaxCurvePoints - 1) {
        const size_t last = std::min(points.size(), first + MaxCurvePoints);
        QJsonArray controlPoints;
        for (size_t i = first; i < last; ++i)
            controlPoints.append(
                QJsonObject{{QStringLiteral("Time"), points[i].t - points[first].t},
                            {QStringLiteral("ParameterValue"), points[i].v}});
        pattern.append(QJsonObject{
            {QStringLiteral("ParameterCurve"),
             QJsonObject{{QStringLiteral("ParameterID"), QStringLiteral("HapticIntensityControl")},
                         {QStringLiteral("Time"), points[first].t},
                         {QStringLiteral("ParameterCurveControlPoints"), controlPoints}}}});
    }
    return QJsonObject{{QStringLiteral("Version"), 1.0},
                       {QStringLiteral("Metadata"),
                        QJsonObject{{QStringLiteral("Project"), QStringLiteral("semhap")},
                                    {QStringLiteral("Description"), description}}},
                       {QStringLiteral("Pattern"), pattern}};
}

} // namespace semhap
