// SPDX-License-Identifier: MIT
#include "metahapticformat.h"

#include "jsonreader.h"

#include <QJsonArray>

#include <algorithm>

namespace semhap {

namespace {

class MetaHapticReader : public JsonReader
{
public:
    MetaHapticReader(const QString &file, QStringList *warnings)
        : JsonReader(file), m_file(file), m_warnings(warnings)
    {}

    bool read(const QJsonObject &json, HapticTimeline *timeline);

private:
    /** Reads `[{time, KEY}, …]`, times not decreasing, values in [0, 1]. */
    bool readEnvelope(const QJsonArray &points, const QString &pointer, QLatin1String key,
                      EnvelopeCurve *curve, EnvelopeCurve *emphasis);
    bool unitKey(const QJsonObject &object, const QString &pointer, QLatin1String key,
                 double *out);

    QString m_file;
    QStringList *m_warnings;
};

bool MetaHapticReader::unitKey(const QJsonObject &object, const QString &pointer,
                               QLatin1String key, double *out)
{
    if (!number(object, pointer, key, out))
        return false;
    if (*out < 0.0 || *out > 1.0)
        return fail(jsonPointerChild(pointer, key),
                    QStringLiteral("must be within [0, 1], got %1").arg(*out));
    return true;
}

bool MetaHapticReader::read(const QJsonObject &json, HapticTimeline *timeline)
{
    ignoreUnknownKeys(
        json, QString(),
        {QLatin1String("version"), QLatin1String("metadata"), QLatin1String("signals")},
        m_warnings);
    QJsonObject version;
    QJsonObject signalsObject;
    QJsonObject continuous;
    QJsonObject envelopes;
    QJsonArray amplitude;
    QJsonArray frequency;
    const QString signalsAt = QStringLiteral("/signals");
    const QString continuousAt = QStringLiteral("/signals/continuous");
    const QString envelopesAt = QStringLiteral("/signals/continuous/envelopes");
    if (!object(json, QString(), QLatin1String("version"), &version) ||
        !object(json, QString(), QLatin1String("signals"), &signalsObject) ||
        !object(signalsObject, signalsAt, QLatin1String("continuous"), &continuous) ||
        !object(continuous, continuousAt, QLatin1String("envelopes"), &envelopes) ||
        !array(envelopes, envelopesAt, QLatin1String("amplitude"), &amplitude) ||
        !array(envelopes, envelopesAt, QLatin1String("frequency"), &frequency, false))
        return false;
    ignoreUnknownKeys(signalsObject, signalsAt, {QLatin1String("continuous")}, m_warnings);
    ignoreUnknownKeys(continuous, continuousAt, {QLatin1String("envelopes")}, m_warnings);
    ignoreUnknownKeys(envelopes, envelopesAt,
                      {QLatin1String("amplitude"), QLatin1String("frequency")}, m_warnings);
    ignoreUnknownKeys(version, QStringLiteral("/version"),
                      {QLatin1String("major"), QLatin1String("minor"), QLatin1String("patch")},
                      m_warnings);
    double major = 0.0;
    if (!number(version, QStringLiteral("/version"), QLatin1String("major"), &major))
        return false;
    if (major != 1.0)
        return fail(QStringLiteral("/version/major"),
                    QStringLiteral("unsupported version %1, expected 1").arg(major));

    EnvelopeCurve envelope;
    EnvelopeCurve emphasis;
    EnvelopeCurve pitch;
    if (!readEnvelope(amplitude, jsonPointerChild(envelopesAt, QLatin1String("amplitude")),
                      QLatin1String("amplitude"), &envelope, &emphasis) ||
        !readEnvelope(frequency, jsonPointerChild(envelopesAt, QLatin1String("frequency")),
                      QLatin1String("frequency"), &pitch, nullptr))
        return false;
    // An emphasis is a short pulse on top of the envelope, as a transient is in AHAP.
    timeline->intensity = EnvelopeCurve::maximum({envelope, emphasis})
                              .simplified(HapticTimeline::SimplifyTolerance / 4);
    // The frequency, weighted by the amplitude at each instant.
    double sum = 0.0;
    double weight = 0.0;
    if (!pitch.isEmpty()) {
        // Both are straight between breakpoints: Simpson's rule is exact for the product.
        const std::vector<double> times =
            EnvelopeCurve::breakpoints({&timeline->intensity, &pitch});
        for (size_t i = 1; i < times.size(); ++i) {
            const double t0 = times[i - 1];
            const double t1 = times[i];
            const double mid = (t0 + t1) / 2;
            const double a0 = timeline->intensity.value(t0);
            const double a1 = timeline->intensity.valueBefore(t1);
            const double am = timeline->intensity.value(mid);
            sum += (t1 - t0) / 6 *
                   (a0 * pitch.value(t0) + 4 * am * pitch.value(mid) + a1 * pitch.valueBefore(t1));
            weight += (t1 - t0) / 6 * (a0 + 4 * am + a1);
        }
    }
    timeline->sharpness = weight > 0 ? sum / weight : (pitch.isEmpty() ? -1.0 : pitch.value(0));
    return true;
}

bool MetaHapticReader::readEnvelope(const QJsonArray &points, const QString &pointer,
                                    QLatin1String key, EnvelopeCurve *curve,
                                    EnvelopeCurve *emphasis)
{
    for (int i = 0; i < points.size(); ++i) {
        const QString item = jsonPointerChild(pointer, i);
        if (!points.at(i).isObject())
            return fail(item,
                        QStringLiteral("expected an object, got ") + jsonTypeName(points.at(i)));
        const QJsonObject point = points.at(i).toObject();
        double t = 0.0;
        double value = 0.0;
        if (emphasis)
            ignoreUnknownKeys(point, item, {QLatin1String("time"), key, QLatin1String("emphasis")},
                              m_warnings);
        else
            ignoreUnknownKeys(point, item, {QLatin1String("time"), key}, m_warnings);
        if (!number(point, item, QLatin1String("time"), &t) || !unitKey(point, item, key, &value))
            return false;
        if (t < 0.0)
            return fail(jsonPointerChild(item, QLatin1String("time")),
                        QStringLiteral("must not be negative, got %1").arg(t));
        if (!curve->isEmpty() && t < curve->endTime())
            return fail(jsonPointerChild(item, QLatin1String("time")),
                        QStringLiteral("times must not decrease"));
        curve->append(t, value);
        QJsonObject accent;
        if (!emphasis || !object(point, item, QLatin1String("emphasis"), &accent, false))
            continue;
        if (accent.isEmpty())
            continue;
        const QString accentAt = jsonPointerChild(item, QLatin1String("emphasis"));
        double strength = 0.0;
        double accentFrequency = 0.0;
        ignoreUnknownKeys(accent, accentAt,
                          {QLatin1String("amplitude"), QLatin1String("frequency")}, m_warnings);
        if (!unitKey(accent, accentAt, QLatin1String("amplitude"), &strength) ||
            !unitKey(accent, accentAt, QLatin1String("frequency"), &accentFrequency))
            return false;
        if (!emphasis->isEmpty() && t < emphasis->endTime())
            t = emphasis->endTime(); // overlapping emphases follow one another
        emphasis->append(t, 0.0);
        emphasis->append(t, strength);
        emphasis->append(t + HapticTimeline::TransientWidth, strength);
        emphasis->append(t + HapticTimeline::TransientWidth, 0.0);
    }
    return true;
}

} // namespace

bool MetaHapticFormat::read(const QJsonObject &json, const QString &file, HapticTimeline *timeline,
                            QStringList *warnings, LoadError *error)
{
    MetaHapticReader reader(file, warnings);
    if (reader.read(json, timeline))
        return true;
    *error = reader.error();
    return false;
}

QJsonObject MetaHapticFormat::write(const HapticTimeline &timeline, const QString &description)
{
    QJsonArray amplitude;
    for (const EnvelopePoint &p : timeline.intensity.points())
        amplitude.append(
            QJsonObject{{QStringLiteral("time"), p.t}, {QStringLiteral("amplitude"), p.v}});
    QJsonArray frequency;
    const double value = timeline.sharpness;
    if (!timeline.intensity.isEmpty() && value >= 0) {
        frequency.append(QJsonObject{{QStringLiteral("time"), timeline.intensity.startTime()},
                                     {QStringLiteral("frequency"), value}});
        frequency.append(QJsonObject{{QStringLiteral("time"), timeline.intensity.endTime()},
                                     {QStringLiteral("frequency"), value}});
    }
    return QJsonObject{
        {QStringLiteral("version"), QJsonObject{{QStringLiteral("major"), 1},
                                                {QStringLiteral("minor"), 0},
                                                {QStringLiteral("patch"), 0}}},
        {QStringLiteral("metadata"),
         QJsonObject{{QStringLiteral("editor"), QStringLiteral("semhap")},
                     {QStringLiteral("description"), description}}},
        {QStringLiteral("signals"),
         QJsonObject{{QStringLiteral("continuous"),
                      QJsonObject{{QStringLiteral("envelopes"),
                                   QJsonObject{{QStringLiteral("amplitude"), amplitude},
                                               {QStringLiteral("frequency"), frequency}}}}}}}};
}

} // namespace semhap
