// SPDX-License-Identifier: MIT
#include "wipingoperator.h"

#include "perception.h"
#include "world.h"

#include <mujoco/mujoco.h>

#include <algorithm>
#include <cmath>

namespace semhap {

namespace {

constexpr double Pi = 3.14159265358979323846;
// The grip the left hand holds the plate's rim with (N): firm, far below the plate's limit.
constexpr double HoldGrip = 15.0;
constexpr double HoldGripSd = 2.0;
// The intended press: how far below the plate's face the person puts the sponge's face (m).
// With the holder's 1000 N/m that is about 12 N, a firm wipe; the person's eye misjudges the
// plate's height by a little each visit.
constexpr double PressDepth = 0.012;
constexpr double PressDepthSd = 0.0025;
constexpr double SurfaceErrorSd = 0.0015;
constexpr double StrokeDepthSd = 0.0008;
// A slow fluctuation of the press while wiping: amplitude (m) and frequency (Hz).
constexpr double Tremor = 0.001;
constexpr double TremorHz = 1.2;
// The plate is wiped in three lanes across its stained square (m from its centre), each
// visit four strokes between x = -StrokeHalf and +StrokeHalf.
constexpr std::array<double, 3> Lanes{-0.047, 0.0, 0.047};
constexpr double StrokeHalf = 0.06;
constexpr int Strokes = 4;
// Heights above the plate's face where the sponge travels between lanes (m).
constexpr double Approach = 0.03;
constexpr double WaitAbove = 0.08;
// The reactive person on a warning: eases off by this share of the press now, at this speed
// (m/s), and presses less by it from then on (never below the floor share of its habit).
constexpr double EaseShare = 0.3;
constexpr double EaseSpeed = 0.03;
constexpr double PressFloor = 0.3;
// Waits after taking the next plate before wiping again (s).
constexpr double RegripPause = 0.8;

} // namespace

WipingOperator::WipingOperator(const World &world, std::uint64_t seed, bool reactive,
                               double reactionTime)
    : m_random(seed), m_reactive(reactive), m_reactionTime(reactionTime),
      m_plate(world.objectIndex(QStringLiteral("plate")))
{
    // The person knows its tool: how far below the wrist the sponge's face hangs.
    const int sponge = world.geomIndex(QStringLiteral("right.sponge"));
    m_reach = world.gripperPose(Gripper::Right).pos[2] -
              (world.data()->geom_xpos[3 * sponge + 2] - world.model()->geom_size[3 * sponge + 2]);
    m_pos = world.target(Gripper::Right).pos;
    m_tremorPhase = m_random.uniform(0, 2 * Pi);
    m_holdGrip = std::max(5.0, m_random.normal(HoldGrip, HoldGripSd));
    m_left.grip(m_holdGrip, 0.5);
}

QString WipingOperator::name() const
{
    return m_reactive ? QStringLiteral("reactive") : QStringLiteral("scripted");
}

void WipingOperator::planLane(const World &world)
{
    const auto plate = world.objectPosition(m_plate);
    const double seen = plate[2] + world.objects()[size_t(m_plate)].upper[2] +
                        m_random.normal(0.0, SurfaceErrorSd);
    const double pace = m_random.uniform(0.85, 1.2);
    m_depth = std::clamp(m_random.normal(PressDepth, PressDepthSd), 0.004, 0.022) * m_pressScale;
    m_ease = 0.0;
    m_easeTarget = 0.0;
    const double y = plate[1] + Lanes[size_t(m_lane)];
    m_lane = (m_lane + 1) % int(Lanes.size());
    const double above = seen + Approach + m_reach;
    const double down = seen - m_depth + m_reach;
    const double start = plate[0] + m_side * StrokeHalf;
    m_path.push_back({{start, y, above}, 0.6 * pace});
    m_path.push_back({{start, y, down}, 0.5 * pace, true});
    m_path.push_back({{start, y, down}, 0.2 * pace, true, true});
    double x = start;
    for (int k = 0; k < Strokes; ++k) {
        x = plate[0] + (k % 2 == 0 ? -m_side : m_side) * StrokeHalf;
        m_path.push_back({{x, y, down + m_random.normal(0.0, StrokeDepthSd)}, 0.9 * pace, true});
    }
    m_path.push_back({{x, y, above}, 0.4 * pace});
}

std::array<double, 3> WipingOperator::follow(double t)
{
    while (!m_path.empty()) {
        const Segment &segment = m_path.front();
        if (!m_segmentStarted) {
            m_segmentStarted = true;
            m_segmentStart = t;
            m_from = m_pos;
        }
        const double s = segment.seconds > 0 ? (t - m_segmentStart) / segment.seconds : 1.0;
        const double k = minimumJerk(s);
        for (size_t i = 0; i < 3; ++i)
            m_pos[i] = m_from[i] + (segment.to[i] - m_from[i]) * k;
        if (s < 1.0)
            break;
        m_path.pop_front();
        m_segmentStarted = false;
    }
    return m_pos;
}

bool WipingOperator::handleBrokenPlate(World &world)
{
    // What the eyes see: the plate gone. Let go, lift the sponge clear, wait for the next
    // plate, take it, and begin again with a new lane visit.
    const bool broken = world.objects()[size_t(m_plate)].broken;
    const double t = world.time();
    if (broken && !m_plateOut) {
        m_plateOut = true;
        m_plateBack = -1.0;
        m_left.clear();
        m_left.grip(HandPlan::OpenGrip, 0.15);
        m_path.clear();
        m_segmentStarted = false;
        const double face =
            world.homePosition(m_plate)[2] + world.objects()[size_t(m_plate)].upper[2];
        m_path.push_back({{m_pos[0], m_pos[1], face + WaitAbove + m_reach}, 0.5});
        m_ease = 0.0;
        m_easeTarget = 0.0;
    } else if (m_plateOut && !broken && m_plateBack < 0) {
        m_plateBack = t;
        m_left.grip(m_holdGrip, 0.5);
    } else if (m_plateOut && !broken && t - m_plateBack >= RegripPause) {
        m_plateOut = false;
    }
    return m_plateOut;
}

void WipingOperator::act(World &world)
{
    const double t = world.time();
    while (!m_percepts.empty() && m_percepts.front().due <= t) {
        react(m_percepts.front());
        m_percepts.pop_front();
    }
    if (m_plate >= 0 && !handleBrokenPlate(world) && m_path.empty())
        planLane(world);
    m_left.apply(world);

    const bool pressing = !m_path.empty() && m_path.front().pressing;
    const std::array<double, 3> nominal = follow(t);
    const double step = EaseSpeed * world.timestep();
    m_ease += std::clamp(m_easeTarget - m_ease, -step, step);
    Pose target = world.target(Gripper::Right);
    target.pos = nominal;
    target.pos[2] += m_ease;
    if (pressing)
        target.pos[2] += Tremor * std::sin(2 * Pi * TremorHz * t + m_tremorPhase);
    world.setTarget(Gripper::Right, target);
}

void WipingOperator::engage(const World &world)
{
    // The path and the plate's hold as planned before the hand-over are stale: resumed, the
    // sponge would jump to where its stroke had got to.
    m_path.clear();
    m_segmentStarted = false;
    m_percepts.clear();
    m_pos = world.target(Gripper::Right).pos;
    m_ease = 0.0;
    m_easeTarget = 0.0;
    const double face = world.homePosition(m_plate)[2] + world.objects()[size_t(m_plate)].upper[2];
    m_path.push_back({{m_pos[0], m_pos[1], std::max(m_pos[2], face + WaitAbove + m_reach)}, 0.5});
    m_left.clear();
    if (!m_plateOut)
        m_left.grip(m_holdGrip, 0.5);
}

void WipingOperator::react(const Percept &percept)
{
    if (m_path.empty() || !m_path.front().pressing)
        return; // felt while off the plate: nothing to change
    Segment &now = m_path.front();
    if (!percept.warning) {
        // Engaged: the sponge is on the plate, the strokes can begin.
        if (now.settle)
            now.seconds = 0.0;
        return;
    }
    m_easeTarget += EaseShare * (m_depth - m_easeTarget);
    m_pressScale = std::max(PressFloor, m_pressScale * (1.0 - EaseShare));
}

void WipingOperator::feel(Gripper hand, const Feeling &feeling, double t)
{
    if (!m_reactive || hand != Gripper::Right)
        return;
    const std::array<double, 2> levels{std::max(feeling.confirmation, feeling.shownConfirmation),
                                       std::max(feeling.warning, feeling.shownWarning)};
    for (size_t cue = 0; cue < levels.size(); ++cue) {
        if (levels[cue] < Perception::Noticeable)
            continue;
        if (t - m_lastFelt[cue] > Perception::PulseGap)
            m_percepts.push_back({t + m_reactionTime, cue == 1});
        m_lastFelt[cue] = t;
    }
}

} // namespace semhap
