// SPDX-License-Identifier: MIT
#include "frameassembler.h"

#include "nametable.h"

#include <algorithm>
#include <cmath>

namespace semhap {

FrameAssembler::FrameAssembler(const TopicMap &map, ActorTable &actors)
    : m_map(map), m_actors(actors)
{
    for (const Gripper g : {Gripper::Left, Gripper::Right}) {
        const TopicMap::GripperTopics &topics = map.grippers[size_t(g)];
        if (!topics.present)
            continue;
        Hand &hand = m_hands[size_t(g)];
        hand.present = true;
        const QString at = QStringLiteral("/grippers/") + gripperName(g);
        for (int side = 0; side < 2; ++side) {
            const TopicMap::Tip &tip = side == 0 ? topics.left : topics.right;
            const QString tipAt =
                at + (side == 0 ? QStringLiteral("/left") : QStringLiteral("/right"));
            if (!tip.present)
                continue;
            hand.force[size_t(side)] =
                want(int(g), tip.topic, tip.force, 3, tipAt + QStringLiteral("/force"),
                     tipAt + QStringLiteral("/topic"));
            if (tip.hasCount)
                hand.count[size_t(side)] = want(int(g), tip.count.topic, tip.count.field, 1,
                                                tipAt + QStringLiteral("/count/field"),
                                                tipAt + QStringLiteral("/count/topic"));
        }
        for (const TopicMap::Signal &s : topics.signalList)
            hand.signalParts.emplace_back(
                signalNames().intern(s.name),
                want(int(g), s.source.topic, s.source.field, 1,
                     at + QStringLiteral("/signals/") + s.name + QStringLiteral("/field"),
                     at + QStringLiteral("/signals/") + s.name + QStringLiteral("/topic")));
        hand.clock = m_topicIndex.value(topics.clock, -1);
        if (hand.clock < 0) // a clock topic the map reads nothing from still makes frames
            hand.clock =
                want(int(g), topics.clock, QString(), 0, QString(), at + QStringLiteral("/clock"))
                    .topic;
        hand.samples.resize(hand.topicsUsed.size());
    }
}

FrameAssembler::Part FrameAssembler::want(int gripper, const QString &topic, const QString &path,
                                          int width, const QString &pointer,
                                          const QString &topicPointer)
{
    int index = m_topicIndex.value(topic, -1);
    if (index < 0) {
        index = int(m_topics.size());
        m_topics << topic;
        m_topicPointers << topicPointer;
        m_topicIndex.insert(topic, index);
        m_wants.emplace_back();
        m_pointers.emplace_back();
        if (m_map.time == TopicMap::Time::Header) {
            // A type without a header (std_msgs/Int32) is timed by its log time.
            m_wants.back().push_back({QStringLiteral("header.stamp"), 1, true});
            m_pointers.back() << QStringLiteral("/time");
        }
    }
    Hand &hand = m_hands[size_t(gripper)];
    if (std::find(hand.topicsUsed.begin(), hand.topicsUsed.end(), index) == hand.topicsUsed.end())
        hand.topicsUsed.push_back(index);
    Part part;
    part.topic = index;
    if (width == 0)
        return part;
    std::vector<TopicDecoder::Want> &wants = m_wants[size_t(index)];
    int offset = 0;
    for (size_t i = 0; i < wants.size(); ++i) {
        if (wants[i].path == path && wants[i].width == width) {
            part.offset = offset;
            return part;
        }
        offset += wants[i].width;
    }
    wants.push_back({path, width});
    m_pointers[size_t(index)] << pointer;
    part.offset = offset;
    return part;
}

bool FrameAssembler::isOptional(int i) const
{
    for (size_t g = 0; g < m_hands.size(); ++g) {
        const Hand &hand = m_hands[g];
        if (hand.present && !m_map.grippers[g].optional &&
            std::find(hand.topicsUsed.begin(), hand.topicsUsed.end(), i) != hand.topicsUsed.end())
            return false;
    }
    return true;
}

void FrameAssembler::take(int i, double logTime, const double *values)
{
    double t = m_map.time == TopicMap::Time::Header ? values[0] : logTime;
    if (!std::isfinite(t))
        t = logTime;
    for (size_t g = 0; g < m_hands.size(); ++g) {
        Hand &hand = m_hands[g];
        const auto used = std::find(hand.topicsUsed.begin(), hand.topicsUsed.end(), i);
        if (!hand.present || used == hand.topicsUsed.end())
            continue;
        std::deque<Sample> &samples = hand.samples[size_t(used - hand.topicsUsed.begin())];
        int count = 0;
        for (const TopicDecoder::Want &w : m_wants[size_t(i)])
            count += w.width;
        samples.push_back({t, std::vector<double>(values, values + count)});
        if (i == hand.clock) {
            if (!m_started) {
                m_start = t;
                m_started = true;
            }
            hand.pending.push_back(t);
        }
        emitReady(g);
    }
}

const FrameAssembler::Sample *FrameAssembler::latest(const Hand &hand, int topic, double t) const
{
    const auto used = std::find(hand.topicsUsed.begin(), hand.topicsUsed.end(), topic);
    const std::deque<Sample> &samples = hand.samples[size_t(used - hand.topicsUsed.begin())];
    const Sample *best = nullptr;
    for (const Sample &s : samples) {
        if (s.t <= t)
            best = &s;
        else
            break;
    }
    return best;
}

Fingertip FrameAssembler::fingertip(const Hand &hand, const TopicMap::Tip &tip, int side,
                                    double t) const
{
    Fingertip out;
    const Part &force = hand.force[size_t(side)];
    const Sample *sample = tip.present ? latest(hand, force.topic, t) : nullptr;
    if (!sample)
        return out;
    const double *v = sample->values.data() + force.offset;
    if (!std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2]))
        return out;
    out.fxyz = TopicMap::rotate(tip.normalAxis, {v[0], v[1], v[2]});
    out.hasFxyz = true;
    out.f = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    out.n = out.f >= tip.contactThreshold ? 1 : 0;
    const Part &count = hand.count[size_t(side)];
    if (tip.hasCount) {
        const Sample *counted = latest(hand, count.topic, t);
        const double n = counted ? counted->values[size_t(count.offset)] : 0.0;
        out.n = std::isfinite(n) && n > 0 ? int(std::min(std::round(n), 1e6)) : 0;
    }
    out.actor = out.n > 0 ? m_actors.intern(tip.actor) : -1;
    out.mu = tip.mu;
    return out;
}

void FrameAssembler::emitReady(size_t g)
{
    Hand &hand = m_hands[g];
    const TopicMap::GripperTopics &topics = m_map.grippers[g];
    while (!hand.pending.empty()) {
        const double t = hand.pending.front();
        bool passed = true;
        for (size_t u = 0; u < hand.topicsUsed.size(); ++u) {
            if (hand.topicsUsed[u] != hand.clock &&
                (hand.samples[u].empty() || hand.samples[u].back().t <= t))
                passed = false;
        }
        if (!passed && !m_finished && hand.pending.size() <= size_t(MaxPending))
            return;
        ContactFrame frame;
        frame.t = t - m_start;
        frame.gripper = Gripper(g);
        frame.left = fingertip(hand, topics.left, 0, t);
        frame.right = fingertip(hand, topics.right, 1, t);
        for (const auto &[id, part] : hand.signalParts) {
            const Sample *s = latest(hand, part.topic, t);
            if (s && std::isfinite(s->values[size_t(part.offset)]))
                frame.signalValues.set(id, s->values[size_t(part.offset)]);
        }
        hand.ready.push_back(frame);
        hand.pending.pop_front();
        // Keep each topic's latest sample at or before this time: the next frame's from there.
        for (std::deque<Sample> &samples : hand.samples) {
            while (samples.size() >= 2 && samples[1].t <= t)
                samples.pop_front();
        }
    }
}

bool FrameAssembler::next(ContactFrame *frame)
{
    if (!m_released.empty()) {
        *frame = std::move(m_released.front());
        m_released.pop_front();
        return true;
    }
    Hand *earliest = nullptr;
    for (Hand &hand : m_hands) {
        if (!hand.present)
            continue;
        // A gripper with nothing made yet may still make an earlier frame than the other's.
        if (hand.ready.empty()) {
            if (m_finished)
                continue;
            Hand &other = &hand == &m_hands[0] ? m_hands[1] : m_hands[0];
            if (other.ready.size() <= size_t(MaxPending))
                return false;
            continue;
        }
        if (!earliest || hand.ready.front().t < earliest->ready.front().t)
            earliest = &hand;
    }
    if (!earliest)
        return false;
    *frame = std::move(earliest->ready.front());
    earliest->ready.pop_front();
    return true;
}

void FrameAssembler::finish()
{
    m_finished = true;
    for (size_t g = 0; g < m_hands.size(); ++g)
        emitReady(g);
    // Both grippers' frames, merged in time order after any released before.
    std::deque<ContactFrame> released;
    released.swap(m_released);
    ContactFrame frame;
    while (next(&frame))
        released.push_back(std::move(frame));
    m_released.swap(released);
    m_finished = false; // a robot may speak again
}

} // namespace semhap
