// SPDX-License-Identifier: MIT
#include "task.h"

#include "insertiontask.h"
#include "taskmonitor.h"
#include "wipingtask.h"
#include "world.h"

namespace semhap {

std::optional<bool> Task::warranted(Gripper, double, double) const
{
    return std::nullopt;
}

std::unique_ptr<Task> makeTask(World &world, std::uint64_t seed, double reactionTime,
                               double horizon, QString *error)
{
    const QString &name = world.taskName();
    if (name.isEmpty())
        return std::make_unique<TaskMonitor>(world, reactionTime, horizon);
    if (name == QLatin1String(InsertionTask::Name))
        return InsertionTask::create(world, seed, error);
    if (name == QLatin1String(WipingTask::Name))
        return WipingTask::create(world, seed, error);
    *error = QStringLiteral("%1: unknown task '%2' (tasks: %3, %4)")
                 .arg(world.sceneName(), name, QLatin1String(InsertionTask::Name),
                      QLatin1String(WipingTask::Name));
    return nullptr;
}

} // namespace semhap
