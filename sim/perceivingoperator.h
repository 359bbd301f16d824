// SPDX-License-Identifier: MIT
#pragma once

#include "metricspec.h"
#include "operator.h"
#include "person.h"

#include <array>
#include <memory>

namespace semhap {

/**
 * The reactive operator's hands with a person's senses (docs/operator.md): what the hands
 * act on is what the Person takes in (detected, recognised, reacted to, seen), not the
 * bands' meaning as the router knows it. The person looks at the hand doing the current
 * sub-task: the picking hand, the holding one while it moves, and the holding one while the
 * picking hand works above it.
 */
class PerceivingOperator : public Operator
{
public:
    /** `hands`: a reactive operator with no delay of its own; the person's draws follow `seed`. */
    PerceivingOperator(std::unique_ptr<Operator> hands, const PersonParameters &parameters,
                       std::uint64_t seed);

    QString name() const override;
    void act(World &world) override;
    void engage(const World &world) override;
    void sense(const Perception &perception, const Task &task, double t) override;
    void feel(Gripper hand, const Feeling &feeling, double t) override;
    /**
     * `cues_taken_in`, `cues_misread`, `warnings_ignored` (both hands), and per hand of the
     * scene `left_reliance`, `right_reliance` (docs/metrics.md).
     */
    void addMetrics(QJsonObject *metrics) const override;
    /** What addMetrics() adds, a row each (docs/metrics.md). */
    static const std::vector<MetricSpec> &metricSpecs();

    const Person &person() const { return m_person; }
    /**
     * The hand a person doing `world`'s task looks at: the only one; else the left while it
     * moves, or while the right works within reach of it; else the right.
     */
    static Gripper gaze(const World &world, const std::array<double, 3> &leftBefore);

    /** A hand's target moving faster than this (m/s) is doing something. */
    static constexpr double Moving = 0.02;
    /** The picking hand works at the holding hand when its target is this close (m, across). */
    static constexpr double AtHand = 0.12;

private:
    std::unique_ptr<Operator> m_hands;
    Person m_person;
    std::array<double, 3> m_leftBefore{};
    std::array<bool, 2> m_hasHand{}; ///< the scene's grippers, as act() found them
};

} // namespace semhap
