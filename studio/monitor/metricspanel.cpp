// SPDX-License-Identifier: MIT
#include "metricspanel.h"

#include "metricspec.h"
#include "runhistory.h"

#include <QCoreApplication>
#include <QFormLayout>
#include <QJsonArray>
#include <QJsonObject>
#include <QLabel>
#include <QLocale>
#include <QScrollArea>
#include <QVBoxLayout>

#include <cmath>
#include <utility>
#include <vector>

namespace semhap {

namespace {

/** The context the metric table's labels and help are translated in (metricspec.h). */
constexpr const char *MetricContext = "semhap::MetricSpec";

/** What an unknown key most likely holds, from its spelling and value. */
MetricUnit guessUnit(const QString &key, double value)
{
    if (key.endsWith(QLatin1String("_seconds")) || key.endsWith(QLatin1String("_time")))
        return MetricUnit::Seconds;
    if (key.endsWith(QLatin1String("_share")))
        return MetricUnit::Share;
    if (value == std::floor(value) && std::abs(value) < 1e15)
        return MetricUnit::Count;
    return MetricUnit::Ratio;
}

using Flat = std::vector<std::pair<QString, QJsonValue>>;

void flatten(const QJsonObject &object, const QString &prefix, Flat *out)
{
    for (auto it = object.begin(); it != object.end(); ++it) {
        const QString key = prefix + it.key();
        if (it->isObject())
            flatten(it->toObject(), key + QLatin1Char('.'), out);
        else
            out->emplace_back(key, *it);
    }
}

/** The known keys first, in the table's order, then the others by name. */
Flat ordered(const QJsonObject &metrics)
{
    Flat all;
    flatten(metrics, QString(), &all);
    Flat out;
    for (const MetricSpec &metric : MetricSpec::all()) {
        for (const auto &entry : all) {
            if (entry.first == QLatin1String(metric.name))
                out.push_back(entry);
        }
    }
    for (const auto &entry : all) {
        if (!MetricSpec::find(entry.first))
            out.push_back(entry);
    }
    return out;
}

} // namespace

MetricsPanel::MetricsPanel(RunHistory &history, QWidget *parent)
    : QWidget(parent), m_history(history),
      m_empty(new QLabel(tr("No metrics yet: they appear while a task runs."), this))
{
    auto *content = new QWidget;
    m_form = new QFormLayout(content);
    m_form->setFieldGrowthPolicy(QFormLayout::ExpandingFieldsGrow);
    m_form->setLabelAlignment(Qt::AlignLeft);
    auto *scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidget(content);
    m_empty->setWordWrap(true);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addWidget(m_empty);
    layout->addWidget(scroll, 1);
    connect(&history, &RunHistory::metricsChanged, this, &MetricsPanel::refresh);
    connect(&history, &RunHistory::reset, this, &MetricsPanel::refresh);
    refresh();
}

QString MetricsPanel::label(const QString &key)
{
    const MetricSpec *metric = MetricSpec::find(key);
    return metric ? QCoreApplication::translate(MetricContext, metric->label) : key;
}

QString MetricsPanel::tooltip(const QString &key)
{
    const MetricSpec *metric = MetricSpec::find(key);
    if (!metric)
        return key;
    QString unit;
    switch (metric->unit) {
    case MetricUnit::Count:
        unit = tr("a count");
        break;
    case MetricUnit::Ratio:
        unit = tr("a ratio");
        break;
    case MetricUnit::Factor:
        unit = tr("times real time");
        break;
    case MetricUnit::Seconds:
        unit = tr("seconds of simulated time");
        break;
    case MetricUnit::Newtons:
        unit = tr("newtons (N)");
        break;
    case MetricUnit::Share:
        unit = tr("a share, 0 to 100 %");
        break;
    case MetricUnit::Text:
        break;
    }
    QString text = QCoreApplication::translate(MetricContext, metric->help);
    if (metric->better == MetricBetter::Higher)
        text += QLatin1Char(' ') + tr("Higher is better.");
    else if (metric->better == MetricBetter::Lower)
        text += QLatin1Char(' ') + tr("Lower is better.");
    return unit.isEmpty() ? tr("%1\nIn exports: %2").arg(text, key)
                          : tr("%1\nIn %2; in exports: %3").arg(text, unit, key);
}

QString MetricsPanel::format(const QString &key, const QJsonValue &value)
{
    if (value.isNull() || value.isUndefined())
        return tr("n/a");
    if (value.isBool())
        return value.toBool() ? tr("yes") : tr("no");
    if (value.isString())
        return value.toString();
    if (value.isArray()) {
        QStringList parts;
        for (const QJsonValue &item : value.toArray())
            parts.append(format(key, item));
        return parts.join(QStringLiteral(", "));
    }
    const double number = value.toDouble();
    const MetricSpec *metric = MetricSpec::find(key);
    switch (metric ? metric->unit : guessUnit(key, number)) {
    case MetricUnit::Count:
        return QLocale().toString(std::llround(number));
    case MetricUnit::Ratio:
        return QLocale().toString(number, 'f', 2);
    case MetricUnit::Factor:
        return tr("%1×").arg(QLocale().toString(number, 'f', 2));
    case MetricUnit::Seconds:
        return tr("%1 s").arg(QLocale().toString(number, 'f', 2));
    case MetricUnit::Newtons:
        return tr("%1 N").arg(QLocale().toString(number, 'f', 2));
    case MetricUnit::Share:
        return tr("%1 %").arg(QLocale().toString(number * 100.0, 'f', 0));
    case MetricUnit::Text:
        return value.toVariant().toString();
    }
    return QString();
}

void MetricsPanel::refresh()
{
    const Flat metrics = ordered(m_history.metrics());
    QStringList keys;
    for (const auto &entry : metrics)
        keys.append(entry.first);
    if (keys != m_keys) {
        while (m_form->rowCount() > 0)
            m_form->removeRow(0);
        for (const QString &key : keys) {
            auto *value = new QLabel;
            value->setObjectName(key);
            value->setTextInteractionFlags(Qt::TextSelectableByMouse);
            auto *name = new QLabel(label(key));
            name->setToolTip(tooltip(key));
            value->setToolTip(name->toolTip());
            m_form->addRow(name, value);
        }
        m_keys = keys;
    }
    for (int row = 0; row < int(metrics.size()); ++row) {
        auto *value = static_cast<QLabel *>(m_form->itemAt(row, QFormLayout::FieldRole)->widget());
        value->setText(format(metrics[size_t(row)].first, metrics[size_t(row)].second));
    }
    m_empty->setVisible(metrics.empty());
}

PanelDock MetricsPanel::dock()
{
    return {QStringLiteral("metricsDock"), tr("Task metrics"), PanelDock::Side::Bottom,
            QStringLiteral("devicesDock")};
}

} // namespace semhap
