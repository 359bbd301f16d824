// SPDX-License-Identifier: MIT
#include "task.h"

#include "tasktype.h"

namespace semhap {

std::optional<bool> Task::warranted(Gripper, double, double) const
{
    return std::nullopt;
}

std::unique_ptr<Task> makeTask(World &world, std::uint64_t seed, double reactionTime,
                               double horizon, QString *error)
{
    const TaskType *type = TaskType::of(world, error);
    return type ? type->create(world, seed, reactionTime, horizon, error) : nullptr;
}

} // namespace semhap
