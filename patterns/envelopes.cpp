// SPDX-License-Identifier: MIT
#include "envelopes.h"

#include <QJsonArray>
#include <QJsonObject>

#include <algorithm>

namespace semhap {

StartValue StartValue::peak()
{
    StartValue s;
    s.m_kind = Kind::Peak;
    return s;
}

StartValue StartValue::value(Number number)
{
    StartValue s;
    s.m_kind = Kind::Value;
    s.m_number = std::move(number);
    return s;
}

double StartValue::resolve(const WaveformContext &ctx) const
{
    switch (m_kind) {
    case Kind::Current:
        return ctx.from;
    case Kind::Peak:
        return ctx.peak;
    case Kind::Value:
        break;
    }
    return m_number.value(ctx.params);
}

QJsonValue StartValue::toJson(const ParamTable &params) const
{
    switch (m_kind) {
    case Kind::Current:
        return QStringLiteral("current");
    case Kind::Peak:
        return QStringLiteral("peak");
    case Kind::Value:
        break;
    }
    return m_number.toJson(params);
}

QString ConstWaveform::type() const
{
    return QStringLiteral("const");
}

double ConstWaveform::sample(const WaveformContext &ctx) const
{
    return m_value.value(ctx.params);
}

QJsonValue ConstWaveform::toJson(const ParamTable &params) const
{
    return QJsonObject{{QStringLiteral("type"), type()},
                       {QStringLiteral("value"), m_value.toJson(params)}};
}

QString ParamWaveform::type() const
{
    return QStringLiteral("param");
}

double ParamWaveform::sample(const WaveformContext &ctx) const
{
    return m_value.value(ctx.params);
}

QJsonValue ParamWaveform::toJson(const ParamTable &params) const
{
    // The Number's object form names the parameter "param"; the waveform form calls it "name".
    QJsonObject o = m_value.toJson(params).toObject();
    o.insert(QStringLiteral("name"), o.take(QStringLiteral("param")));
    o.insert(QStringLiteral("type"), type());
    return o;
}

QString RampWaveform::type() const
{
    return QStringLiteral("ramp");
}

double RampWaveform::sample(const WaveformContext &ctx) const
{
    const double to = m_to.value(ctx.params);
    const double time = duration(ctx.params);
    if (ctx.t >= time)
        return to;
    const double start = m_from.resolve(ctx);
    return start + (to - start) * std::max(ctx.t, 0.0) / time;
}

double RampWaveform::duration(const double *params) const
{
    return std::max(m_time.value(params), 0.0);
}

QJsonValue RampWaveform::toJson(const ParamTable &params) const
{
    QJsonObject o{{QStringLiteral("type"), type()},
                  {QStringLiteral("to"), m_to.toJson(params)},
                  {QStringLiteral("time"), m_time.toJson(params)}};
    if (m_from.kind() != StartValue::Kind::Current)
        o.insert(QStringLiteral("from"), m_from.toJson(params));
    return o;
}

QString KeyframesWaveform::type() const
{
    return QStringLiteral("keyframes");
}

double KeyframesWaveform::sample(const WaveformContext &ctx) const
{
    const auto upper = std::upper_bound(m_points.begin(), m_points.end(), ctx.t,
                                        [](double t, const auto &p) { return t < p.first; });
    if (upper == m_points.end())
        return m_points.back().second;
    const auto &[t1, v1] = *upper;
    double t0 = 0.0;
    double v0 = 0.0;
    if (upper == m_points.begin()) {
        // Before the first point: the implicit knot (0, start value).
        if (ctx.t < 0.0)
            return m_from.resolve(ctx);
        v0 = m_from.resolve(ctx);
    } else {
        t0 = (upper - 1)->first;
        v0 = (upper - 1)->second;
    }
    return v0 + (v1 - v0) * (ctx.t - t0) / (t1 - t0);
}

double KeyframesWaveform::duration(const double *) const
{
    return m_points.back().first;
}

QJsonValue KeyframesWaveform::toJson(const ParamTable &params) const
{
    QJsonArray points;
    for (const auto &[t, v] : m_points)
        points.append(QJsonArray{t, v});
    QJsonObject o{{QStringLiteral("type"), type()}, {QStringLiteral("points"), points}};
    if (m_from.kind() != StartValue::Kind::Current)
        o.insert(QStringLiteral("from"), m_from.toJson(params));
    return o;
}

} // namespace semhap
