// SPDX-License-Identifier: MIT
#include "metricspanel.h"

#include "runhistory.h"

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

enum class Kind
{
    Count,
    Ratio,
    Factor,
    Seconds,
    Newtons,
    Share,
    Text
};

struct KnownMetric
{
    const char *key;
    const char *label;
    Kind kind;
};

// docs/metrics.md, in the order a reader looks for them.
const KnownMetric Known[] = {
    {"completion_time", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Completion time"),
     Kind::Seconds},
    {"cubes_transferred", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Cubes transferred"),
     Kind::Count},
    {"cubes_broken", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Cubes broken"), Kind::Count},
    {"cubes_dropped", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Cubes dropped (slipped out)"),
     Kind::Count},
    {"grasps", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Grasps"), Kind::Count},
    {"grasps_per_transfer", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Grasps per transfer"),
     Kind::Ratio},
    {"average_grasp_force", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Average grasp force"),
     Kind::Newtons},
    {"average_peak_grasp_force",
     QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Average peak grasp force"), Kind::Newtons},
    {"warning_lead_time", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Warning lead time"),
     Kind::Seconds},
    {"breaks_warned_share", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Breaks warned"),
     Kind::Share},
    {"breaks_warned_in_time_share",
     QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Breaks warned in time"), Kind::Share},
    {"containers_dropped", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Containers dropped"),
     Kind::Count},
    {"drop_warning_lead_time", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Drop warning lead time"),
     Kind::Seconds},
    {"drops_warned_share", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Drops warned"), Kind::Share},
    {"drops_warned_in_time_share",
     QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Drops warned in time"), Kind::Share},
    {"transfers_per_container_cycle",
     QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Transfers per container cycle"), Kind::Ratio},
    {"confirmations_per_grasp",
     QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Confirmations felt per grasp"), Kind::Ratio},
    {"slip_episodes", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Slip episodes"), Kind::Count},
    {"warnings_per_slip_episode",
     QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Warnings felt per slip episode"), Kind::Ratio},
    {"box_refills", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Cube box refills"), Kind::Count},
    {"insertions", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Plugs inserted"), Kind::Count},
    {"time_to_insert", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Time to insert"), Kind::Seconds},
    {"collisions", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Collisions with the port"),
     Kind::Count},
    {"peak_insertion_force", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Peak insertion force"),
     Kind::Newtons},
    {"plug_pickups", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Plug pick-ups"), Kind::Count},
    {"plugs_dropped", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Plugs dropped"), Kind::Count},
    {"area_cleaned", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Area cleaned (plates)"),
     Kind::Ratio},
    {"time_to_clean", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Time to clean"), Kind::Seconds},
    {"plates_cleaned", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Plates cleaned"), Kind::Count},
    {"plates_broken", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Plates broken"), Kind::Count},
    {"peak_force", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Peak force"), Kind::Newtons},
    {"time_above_safe_force",
     QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Time above the safe force"), Kind::Seconds},
    {"average_press_force", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Average press force"),
     Kind::Newtons},
    {"warnings_felt", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Warnings felt"), Kind::Count},
    {"stiffened_at", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Sponge stiffened at"),
     Kind::Seconds},
    {"sim_seconds", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Simulated time"), Kind::Seconds},
    {"wall_seconds", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Wall time"), Kind::Seconds},
    {"realtime_factor", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Real-time factor"),
     Kind::Factor},
    {"scene", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Scene"), Kind::Text},
    {"router", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Router"), Kind::Text},
    {"operator", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Operator"), Kind::Text},
    {"seed", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Seed"), Kind::Count},
};

const KnownMetric *known(const QString &key)
{
    for (const KnownMetric &metric : Known) {
        if (key == QLatin1String(metric.key))
            return &metric;
    }
    return nullptr;
}

/** What an unknown key most likely holds, from its spelling and value. */
Kind guessKind(const QString &key, double value)
{
    if (key.endsWith(QLatin1String("_seconds")) || key.endsWith(QLatin1String("_time")))
        return Kind::Seconds;
    if (key.endsWith(QLatin1String("_share")))
        return Kind::Share;
    if (value == std::floor(value) && std::abs(value) < 1e15)
        return Kind::Count;
    return Kind::Ratio;
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

/** The known keys first, in the order above, then the others by name. */
Flat ordered(const QJsonObject &metrics)
{
    Flat all;
    flatten(metrics, QString(), &all);
    Flat out;
    for (const KnownMetric &metric : Known) {
        for (const auto &entry : all) {
            if (entry.first == QLatin1String(metric.key))
                out.push_back(entry);
        }
    }
    for (const auto &entry : all) {
        if (!known(entry.first))
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
    const KnownMetric *metric = known(key);
    return metric ? tr(metric->label) : key;
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
    const KnownMetric *metric = known(key);
    switch (metric ? metric->kind : guessKind(key, number)) {
    case Kind::Count:
        return QLocale().toString(std::llround(number));
    case Kind::Ratio:
        return QLocale().toString(number, 'f', 2);
    case Kind::Factor:
        return tr("%1×").arg(QLocale().toString(number, 'f', 2));
    case Kind::Seconds:
        return tr("%1 s").arg(QLocale().toString(number, 'f', 2));
    case Kind::Newtons:
        return tr("%1 N").arg(QLocale().toString(number, 'f', 2));
    case Kind::Share:
        return tr("%1 %").arg(QLocale().toString(number * 100.0, 'f', 0));
    case Kind::Text:
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
            name->setToolTip(key);
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

} // namespace semhap
