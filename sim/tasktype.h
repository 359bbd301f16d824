// SPDX-License-Identifier: MIT
#pragma once

#include "metricspec.h"

#include <QString>
#include <QStringList>

#include <cstdint>
#include <memory>
#include <vector>

namespace semhap {

class Operator;
class Task;
class World;

/**
 * A task as one registered row: the name a scene gives it (its `semhap:task` text), how to
 * make its Task (rules and metrics) and its operators, which operators can do it, and its
 * metrics. makeTask, makeOperator, operatorNames and MetricSpec read the rows; a new task is
 * its own files (its Task, its operator, its scene) plus one row in tasktype.cpp.
 */
struct TaskType
{
    /** The scene's `semhap:task`; "" is the cube tasks (box_and_block, bimanual_sorting). */
    const char *name = "";
    /**
     * The task for `world`, laid out or drawn from `seed` now; `reactionTime` and `horizon`
     * judge warnings (docs/metrics.md). Null with `error` for a scene it cannot do.
     */
    std::unique_ptr<Task> (*create)(World &world, std::uint64_t seed, double reactionTime,
                                    double horizon, QString *error) = nullptr;
    /**
     * The operators that can do it, by name; `perceiving` is added wherever `reactive` is
     * (it perceives for the reactive hands).
     */
    QStringList operators;
    /** The operator `name` (one of `operators`) for `world`; null with `error`. */
    std::unique_ptr<Operator> (*makeOperator)(const QString &name, const World &world,
                                              std::uint64_t seed, double reactionTime,
                                              QString *error) = nullptr;
    /** Its metrics, in the order a reader looks for them. */
    const std::vector<MetricSpec> &(*metrics)() = nullptr;

    /** Every task, in the order the docs and the Metrics panel list them. */
    static const std::vector<TaskType> &all();
    /** The row named `name`, or null. */
    static const TaskType *find(const QString &name);
    /** The row of `world`'s scene; null with `error` naming the tasks there are. */
    static const TaskType *of(const World &world, QString *error);
};

} // namespace semhap
