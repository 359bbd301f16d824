// SPDX-License-Identifier: MIT
#include "perceivingoperator.h"

#include "world.h"

#include <QJsonObject>

#include <cmath>

namespace semhap {

namespace {

/** The person's draws are a stream of their own, so the hands vary as the reactive ones do. */
constexpr std::uint64_t PersonStream = 0x9e3779b97f4a7c15ull;

} // namespace

PerceivingOperator::PerceivingOperator(std::unique_ptr<Operator> hands,
                                       const PersonParameters &parameters, std::uint64_t seed)
    : m_hands(std::move(hands)), m_person(parameters, seed ^ PersonStream)
{}

QString PerceivingOperator::name() const
{
    return QStringLiteral("perceiving");
}

Gripper PerceivingOperator::gaze(const World &world, const std::array<double, 3> &leftBefore)
{
    if (!world.hasGripper(Gripper::Left))
        return Gripper::Right;
    if (!world.hasGripper(Gripper::Right))
        return Gripper::Left;
    const auto left = world.target(Gripper::Left).pos;
    const double moved =
        std::hypot(left[0] - leftBefore[0], left[1] - leftBefore[1], left[2] - leftBefore[2]);
    if (moved > Moving * world.timestep())
        return Gripper::Left;
    // The eyes go where the picking hand is going (its target), ahead of the hand.
    const auto right = world.target(Gripper::Right).pos;
    const auto holding = world.gripperPose(Gripper::Left).pos;
    return std::hypot(right[0] - holding[0], right[1] - holding[1]) < AtHand ? Gripper::Left
                                                                             : Gripper::Right;
}

void PerceivingOperator::act(World &world)
{
    m_hasHand = {world.hasGripper(Gripper::Left), world.hasGripper(Gripper::Right)};
    m_hands->act(world);
    // Where the hands go next is where the eyes go: after they are given their targets.
    m_person.look(gaze(world, m_leftBefore), world.time());
    if (world.hasGripper(Gripper::Left))
        m_leftBefore = world.target(Gripper::Left).pos;
}

void PerceivingOperator::engage(const World &world)
{
    m_hands->engage(world);
    m_person.forget();
    if (world.hasGripper(Gripper::Left))
        m_leftBefore = world.target(Gripper::Left).pos;
}

void PerceivingOperator::sense(const Perception &perception, const Task &task, double t)
{
    m_person.sense(perception, task, t);
}

void PerceivingOperator::feel(Gripper hand, const Feeling &, double t)
{
    // What the hands act on is what the person has taken in, not what the bands meant.
    m_hands->feel(hand, m_person.feeling(hand), t);
}

void PerceivingOperator::addMetrics(QJsonObject *metrics) const
{
    int cues = 0;
    int misread = 0;
    int ignored = 0;
    for (Gripper hand : {Gripper::Left, Gripper::Right}) {
        const Person::Record &record = m_person.record(hand);
        cues += record.cues;
        misread += record.misread;
        ignored += record.ignored;
        if (m_hasHand[size_t(hand)])
            metrics->insert(hand == Gripper::Left ? QStringLiteral("left_reliance")
                                                  : QStringLiteral("right_reliance"),
                            m_person.reliance(hand));
    }
    metrics->insert(QStringLiteral("cues_taken_in"), cues);
    metrics->insert(QStringLiteral("cues_misread"), misread);
    metrics->insert(QStringLiteral("warnings_ignored"), ignored);
}

const std::vector<MetricSpec> &PerceivingOperator::metricSpecs()
{
    static const std::vector<MetricSpec> specs = {
        {"cues_taken_in", MetricUnit::Count, MetricBetter::Neither,
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Cues taken in"),
         QT_TRANSLATE_NOOP("semhap::MetricSpec",
                           "Cues the perceiving operator felt on a band or saw on the overlay.")},
        {"cues_misread", MetricUnit::Count, MetricBetter::Lower,
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Cues misread"),
         QT_TRANSLATE_NOOP("semhap::MetricSpec",
                           "Cues the perceiving operator took for a message of the other meaning: "
                           "a warning for a confirmation, or the other way round.")},
        {"warnings_ignored", MetricUnit::Count, MetricBetter::Lower,
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Warnings ignored"),
         QT_TRANSLATE_NOOP("semhap::MetricSpec",
                           "Warnings the perceiving operator felt and did not answer, for how "
                           "seldom that hand's warnings had been right.")},
        {"left_reliance", MetricUnit::Share, MetricBetter::Neither,
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Left reliance"),
         QT_TRANSLATE_NOOP("semhap::MetricSpec",
                           "The share of the left hand's warnings the perceiving operator answers "
                           "now.")},
        {"right_reliance", MetricUnit::Share, MetricBetter::Neither,
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Right reliance"),
         QT_TRANSLATE_NOOP(
             "semhap::MetricSpec",
             "The share of the right hand's warnings the perceiving operator answers "
             "now.")},
    };
    return specs;
}

} // namespace semhap
