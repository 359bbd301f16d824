// SPDX-License-Identifier: MIT
#pragma once

#include <QString>

#include <vector>

namespace semhap {

/** What a metric's number is, for reading it and for its unit. */
enum class MetricUnit
{
    Count,   ///< a whole number of things or times
    Ratio,   ///< a plain number, two decimals
    Factor,  ///< times something (× real time)
    Seconds, ///< simulated seconds
    Newtons,
    Share, ///< 0 to 1, read as a percentage
    Text   ///< not a number (the run's scene, router, operator)
};

/** Which way a metric is better, for a comparison to say which condition did better. */
enum class MetricBetter
{
    Higher,
    Lower,
    Neither ///< a description of the run, not a score (grasps, slip episodes)
};

/** What a metric tells of a run. */
enum class MetricRole
{
    Outcome, ///< how the task went: what conditions are compared on
    Measure, ///< of the run itself (its times), not of the condition
    Input    ///< what the run was given (scene, router, operator, seed)
};

/**
 * One metric a run reports, as one row: its snake_case name (the JSON key, the CSV column),
 * its unit, which way it is better, a short label and one sentence of help (docs/metrics.md
 * defines it at length). A task, an operator and the run itself each register their rows;
 * the Metrics panel, `semhap compare`, the study's measures and the docs' check read them.
 * Labels and help are English; the studio translates them in the context "semhap::MetricSpec".
 */
struct MetricSpec
{
    const char *name = "";
    MetricUnit unit = MetricUnit::Count;
    MetricBetter better = MetricBetter::Neither;
    const char *label = "";
    const char *help = "";
    MetricRole role = MetricRole::Outcome;

    /**
     * Every metric: the tasks' (in their registration's order), the operators', then the
     * run's measures and inputs (SimRun). Names are unique across the table.
     */
    static const std::vector<MetricSpec> &all();
    /** The row named `name`, or null (a metric the table does not know, or a nested key). */
    static const MetricSpec *find(const QString &name);
    /** The rows of `role` whose values are numbers, in table order. */
    static std::vector<const MetricSpec *> numbers(MetricRole role);
};

} // namespace semhap
