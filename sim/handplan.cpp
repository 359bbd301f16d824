// SPDX-License-Identifier: MIT
#include "handplan.h"

#include <algorithm>

namespace semhap {

double minimumJerk(double s)
{
    s = std::clamp(s, 0.0, 1.0);
    return s * s * s * (10.0 + s * (-15.0 + 6.0 * s));
}

void HandPlan::move(const std::array<double, 3> &to, double seconds)
{
    Segment segment{Segment::Move};
    segment.to = to;
    segment.seconds = seconds;
    m_queue.push_back(segment);
}

void HandPlan::grip(double force, double seconds)
{
    Segment segment{Segment::Grip};
    segment.force = force;
    segment.seconds = seconds;
    m_queue.push_back(segment);
}

void HandPlan::wait(double seconds)
{
    Segment segment{Segment::Wait};
    segment.seconds = seconds;
    m_queue.push_back(segment);
}

void HandPlan::clear()
{
    m_queue.clear();
}

void HandPlan::regrip(double force, double seconds)
{
    if (isGripping())
        m_queue.pop_front();
    Segment segment{Segment::Grip};
    segment.force = force;
    segment.seconds = seconds;
    m_queue.push_front(segment);
}

bool HandPlan::isGripping() const
{
    return !m_queue.empty() && m_queue.front().kind == Segment::Grip;
}

void HandPlan::apply(World &world)
{
    const double now = world.time();
    while (!m_queue.empty()) {
        Segment &segment = m_queue.front();
        if (!segment.started) {
            segment.started = true;
            segment.start = now;
            segment.from = world.target(m_gripper).pos;
            segment.fromForce = world.grip(m_gripper);
        }
        const double s = segment.seconds > 0 ? (now - segment.start) / segment.seconds : 1.0;
        if (segment.kind == Segment::Move) {
            Pose target = world.target(m_gripper);
            const double k = minimumJerk(s);
            for (size_t i = 0; i < 3; ++i)
                target.pos[i] = segment.from[i] + (segment.to[i] - segment.from[i]) * k;
            world.setTarget(m_gripper, target);
        } else if (segment.kind == Segment::Grip) {
            const double k = std::clamp(s, 0.0, 1.0);
            world.setGrip(m_gripper, segment.fromForce + (segment.force - segment.fromForce) * k);
        }
        if (s < 1.0)
            return;
        m_queue.pop_front();
    }
}

} // namespace semhap
