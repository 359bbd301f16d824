// SPDX-License-Identifier: MIT
#include "operator.h"

#include "perceivingoperator.h"
#include "tasktype.h"
#include "world.h"

namespace semhap {

namespace {

/** The operator that perceives for the reactive hands, on every task they can do. */
const QLatin1String Perceiving("perceiving");
const QLatin1String Reactive("reactive");

/** `type`'s operators, with the perceiving one after the reactive hands it drives. */
QStringList operatorsOf(const TaskType &type)
{
    QStringList names;
    for (const QString &name : type.operators) {
        names.append(name);
        if (name == Reactive)
            names.append(Perceiving);
    }
    return names;
}

} // namespace

void Operator::feel(Gripper, const Feeling &, double) {}

void Operator::sense(const Perception &, const Task &, double) {}

void Operator::addMetrics(QJsonObject *) const {}

QStringList operatorNames()
{
    QStringList names;
    for (const TaskType &type : TaskType::all()) {
        for (const QString &name : operatorsOf(type)) {
            if (!names.contains(name))
                names.append(name);
        }
    }
    return names;
}

std::unique_ptr<Operator> makeOperator(const QString &name, const World &world, std::uint64_t seed,
                                       double reactionTime, const PersonParameters &person,
                                       QString *error)
{
    if (!operatorNames().contains(name)) {
        *error = QStringLiteral("unknown operator '%1' (operators: %2)")
                     .arg(name, operatorNames().join(QStringLiteral(", ")));
        return nullptr;
    }
    const TaskType *type = TaskType::of(world, error);
    if (!type)
        return nullptr;
    const QStringList supported = operatorsOf(*type);
    if (!supported.contains(name)) {
        *error = QStringLiteral("%1: the %2 operator cannot do %3 (operators: %4)")
                     .arg(world.sceneName(), name, world.taskName(),
                          supported.join(QStringLiteral(", ")));
        return nullptr;
    }
    if (name == Perceiving) {
        // The reactive hands, with no delay of their own: the person's senses supply it.
        std::unique_ptr<Operator> hands = type->makeOperator(Reactive, world, seed, 0.0, error);
        if (!hands)
            return nullptr;
        return std::make_unique<PerceivingOperator>(std::move(hands), person, seed);
    }
    return type->makeOperator(name, world, seed, reactionTime, error);
}

} // namespace semhap
