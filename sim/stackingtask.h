// SPDX-License-Identifier: MIT
#pragma once

#include "metricspec.h"
#include "task.h"
#include "world.h"

#include <vector>

namespace semhap {

/**
 * block_stacking's rules and metrics (docs/metrics.md): blocks taken from a pile and stacked
 * on a base into a tower `Levels` high. It counts the levels each placement adds, the
 * towers finished, the tallest tower, the topples (levels lost with no block in hand) and
 * the blocks dropped (let go of anywhere but on the tower), and the time from lifting a block
 * to the level it adds. A finished tower is put back into the pile once the hand has risen
 * clear of it; a block lying anywhere but the pile and the tower goes back after
 * `DropPenalty`.
 */
class StackingTask : public Task
{
public:
    /** The `semhap:task` text of the scenes this task runs. */
    static constexpr const char *Name = "block_stacking";
    /** How many levels a finished tower has. */
    static constexpr int Levels = 5;
    /** Seconds a fallen block lies before the task puts it back into the pile. */
    static constexpr double DropPenalty = 2.0;
    /** How long a change of the tower must hold before it counts (s): a block settling. */
    static constexpr double Settle = 0.3;

    /** The task on `world`; null with `error` if the scene lacks its site or blocks. */
    static std::unique_ptr<StackingTask> create(World &world, QString *error);

    void observe(World &world) override;
    void feel(Gripper hand, const Feeling &feeling, double t) override;
    QJsonObject metrics() const override;
    /** Its metrics, a row each (docs/metrics.md). */
    static const std::vector<MetricSpec> &metricSpecs();

    /** The scene's blocks (objects named `block_…`), by object index. */
    static std::vector<int> blocksOf(const World &world);
    /**
     * The blocks standing on the base now, from the bottom up: each at rest on the one below
     * (on the base, the first), upright, centred on the tower's site within a block's third.
     * A block in the right gripper's fingers is not part of it.
     */
    static std::vector<int> tower(const World &world, const std::vector<int> &blocks);
    /** Where the tower stands: the base's face under its centre (site `tower`). */
    static std::array<double, 3> base(const World &world);
    /** A block's edge (m; the scene's blocks are cubes). */
    static double blockSize(const World &world, int block);

private:
    explicit StackingTask(World &world);
    /** Puts `block` back where the scene started it, whole and at rest. */
    void putBack(World &world, int block);

    std::vector<int> m_blocks;
    std::vector<double> m_lyingSince; ///< per block: since when it lies out of play; -1: not
    int m_levels = 0;                 ///< how many levels the counted tower has
    int m_seen = 0;                   ///< how many the tower had at the last step
    double m_seenSince = 0.0;
    std::vector<int> m_tower;    ///< the tower as counted, from the bottom up
    int m_carried = -1;          ///< the block in hand, lifted; -1: none
    double m_liftedAt = -1.0;    ///< when it was lifted
    double m_lostAt = -1.0;      ///< when the carried block left the fingertips; -1: in them
    double m_pendingLift = -1.0; ///< the lift of a block let go of on the tower, not yet counted
    int m_released = -1;         ///< a block let go of, to see where it comes to rest
    double m_releasedAt = -1.0;
    bool m_finished = false; ///< this tower has reached Levels

    int m_stacked = 0;
    int m_towers = 0;
    int m_tallest = 0;
    int m_topples = 0;
    int m_dropped = 0;
    int m_timed = 0;
    double m_timeSum = 0.0;
};

} // namespace semhap
