// SPDX-License-Identifier: MIT
#pragma once

#include "actortable.h"
#include "contactframe.h"
#include "topicdecoder.h"
#include "topicmap.h"

#include <QHash>
#include <QStringList>

#include <array>
#include <deque>
#include <vector>

namespace semhap {

/**
 * Turns a robot's decoded topic messages into contact frames as a topic map says
 * (docs/ros.md): a frame for a gripper at each message of its clock topic, each fingertip's
 * part from that tip's latest message at or before the clock message's time. Messages may
 * come out of time order across topics (header stamps lag the log): a frame waits until
 * every other topic of its gripper has passed its time, at most MaxPending clock messages,
 * so that no later message could still belong to it.
 */
class FrameAssembler
{
public:
    /** The most clock messages a gripper's frames wait for a silent topic. */
    static constexpr int MaxPending = 1024;

    FrameAssembler(const TopicMap &map, ActorTable &actors);

    /** The topics the map reads, each once. */
    const QStringList &topics() const { return m_topics; }
    /** The index of `topic` in topics(), or -1. */
    int topicIndex(const QString &topic) const { return m_topicIndex.value(topic, -1); }
    /** What is read from topic `i`: the header's stamp first when the map's time is the header's.
     */
    const std::vector<TopicDecoder::Want> &wants(int i) const { return m_wants[size_t(i)]; }
    /** The map's JSON pointer that asked for each of topic `i`'s wants, for errors. */
    const QStringList &pointers(int i) const { return m_pointers[size_t(i)]; }
    /** Whether a recording may lack topic `i`: only optional grippers read it. */
    bool isOptional(int i) const;
    /** The map's JSON pointer that first names topic `i`, for errors. */
    QString topicPointer(int i) const { return m_topicPointers[i]; }

    /**
     * A message of topic `i`, logged (or arrived) at `logTime` seconds, with its wants'
     * values. With the header's time, a message without a header stamp (NaN: a type without
     * a header, a JSON message lacking it) is timed by its log time.
     */
    void take(int i, double logTime, const double *values);
    /**
     * The next frame made, in time order across the grippers (a gripper's frames wait for
     * the other's, at most MaxPending); false when none is ready.
     */
    bool next(ContactFrame *frame);
    /**
     * No more messages for now (the end of a recording, a robot fallen silent): every frame
     * still waiting is made and handed on by next(). Messages may follow.
     */
    void finish();
    /** The time (s, in the messages' clock) that frames count from: the first clock message's. */
    double start() const { return m_start; }
    /** Frames count from `t` (s, in the messages' clock) instead. */
    void setStart(double t)
    {
        m_start = t;
        m_started = true;
    }

private:
    struct Sample
    {
        double t;
        std::vector<double> values;
    };
    struct Part
    {
        int topic = -1;
        int offset = -1; ///< of the part's first number among the topic's values
    };
    struct Hand
    {
        bool present = false;
        int clock = -1;
        std::array<Part, 2> force;                     ///< left, right tip
        std::array<Part, 2> count;                     ///< left, right tip; topic -1 without
        std::vector<std::pair<int, Part>> signalParts; ///< signalNames() id
        std::vector<int> topicsUsed;
        std::vector<std::deque<Sample>> samples; ///< per topicsUsed
        std::deque<double> pending;              ///< clock messages' times, waiting
        std::deque<ContactFrame> ready;          ///< made, waiting for the other gripper's
    };

    Part want(int gripper, const QString &topic, const QString &path, int width,
              const QString &pointer, const QString &topicPointer);
    void emitReady(size_t gripper);
    const Sample *latest(const Hand &hand, int topic, double t) const;
    Fingertip fingertip(const Hand &hand, const TopicMap::Tip &tip, int side, double t) const;

    TopicMap m_map;
    ActorTable &m_actors;
    QStringList m_topics;
    QHash<QString, int> m_topicIndex;
    std::vector<std::vector<TopicDecoder::Want>> m_wants;
    std::vector<QStringList> m_pointers;
    QStringList m_topicPointers;
    std::array<Hand, 2> m_hands;
    std::deque<ContactFrame> m_released; ///< made by finish(), in time order
    double m_start = 0.0;
    bool m_started = false;
    bool m_finished = false;
};

} // namespace semhap
