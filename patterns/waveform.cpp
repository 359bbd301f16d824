// SPDX-License-Identifier: MIT
#include "waveform.h"

#include <QJsonArray>
#include <QJsonObject>

#include <algorithm>

namespace semhap {

ParamTable::ParamTable()
{
    declare(QStringLiteral("intensity"), 1.0);
}

int ParamTable::declare(const QString &name, double defaultValue)
{
    int index = indexOf(name);
    if (index >= 0) {
        m_defaults[size_t(index)] = defaultValue;
        return index;
    }
    m_names.push_back(name);
    m_defaults.push_back(defaultValue);
    return size() - 1;
}

int ParamTable::indexOf(const QString &name) const
{
    const auto it = std::find(m_names.begin(), m_names.end(), name);
    return it == m_names.end() ? -1 : int(it - m_names.begin());
}

Curve Curve::linear(double gain, double offset)
{
    Curve c;
    c.m_kind = Kind::Linear;
    c.m_gain = gain;
    c.m_offset = offset;
    return c;
}

Curve Curve::points(std::vector<std::pair<double, double>> points)
{
    Curve c;
    c.m_kind = Kind::Points;
    c.m_points = std::move(points);
    return c;
}

double Curve::map(double x) const
{
    switch (m_kind) {
    case Kind::Identity:
        return x;
    case Kind::Linear:
        return m_gain * x + m_offset;
    case Kind::Points:
        break;
    }
    if (m_points.empty())
        return x;
    if (x <= m_points.front().first)
        return m_points.front().second;
    if (x >= m_points.back().first)
        return m_points.back().second;
    const auto upper = std::upper_bound(m_points.begin(), m_points.end(), x,
                                        [](double v, const auto &p) { return v < p.first; });
    const auto &[x1, y1] = *upper;
    const auto &[x0, y0] = *(upper - 1);
    return y0 + (y1 - y0) * (x - x0) / (x1 - x0);
}

Number Number::bound(int param, Curve curve)
{
    Number n;
    n.m_param = param;
    n.m_curve = std::move(curve);
    return n;
}

QJsonValue Number::toJson(const ParamTable &params) const
{
    if (isConstant())
        return m_constant;
    QJsonObject o{{QStringLiteral("param"), params.name(m_param)}};
    switch (m_curve.kind()) {
    case Curve::Kind::Identity:
        break;
    case Curve::Kind::Linear:
        o.insert(QStringLiteral("gain"), m_curve.gain());
        o.insert(QStringLiteral("offset"), m_curve.offset());
        break;
    case Curve::Kind::Points: {
        QJsonArray points;
        for (const auto &[x, y] : m_curve.pointList())
            points.append(QJsonArray{x, y});
        o.insert(QStringLiteral("curve"), points);
        break;
    }
    }
    return o;
}

NumberJson NumberJson::read(const QJsonValue &json)
{
    NumberJson number;
    if (!json.isObject()) {
        number.constant = json.toDouble();
        return number;
    }
    const QJsonObject o = json.toObject();
    number.param = o.value(QLatin1String("param")).toString();
    number.gain = o.value(QLatin1String("gain")).toDouble(1.0);
    number.offset = o.value(QLatin1String("offset")).toDouble(0.0);
    number.curve = o.value(QLatin1String("curve"));
    return number;
}

QJsonValue NumberJson::toJson() const
{
    if (!isBound())
        return constant;
    QJsonObject o{{QStringLiteral("param"), param}};
    if (!curve.isUndefined()) {
        o.insert(QStringLiteral("curve"), curve);
        return o;
    }
    if (gain != 1.0)
        o.insert(QStringLiteral("gain"), gain);
    if (offset != 0.0)
        o.insert(QStringLiteral("offset"), offset);
    return o;
}

void insertNumber(QJsonObject &object, const QString &key, const Number &number,
                  const ParamTable &params, double defaultValue)
{
    if (!number.isConstant() || number.value(nullptr) != defaultValue)
        object.insert(key, number.toJson(params));
}

void Waveform::reset(double *state) const
{
    std::fill(state + m_stateOffset, state + m_stateOffset + ownStateSize(), 0.0);
}

double Waveform::duration(const double *) const
{
    return Forever;
}

void Waveform::assignState(int &next)
{
    m_stateOffset = next;
    next += ownStateSize();
}

} // namespace semhap
