// SPDX-License-Identifier: MIT
#pragma once

#include <QProcessEnvironment>
#include <QString>

#include <optional>

namespace semhap {

/**
 * Which slice of a grid one process runs: slice `index` of `count` (1-based) takes the grid's
 * positions p (0-based) with p % count == index - 1, so the slices of 1..count, on any
 * machines, are the whole grid once. Given as `I/N`, or `auto` inside a Slurm job array,
 * whose task is slice (its position in the array) of (the array's task count).
 */
struct Shard
{
    int index = 1;
    int count = 1;

    /** Whether the grid's `position` (0-based) is this slice's. */
    bool takes(int position) const { return position % count == index - 1; }
    /** `I/N`, as the command line takes it. */
    QString text() const;

    /**
     * `I/N`, or `auto` read from the SLURM_ARRAY_TASK_* variables of `environment`; none,
     * with `error` a sentence for the user, for text that is neither, `auto` outside an
     * array job (naming the variables) or an array with gaps.
     */
    static std::optional<Shard> parse(const QString &text, const QProcessEnvironment &environment,
                                      QString *error);
};

} // namespace semhap
