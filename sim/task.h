// SPDX-License-Identifier: MIT
#pragma once

#include "operator.h"

#include <QJsonObject>
#include <QString>

#include <cstdint>
#include <memory>
#include <optional>

namespace semhap {

class World;

/**
 * How long before a failure a warning's onset may lie and still count as its warning (s):
 * the metrics by onset and the warnings' precision (docs/metrics.md).
 */
constexpr double DefaultHorizon = 3.0;

/**
 * A scene's task: its rules (what it puts back, and when) and its metrics
 * (docs/metrics.md). SimRun calls observe() after every physics step and feel() with what
 * each hand perceives.
 */
class Task
{
public:
    virtual ~Task() = default;
    /** Applies the rules and counts, after a physics step. */
    virtual void observe(World &world) = 0;
    /** What the operator perceives of `hand` now (from Perception). */
    virtual void feel(Gripper hand, const Feeling &feeling, double t) = 0;
    /** The metrics so far, snake_case keys; averages over nothing are null. */
    virtual QJsonObject metrics() const = 0;
    /**
     * Whether a warning felt on `hand` from `onset` on was borne out, as a warning's
     * precision counts it (docs/metrics.md); empty until `t` is a horizon past the onset,
     * and always for a task that does not judge its warnings.
     */
    virtual std::optional<bool> warranted(Gripper hand, double onset, double t) const;
};

/**
 * The task of `world`'s scene, by its `semhap:task` text (sim/README.md), made by that
 * TaskType row: `usb_insertion`, `dish_wiping`, or without one the cube tasks
 * (box_and_block, bimanual_sorting). It may lay
 * the scene out, or draw what it varies unseen, from `seed` now. Null with `error` for a task
 * semhap does not know or a scene it cannot do. `reactionTime` and `horizon` judge the
 * warnings (docs/metrics.md).
 */
std::unique_ptr<Task> makeTask(World &world, std::uint64_t seed, double reactionTime,
                               double horizon, QString *error);

} // namespace semhap
