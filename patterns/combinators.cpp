// SPDX-License-Identifier: MIT
#include "combinators.h"

#include <QJsonArray>
#include <QJsonObject>

#include <algorithm>

namespace semhap {

namespace {

std::vector<WaveformPtr> single(WaveformPtr in)
{
    std::vector<WaveformPtr> children;
    children.push_back(std::move(in));
    return children;
}

} // namespace

CompositeWaveform::CompositeWaveform(std::vector<WaveformPtr> children)
    : m_children(std::move(children))
{}

void CompositeWaveform::reset(double *state) const
{
    Waveform::reset(state);
    for (const WaveformPtr &child : m_children)
        child->reset(state);
}

void CompositeWaveform::assignState(int &next)
{
    Waveform::assignState(next);
    for (const WaveformPtr &child : m_children)
        child->assignState(next);
}

QJsonValue CompositeWaveform::toJson(const ParamTable &params) const
{
    QJsonArray of;
    for (const WaveformPtr &child : m_children)
        of.append(child->toJson(params));
    return QJsonObject{{QStringLiteral("type"), type()}, {QStringLiteral("of"), of}};
}

QString SumWaveform::type() const
{
    return QStringLiteral("sum");
}

double SumWaveform::sample(const WaveformContext &ctx) const
{
    double sum = 0.0;
    for (const WaveformPtr &child : m_children)
        sum += child->sample(ctx);
    return sum;
}

double SumWaveform::duration(const double *params) const
{
    double longest = 0.0;
    for (const WaveformPtr &child : m_children)
        longest = std::max(longest, child->duration(params));
    return longest;
}

QString ProductWaveform::type() const
{
    return QStringLiteral("product");
}

double ProductWaveform::sample(const WaveformContext &ctx) const
{
    double product = 1.0;
    for (const WaveformPtr &child : m_children)
        product *= child->sample(ctx);
    return product;
}

double ProductWaveform::duration(const double *params) const
{
    double shortest = Forever;
    for (const WaveformPtr &child : m_children)
        shortest = std::min(shortest, child->duration(params));
    return shortest;
}

QString SequenceWaveform::type() const
{
    return QStringLiteral("sequence");
}

double SequenceWaveform::sample(const WaveformContext &ctx) const
{
    double &index = ctx.state[m_stateOffset];
    double &childStart = ctx.state[m_stateOffset + 1];
    double &childFrom = ctx.state[m_stateOffset + 2];

    size_t current = size_t(index);
    WaveformContext child = ctx;
    child.from = current == 0 ? ctx.from : childFrom;
    double previousT = ctx.t - ctx.dt;
    bool handedOver = false;
    while (current + 1 < m_children.size()) {
        const double length = m_children[current]->duration(ctx.params);
        const double end = childStart + length;
        if (ctx.t < end - TimeTolerance)
            break;
        // Finish the child exactly at its end: its last value is where the next one starts.
        child.t = length;
        child.dt = std::max(end - std::max(previousT, childStart), 0.0);
        child.from = m_children[current]->sample(child);
        childFrom = child.from;
        childStart = end;
        previousT = end;
        ++current;
        index = double(current);
        m_children[current]->reset(ctx.state);
        handedOver = true;
    }
    child.t = ctx.t - childStart;
    child.dt = handedOver ? std::max(ctx.t - childStart, 0.0) : ctx.dt;
    return m_children[current]->sample(child);
}

double SequenceWaveform::duration(const double *params) const
{
    double total = 0.0;
    for (const WaveformPtr &child : m_children)
        total += child->duration(params);
    return total;
}

ScaleWaveform::ScaleWaveform(WaveformPtr in, Number gain, Number div, Number offset)
    : CompositeWaveform(single(std::move(in))), m_gain(std::move(gain)), m_div(std::move(div)),
      m_offset(std::move(offset))
{}

QString ScaleWaveform::type() const
{
    return QStringLiteral("scale");
}

double ScaleWaveform::sample(const WaveformContext &ctx) const
{
    const double in = m_children.front()->sample(ctx);
    const double div = m_div.value(ctx.params);
    const double quotient = div == 0.0 ? 0.0 : in * m_gain.value(ctx.params) / div;
    return quotient + m_offset.value(ctx.params);
}

double ScaleWaveform::duration(const double *params) const
{
    return m_children.front()->duration(params);
}

QJsonValue ScaleWaveform::toJson(const ParamTable &params) const
{
    QJsonObject o{{QStringLiteral("type"), type()},
                  {QStringLiteral("in"), m_children.front()->toJson(params)}};
    insertNumber(o, QStringLiteral("gain"), m_gain, params, 1.0);
    insertNumber(o, QStringLiteral("div"), m_div, params, 1.0);
    insertNumber(o, QStringLiteral("offset"), m_offset, params, 0.0);
    return o;
}

ClipWaveform::ClipWaveform(WaveformPtr in, Number min, Number max)
    : CompositeWaveform(single(std::move(in))), m_min(std::move(min)), m_max(std::move(max))
{}

QString ClipWaveform::type() const
{
    return QStringLiteral("clip");
}

double ClipWaveform::sample(const WaveformContext &ctx) const
{
    const double in = m_children.front()->sample(ctx);
    return std::max(m_min.value(ctx.params), std::min(m_max.value(ctx.params), in));
}

double ClipWaveform::duration(const double *params) const
{
    return m_children.front()->duration(params);
}

QJsonValue ClipWaveform::toJson(const ParamTable &params) const
{
    QJsonObject o{{QStringLiteral("type"), type()},
                  {QStringLiteral("in"), m_children.front()->toJson(params)}};
    insertNumber(o, QStringLiteral("min"), m_min, params, 0.0);
    insertNumber(o, QStringLiteral("max"), m_max, params, 1.0);
    return o;
}

} // namespace semhap
