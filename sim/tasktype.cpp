// SPDX-License-Identifier: MIT
#include "tasktype.h"

#include "insertionoperator.h"
#include "insertiontask.h"
#include "scriptedoperator.h"
#include "stackingoperator.h"
#include "stackingtask.h"
#include "taskmonitor.h"
#include "wipingoperator.h"
#include "wipingtask.h"
#include "world.h"

namespace semhap {

const std::vector<TaskType> &TaskType::all()
{
    static const std::vector<TaskType> rows = {
        {
            "",
            [](World &world, std::uint64_t, double reactionTime, double horizon,
               QString *) -> std::unique_ptr<Task> {
                return std::make_unique<TaskMonitor>(world, reactionTime, horizon);
            },
            {QStringLiteral("scripted"), QStringLiteral("reactive"),
             QStringLiteral("fast_squeeze"), QStringLiteral("drifting_hold")},
            &ScriptedOperator::create,
            &TaskMonitor::metricSpecs,
        },
        {
            InsertionTask::Name,
            [](World &world, std::uint64_t seed, double, double, QString *error)
                -> std::unique_ptr<Task> { return InsertionTask::create(world, seed, error); },
            {QStringLiteral("scripted"), QStringLiteral("reactive")},
            [](const QString &operatorName, const World &, std::uint64_t seed, double reactionTime,
               QString *) -> std::unique_ptr<Operator> {
                return std::make_unique<InsertionOperator>(
                    seed, operatorName == QLatin1String("reactive"), reactionTime);
            },
            &InsertionTask::metricSpecs,
        },
        {
            WipingTask::Name,
            [](World &world, std::uint64_t seed, double, double, QString *error)
                -> std::unique_ptr<Task> { return WipingTask::create(world, seed, error); },
            {QStringLiteral("scripted"), QStringLiteral("reactive")},
            [](const QString &operatorName, const World &world, std::uint64_t seed,
               double reactionTime, QString *) -> std::unique_ptr<Operator> {
                return std::make_unique<WipingOperator>(
                    world, seed, operatorName == QLatin1String("reactive"), reactionTime);
            },
            &WipingTask::metricSpecs,
        },
        {
            StackingTask::Name,
            [](World &world, std::uint64_t, double, double, QString *error)
                -> std::unique_ptr<Task> { return StackingTask::create(world, error); },
            {QStringLiteral("scripted"), QStringLiteral("reactive")},
            [](const QString &operatorName, const World &, std::uint64_t seed, double reactionTime,
               QString *) -> std::unique_ptr<Operator> {
                return std::make_unique<StackingOperator>(
                    seed, operatorName == QLatin1String("reactive"), reactionTime);
            },
            &StackingTask::metricSpecs,
        },
    };
    return rows;
}

const TaskType *TaskType::find(const QString &name)
{
    for (const TaskType &row : all()) {
        if (name == QLatin1String(row.name))
            return &row;
    }
    return nullptr;
}

const TaskType *TaskType::of(const World &world, QString *error)
{
    if (const TaskType *type = find(world.taskName()))
        return type;
    QStringList names;
    for (const TaskType &row : all()) {
        if (*row.name)
            names.append(QLatin1String(row.name));
    }
    *error = QStringLiteral("%1: unknown task '%2' (tasks: %3)")
                 .arg(world.sceneName(), world.taskName(), names.join(QStringLiteral(", ")));
    return nullptr;
}

} // namespace semhap
