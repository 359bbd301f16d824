// SPDX-License-Identifier: MIT
#include "stackingtask.h"

#include <QJsonValue>

#include <algorithm>
#include <cmath>

namespace semhap {

namespace {

// A block counts as lifted once held this far above where the scene started it (m).
constexpr double Lifted = 0.01;
// Out of both fingertips this long, a held block was let go of (s).
constexpr double LostAfter = 0.05;
// A block in the tower: within this share of its edge of its level's height, and of the
// site's axis; turned less than about 11 degrees off upright; slower than this (m/s).
constexpr double LevelTolerance = 0.15;
constexpr double AxisTolerance = 1.0 / 3.0;
constexpr double Upright = 0.98;
constexpr double AtRest = 0.05;
// A finished tower goes back into the pile once the wrist is this far above its top (m).
constexpr double HandClear = 0.08;

QJsonValue mean(double sum, int count)
{
    return count > 0 ? QJsonValue(sum / count) : QJsonValue();
}

/** How near one of the block's axes is to the vertical: 1 upright, on any face. */
double uprightness(const std::array<double, 4> &q)
{
    const double w = q[0], x = q[1], y = q[2], z = q[3];
    return std::max({std::abs(2 * (x * z - w * y)), std::abs(2 * (y * z + w * x)),
                     std::abs(1 - 2 * (x * x + y * y))});
}

double speedOf(const World &world, int object)
{
    const auto v = world.objectVelocity(object);
    return std::hypot(v[0], v[1], v[2]);
}

} // namespace

std::unique_ptr<StackingTask> StackingTask::create(World &world, QString *error)
{
    Region pick;
    if (!world.sitePose(QStringLiteral("tower")) || !world.region(QStringLiteral("pick"), &pick) ||
        int(blocksOf(world).size()) < Levels) {
        *error = QStringLiteral("%1: the %2 task needs a site 'tower', a box site 'pick' and at "
                                "least %3 free bodies named block_…")
                     .arg(world.sceneName(), QLatin1String(Name))
                     .arg(Levels);
        return nullptr;
    }
    return std::unique_ptr<StackingTask>(new StackingTask(world));
}

StackingTask::StackingTask(World &world)
    : m_blocks(blocksOf(world)), m_lyingSince(world.objects().size(), -1.0)
{}

std::vector<int> StackingTask::blocksOf(const World &world)
{
    std::vector<int> blocks;
    for (size_t i = 0; i < world.objects().size(); ++i) {
        if (world.objects()[i].name.startsWith(QLatin1String("block_")))
            blocks.push_back(int(i));
    }
    return blocks;
}

std::array<double, 3> StackingTask::base(const World &world)
{
    return world.sitePose(QStringLiteral("tower"))->pos;
}

double StackingTask::blockSize(const World &world, int block)
{
    const SceneObject &object = world.objects()[size_t(block)];
    return object.upper[2] - object.lower[2];
}

std::vector<int> StackingTask::tower(const World &world, const std::vector<int> &blocks)
{
    const std::array<double, 3> at = base(world);
    const int held = world.objectSqueezed(Gripper::Right);
    std::vector<int> stack;
    double face = at[2];
    for (size_t level = 0; level < blocks.size(); ++level) {
        int found = -1;
        for (int block : blocks) {
            if (block == held || world.objects()[size_t(block)].broken)
                continue;
            const double size = blockSize(world, block);
            const Pose pose = world.objectPose(block);
            if (std::abs(pose.pos[2] - (face + size / 2)) < LevelTolerance * size &&
                std::hypot(pose.pos[0] - at[0], pose.pos[1] - at[1]) < AxisTolerance * size &&
                uprightness(pose.quat) > Upright && speedOf(world, block) < AtRest) {
                found = block;
                break;
            }
        }
        if (found < 0)
            break;
        stack.push_back(found);
        face += blockSize(world, found);
    }
    return stack;
}

void StackingTask::putBack(World &world, int block)
{
    world.restoreObject(block, world.homePosition(block));
    m_lyingSince[size_t(block)] = -1.0;
}

void StackingTask::observe(World &world)
{
    const double t = world.time();
    const int squeezed = world.objectSqueezed(Gripper::Right);
    const int held = std::count(m_blocks.begin(), m_blocks.end(), squeezed) > 0 ? squeezed : -1;

    // In hand and lifted; let go of once out of the fingertips for LostAfter.
    if (held >= 0) {
        m_lostAt = -1.0;
        if (held != m_carried &&
            world.objectPosition(held)[2] > world.homePosition(held)[2] + Lifted) {
            m_carried = held;
            m_liftedAt = t;
        }
    } else if (m_carried >= 0) {
        if (m_lostAt < 0)
            m_lostAt = t;
        if (t - m_lostAt >= LostAfter) {
            m_released = m_carried;
            m_releasedAt = t;
            m_pendingLift = m_liftedAt;
            m_carried = -1;
            m_lostAt = -1.0;
        }
    }

    // The tower, once a change has held for Settle.
    const std::vector<int> now = tower(world, m_blocks);
    if (int(now.size()) != m_seen) {
        m_seen = int(now.size());
        m_seenSince = t;
    }
    if (m_seen != m_levels && t - m_seenSince >= Settle) {
        if (m_seen > m_levels) {
            m_stacked += m_seen - m_levels;
            if (m_pendingLift >= 0 && std::count(now.begin(), now.end(), m_released) > 0) {
                m_timeSum += m_seenSince - m_pendingLift;
                ++m_timed;
                m_pendingLift = -1.0;
                m_released = -1;
            }
        } else {
            // Levels lost: a topple, unless all that went is the block now in hand.
            std::vector<int> lost;
            for (int block : m_tower) {
                if (std::count(now.begin(), now.end(), block) == 0)
                    lost.push_back(block);
            }
            if (!(lost.size() == 1 && lost.front() == held))
                ++m_topples;
        }
        m_levels = m_seen;
        m_tower = now;
        m_tallest = std::max(m_tallest, m_levels);
        if (m_levels >= Levels && !m_finished) {
            ++m_towers;
            m_finished = true;
        }
    }

    // A block let go of: on the tower it is counted above; at rest anywhere else, dropped.
    if (m_released >= 0 && t - m_releasedAt >= Settle &&
        std::count(now.begin(), now.end(), m_released) == 0 &&
        speedOf(world, m_released) < AtRest) {
        ++m_dropped;
        m_released = -1;
        m_pendingLift = -1.0;
    }

    // A finished tower goes back into the pile once the hand has risen clear of it.
    const double top = base(world)[2] + Levels * blockSize(world, m_blocks.front());
    if (m_finished && held < 0 && world.gripperPose(Gripper::Right).pos[2] > top + HandClear) {
        for (int block : m_tower)
            putBack(world, block);
        m_tower.clear();
        m_levels = m_seen = 0;
        m_finished = false;
    }

    // Out of play (neither in the pile, the tower nor the hand) for DropPenalty: back.
    Region pick;
    world.region(QStringLiteral("pick"), &pick);
    for (int block : m_blocks) {
        const bool inPlay = block == held || block == m_carried ||
                            pick.contains(world.objectPosition(block)) ||
                            std::count(now.begin(), now.end(), block) > 0;
        double &since = m_lyingSince[size_t(block)];
        if (inPlay)
            since = -1.0;
        else if (since < 0)
            since = t;
        else if (t - since >= DropPenalty)
            putBack(world, block);
    }
}

void StackingTask::feel(Gripper, const Feeling &, double) {}

QJsonObject StackingTask::metrics() const
{
    return {{QStringLiteral("blocks_stacked"), m_stacked},
            {QStringLiteral("towers_built"), m_towers},
            {QStringLiteral("tallest_tower"), m_tallest},
            {QStringLiteral("topples"), m_topples},
            {QStringLiteral("blocks_dropped"), m_dropped},
            {QStringLiteral("time_per_level"), mean(m_timeSum, m_timed)}};
}

const std::vector<MetricSpec> &StackingTask::metricSpecs()
{
    static const std::vector<MetricSpec> specs = {
        {"blocks_stacked", MetricUnit::Count, MetricBetter::Higher,
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Blocks stacked"),
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Levels the placements added to the tower.")},
        {"towers_built", MetricUnit::Count, MetricBetter::Higher,
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Towers built"),
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Towers stacked five blocks high.")},
        {"tallest_tower", MetricUnit::Count, MetricBetter::Higher,
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Tallest tower"),
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "The most levels the tower had at once.")},
        {"topples", MetricUnit::Count, MetricBetter::Lower,
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Topples"),
         QT_TRANSLATE_NOOP("semhap::MetricSpec",
                           "Times the tower lost levels without a block being taken off it.")},
        {"blocks_dropped", MetricUnit::Count, MetricBetter::Lower,
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Blocks dropped"),
         QT_TRANSLATE_NOOP("semhap::MetricSpec",
                           "Lifted blocks let go of anywhere but on top of the tower.")},
        {"time_per_level", MetricUnit::Seconds, MetricBetter::Lower,
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Time per level"),
         QT_TRANSLATE_NOOP("semhap::MetricSpec",
                           "The mean time from lifting a block to the level it adds.")},
    };
    return specs;
}

} // namespace semhap
