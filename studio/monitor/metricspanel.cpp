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
    const char *meaning; ///< one sentence, as docs/metrics.md defines it
    Kind kind;
};

// docs/metrics.md, in the order a reader looks for them.
const KnownMetric Known[] = {
    {"completion_time", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Completion time"),
     QT_TRANSLATE_NOOP(
         "semhap::MetricsPanel",
         "When the pile was first finished: every cube transferred or broken (box_and_block)."),
     Kind::Seconds},
    {"cubes_transferred", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Cubes transferred"),
     QT_TRANSLATE_NOOP("semhap::MetricsPanel",
                       "Cubes that arrived where the task wants them, once per trip."),
     Kind::Count},
    {"cubes_broken", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Cubes broken"),
     QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Cubes that fractured under the fingertips."),
     Kind::Count},
    {"cubes_dropped", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Cubes dropped (slipped out)"),
     QT_TRANSLATE_NOOP(
         "semhap::MetricsPanel",
         "Grasps that ended while the hand still gripped, after a lift: the cube slipped out."),
     Kind::Count},
    {"grasps", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Grasps"),
     QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Grasps begun."), Kind::Count},
    {"grasps_per_transfer", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Grasps per transfer"),
     QT_TRANSLATE_NOOP("semhap::MetricsPanel",
                       "Grasps per cube transferred: 1 is one grasp for each."),
     Kind::Ratio},
    {"average_grasp_force", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Average grasp force"),
     QT_TRANSLATE_NOOP("semhap::MetricsPanel",
                       "The mean force of both fingertips over every moment of every grasp."),
     Kind::Newtons},
    {"average_peak_grasp_force",
     QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Average peak grasp force"),
     QT_TRANSLATE_NOOP("semhap::MetricsPanel",
                       "The mean over grasps of the highest force during each."),
     Kind::Newtons},
    {"warning_lead_time", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Warning lead time"),
     QT_TRANSLATE_NOOP("semhap::MetricsPanel",
                       "How long before a break its warning was first felt, on average."),
     Kind::Seconds},
    {"breaks_warned_share", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Breaks warned"),
     QT_TRANSLATE_NOOP("semhap::MetricsPanel", "The share of breaks a felt warning came before."),
     Kind::Share},
    {"breaks_warned_in_time_share",
     QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Breaks warned in time"),
     QT_TRANSLATE_NOOP("semhap::MetricsPanel", "The share of breaks warned at least a reaction "
                                               "time before: the warnings a person could act on."),
     Kind::Share},
    {"containers_dropped", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Containers dropped"),
     QT_TRANSLATE_NOOP("semhap::MetricsPanel",
                       "Times the held container left the left fingertips and fell (bimanual)."),
     Kind::Count},
    {"drop_warning_lead_time", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Drop warning lead time"),
     QT_TRANSLATE_NOOP(
         "semhap::MetricsPanel",
         "How long before a container drop its warning was first felt, on average (bimanual)."),
     Kind::Seconds},
    {"drops_warned_share", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Drops warned"),
     QT_TRANSLATE_NOOP("semhap::MetricsPanel",
                       "The share of container drops a felt warning came before (bimanual)."),
     Kind::Share},
    {"drops_warned_in_time_share",
     QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Drops warned in time"),
     QT_TRANSLATE_NOOP(
         "semhap::MetricsPanel",
         "The share of container drops warned at least a reaction time before (bimanual)."),
     Kind::Share},
    {"containers_set_down", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Containers set down"),
     QT_TRANSLATE_NOOP("semhap::MetricsPanel",
                       "Times the holding hand set the full container down on its base to be "
                       "emptied (bimanual)."),
     Kind::Count},
    {"transfers_per_container_cycle",
     QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Transfers per container cycle"),
     QT_TRANSLATE_NOOP(
         "semhap::MetricsPanel",
         "Cubes transferred per container cycle, which a drop or a set-down ends (bimanual)."),
     Kind::Ratio},
    {"confirmations_per_grasp",
     QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Confirmations felt per grasp"),
     QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Confirmations felt per real grasp: 1 is one per "
                                               "grasp, more is chatter, 0 without feedback."),
     Kind::Ratio},
    {"slip_episodes", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Slip episodes"),
     QT_TRANSLATE_NOOP("semhap::MetricsPanel",
                       "Times the container slid in the left fingertips (bimanual)."),
     Kind::Count},
    {"warnings_per_slip_episode",
     QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Warnings felt per slip episode"),
     QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Warnings felt on the left hand per slip: above 1, "
                                               "warnings came that no slip answered (bimanual)."),
     Kind::Ratio},
    {"breaks_warned_by_onset_share",
     QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Breaks warned by onset"),
     QT_TRANSLATE_NOOP("semhap::MetricsPanel",
                       "The share of breaks whose warning began within the horizon before, in "
                       "time to act: a warning on all along does not count."),
     Kind::Share},
    {"right_warning_precision",
     QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Right warnings borne out"),
     QT_TRANSLATE_NOOP("semhap::MetricsPanel",
                       "The share of the right hand's warnings a break, or the grip crossing the "
                       "break line, followed within the horizon: the rest were false alarms."),
     Kind::Share},
    {"right_warning_duty", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Right warning duty"),
     QT_TRANSLATE_NOOP("semhap::MetricsPanel",
                       "The share of grasping time a warning was felt on the right hand."),
     Kind::Share},
    {"drops_warned_by_onset_share",
     QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Drops warned by onset"),
     QT_TRANSLATE_NOOP("semhap::MetricsPanel",
                       "The share of container drops whose warning began within the horizon "
                       "before, in time to act (bimanual)."),
     Kind::Share},
    {"left_warning_precision",
     QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Left warnings borne out"),
     QT_TRANSLATE_NOOP("semhap::MetricsPanel",
                       "The share of the left hand's warnings a drop or a slip followed within "
                       "the horizon: the rest were false alarms (bimanual)."),
     Kind::Share},
    {"left_warning_duty", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Left warning duty"),
     QT_TRANSLATE_NOOP("semhap::MetricsPanel",
                       "The share of the time the container was held that a warning was felt "
                       "(bimanual)."),
     Kind::Share},
    {"box_refills", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Cube box refills"),
     QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Times the cube box was refilled."), Kind::Count},
    {"insertions", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Plugs inserted"),
     QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Plugs seated in the port."), Kind::Count},
    {"time_to_insert", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Time to insert"),
     QT_TRANSLATE_NOOP("semhap::MetricsPanel",
                       "The mean time from picking a plug up to seating it."),
     Kind::Seconds},
    {"collisions", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Collisions with the port"),
     QT_TRANSLATE_NOOP("semhap::MetricsPanel",
                       "Times the plug pushed on the port's face beside the opening."),
     Kind::Count},
    {"peak_insertion_force", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Peak insertion force"),
     QT_TRANSLATE_NOOP("semhap::MetricsPanel", "The highest force on the port during the run."),
     Kind::Newtons},
    {"plug_pickups", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Plug pick-ups"),
     QT_TRANSLATE_NOOP("semhap::MetricsPanel",
                       "Times a plug was lifted from where it was laid out."),
     Kind::Count},
    {"plugs_dropped", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Plugs dropped"),
     QT_TRANSLATE_NOOP("semhap::MetricsPanel",
                       "Plugs let go of after a pick-up without being seated."),
     Kind::Count},
    {"area_cleaned", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Area cleaned (plates)"),
     QT_TRANSLATE_NOOP(
         "semhap::MetricsPanel",
         "Cells cleaned, in plates' worth: above 1 when more than a plate was cleaned."),
     Kind::Ratio},
    {"time_to_clean", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Time to clean"),
     QT_TRANSLATE_NOOP("semhap::MetricsPanel",
                       "When every cell of the first plate was first clean."),
     Kind::Seconds},
    {"plates_cleaned", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Plates cleaned"),
     QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Times every cell of a plate was clean at once."),
     Kind::Count},
    {"plates_broken", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Plates broken"),
     QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Plates broken by pressing above 40 N."),
     Kind::Count},
    {"peak_force", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Peak force"),
     QT_TRANSLATE_NOOP("semhap::MetricsPanel", "The highest press of the sponge on the plate."),
     Kind::Newtons},
    {"time_above_safe_force",
     QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Time above the safe force"),
     QT_TRANSLATE_NOOP("semhap::MetricsPanel", "The time the press was above the safe 25 N."),
     Kind::Seconds},
    {"average_press_force", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Average press force"),
     QT_TRANSLATE_NOOP("semhap::MetricsPanel",
                       "The mean press while the sponge pressed on the plate."),
     Kind::Newtons},
    {"warnings_felt", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Warnings felt"),
     QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Warnings felt on the wiping hand."), Kind::Count},
    {"stiffened_at", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Sponge stiffened at"),
     QT_TRANSLATE_NOOP("semhap::MetricsPanel", "When the sponge's holder stiffened."),
     Kind::Seconds},
    {"cues_taken_in", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Cues taken in"),
     QT_TRANSLATE_NOOP("semhap::MetricsPanel",
                       "Cues the perceiving operator felt on a band or saw on the overlay."),
     Kind::Count},
    {"cues_misread", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Cues misread"),
     QT_TRANSLATE_NOOP("semhap::MetricsPanel",
                       "Cues the perceiving operator took for a message of the other meaning: "
                       "a warning for a confirmation, or the other way round."),
     Kind::Count},
    {"warnings_ignored", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Warnings ignored"),
     QT_TRANSLATE_NOOP("semhap::MetricsPanel",
                       "Warnings the perceiving operator felt and did not answer, for how "
                       "seldom that hand's warnings had been right."),
     Kind::Count},
    {"left_reliance", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Left reliance"),
     QT_TRANSLATE_NOOP("semhap::MetricsPanel",
                       "The share of the left hand's warnings the perceiving operator answers "
                       "now."),
     Kind::Share},
    {"right_reliance", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Right reliance"),
     QT_TRANSLATE_NOOP("semhap::MetricsPanel",
                       "The share of the right hand's warnings the perceiving operator answers "
                       "now."),
     Kind::Share},
    {"sim_seconds", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Simulated time"),
     QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Simulated time so far."), Kind::Seconds},
    {"wall_seconds", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Wall time"),
     QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Real time so far."), Kind::Seconds},
    {"realtime_factor", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Real-time factor"),
     QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Simulated seconds per real second."),
     Kind::Factor},
    {"scene", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Scene"),
     QT_TRANSLATE_NOOP("semhap::MetricsPanel", "The task that runs."), Kind::Text},
    {"router", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Router"),
     QT_TRANSLATE_NOOP("semhap::MetricsPanel", "The router the run was loaded with."), Kind::Text},
    {"operator", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Operator"),
     QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Who drives the grippers when you do not."),
     Kind::Text},
    {"seed", QT_TRANSLATE_NOOP("semhap::MetricsPanel", "Seed"),
     QT_TRANSLATE_NOOP("semhap::MetricsPanel",
                       "The seed of the operator and of a laid-out scene."),
     Kind::Count},
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

QString MetricsPanel::tooltip(const QString &key)
{
    const KnownMetric *metric = known(key);
    if (!metric)
        return key;
    QString unit;
    switch (metric->kind) {
    case Kind::Count:
        unit = tr("a count");
        break;
    case Kind::Ratio:
        unit = tr("a ratio");
        break;
    case Kind::Factor:
        unit = tr("times real time");
        break;
    case Kind::Seconds:
        unit = tr("seconds of simulated time");
        break;
    case Kind::Newtons:
        unit = tr("newtons (N)");
        break;
    case Kind::Share:
        unit = tr("a share, 0 to 100 %");
        break;
    case Kind::Text:
        break;
    }
    const QString meaning = tr(metric->meaning);
    return unit.isEmpty() ? tr("%1\nIn exports: %2").arg(meaning, key)
                          : tr("%1\nIn %2; in exports: %3").arg(meaning, unit, key);
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

} // namespace semhap
