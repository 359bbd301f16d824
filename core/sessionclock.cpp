// SPDX-License-Identifier: MIT
#include "sessionclock.h"

#include "sessioninfo.h"

#include <QJsonArray>
#include <QJsonDocument>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace semhap {

double SessionClock::now()
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

bool SessionClock::fromInfo(const SessionInfo &info, SessionClock *clock, QString *error)
{
    clock->m_samples.clear();
    const auto it = info.extra.constFind(QLatin1String(MetadataKey));
    if (it == info.extra.constEnd())
        return true;
    const QString where = QLatin1String(MetadataKey) + QStringLiteral(": ");
    QJsonParseError parse{};
    const QJsonDocument document = QJsonDocument::fromJson(it.value().toUtf8(), &parse);
    if (!document.isArray()) {
        *error = where + QStringLiteral("not a JSON array of [t, steady] pairs");
        return false;
    }
    const QJsonArray pairs = document.array();
    for (int i = 0; i < pairs.size(); ++i) {
        const QJsonArray pair = pairs.at(i).toArray();
        const Sample sample{pair.at(0).toDouble(qQNaN()), pair.at(1).toDouble(qQNaN())};
        if (pair.size() != 2 || !std::isfinite(sample.t) || !std::isfinite(sample.steady)) {
            *error = where + QStringLiteral("pair %1 is not two numbers").arg(i + 1);
            return false;
        }
        if (!clock->m_samples.empty() && (sample.t < clock->m_samples.back().t ||
                                          sample.steady < clock->m_samples.back().steady)) {
            *error = where + QStringLiteral("pair %1 goes back in time").arg(i + 1);
            return false;
        }
        clock->m_samples.push_back(sample);
    }
    return true;
}

QByteArray SessionClock::toJson(const std::vector<Sample> &samples)
{
    QJsonArray pairs;
    for (const Sample &sample : samples)
        pairs.append(QJsonArray{sample.t, sample.steady});
    return QJsonDocument(pairs).toJson(QJsonDocument::Compact);
}

double SessionClock::rate() const
{
    if (m_samples.size() < 2)
        return 1.0;
    const double steady = m_samples.back().steady - m_samples.front().steady;
    const double t = m_samples.back().t - m_samples.front().t;
    return steady > 0.0 ? t / steady : 1.0;
}

bool SessionClock::followsClock() const
{
    return !m_samples.empty() && rate() <= 1.0 + MaxRateError;
}

double SessionClock::toSteady(double t) const
{
    if (t <= m_samples.front().t)
        return m_samples.front().steady + (t - m_samples.front().t);
    if (t >= m_samples.back().t)
        return m_samples.back().steady + (t - m_samples.back().t);
    // The first sample after t; the one before it is earlier (t > front().t).
    const auto after = std::upper_bound(m_samples.begin(), m_samples.end(), t,
                                        [](double value, const Sample &s) { return value < s.t; });
    const Sample &a = *(after - 1);
    const Sample &b = *after;
    return a.steady + (t - a.t) / (b.t - a.t) * (b.steady - a.steady);
}

} // namespace semhap
