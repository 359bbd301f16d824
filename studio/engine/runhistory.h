// SPDX-License-Identifier: MIT
#pragma once

#include "contactframe.h"
#include "detector.h"
#include "deviceframe.h"
#include "nodeactivity.h"
#include "router.h"
#include "semanticevent.h"

#include <QJsonObject>
#include <QObject>
#include <QStringList>

#include <algorithm>
#include <array>
#include <deque>
#include <vector>

namespace semhap {

/** The active detectors' thresholds for one gripper, drawn as lines on its plots. */
struct GripperThresholds
{
    /** The levels of the detectors on this gripper's frames, as they report them. */
    std::vector<DetectorLevel> levels;
    /** The threshold nodes reading a signal of this gripper's frames, in graph order. */
    std::vector<ThresholdLevels> signalThresholds;
};

/** One device of the running router, as the panels list it. */
struct RunDevice
{
    QString name;  ///< the router's device name (`right.vibro`)
    QString model; ///< the device model's name
    QStringList channels;
    /** Its hand is not in the scene (a left band on a one-handed task): it never plays. */
    bool idle = false;
};

/** Which hands a run has, by Gripper: a scene's grippers, or a session's recorded frames. */
using Hands = std::array<bool, 2>;

/**
 * The thresholds each present hand's detectors fire at, and the threshold nodes reading its
 * signals, as the router compiled them; an absent hand's never fire, so it gets none.
 */
std::array<GripperThresholds, 2> thresholdsOf(const Router &router, const Hands &present);

/** The router's devices as the panels list them; those of an absent hand are idle. */
std::vector<RunDevice> liveDevicesOf(const Router &router, const Hands &present);

/** Whether the router's device `device` belongs to a hand the run does not have. */
bool isIdleDevice(const Router &router, int device, const Hands &present);

/** A semantic message from its begin to its end (open while `active`). */
struct MessageSpan
{
    Gripper gripper = Gripper::Right;
    QString node; ///< the detector's node id
    DetectorKind detector = DetectorKind::Force;
    Message message = Message::Grasp;
    Category category = Category::Confirmation;
    double begin = 0.0;
    double end = 0.0; ///< the latest time seen while active
    bool active = true;
    double peak = 0.0; ///< the highest intensity it reached
};

/**
 * A growing series the GUI reads by running index: values keep their index while the
 * oldest are trimmed, so a view remembers where it stopped and reads only what is new —
 * unless the newest were taken back (rewinds() changed): then it reads all again.
 */
template<typename T> class RunSeries
{
public:
    qint64 begin() const { return m_first; }
    qint64 end() const { return m_first + qint64(m_values.size()); }
    const T &at(qint64 index) const { return m_values[size_t(index - m_first)]; }
    bool isEmpty() const { return m_values.empty(); }
    const T &last() const { return m_values.back(); }
    /** The latest value at or before `t` (by its `t`), or null when the series starts after. */
    const T *latestAt(double t) const
    {
        // The first value after t, by bisection: the values are in time order.
        const auto after =
            std::upper_bound(m_values.begin(), m_values.end(), t,
                             [](double at, const T &value) { return at < value.t; });
        return after == m_values.begin() ? nullptr : &*(after - 1);
    }
    void append(const T &value) { m_values.push_back(value); }
    /** Appends `other`'s values, oldest first (they get this series' next indices). */
    void appendAll(const RunSeries &other)
    {
        m_values.insert(m_values.end(), other.m_values.begin(), other.m_values.end());
    }
    /** Drops the values older than `t` (by their `t`). */
    void trimBefore(double t)
    {
        while (!m_values.empty() && m_values.front().t < t) {
            m_values.pop_front();
            ++m_first;
        }
    }
    /** Drops the values newer than `t` (by their `t`); counts a rewind if any went. */
    void dropAfter(double t)
    {
        if (m_values.empty() || !(m_values.back().t > t))
            return;
        while (!m_values.empty() && m_values.back().t > t)
            m_values.pop_back();
        ++m_rewinds;
    }
    /** How often values were taken back from the end: what a view read of them is gone. */
    int rewinds() const { return m_rewinds; }
    void clear()
    {
        m_first += qint64(m_values.size());
        m_values.clear();
    }

private:
    std::deque<T> m_values;
    qint64 m_first = 0;
    int m_rewinds = 0;
};

/**
 * What the studio has seen of the running pipeline — contact frames per gripper, semantic
 * events and the message spans they make, device frames per device, the task metrics —
 * kept for the last `keepSeconds()` of pipeline time. GUI thread only: the engine fills it
 * from its lock-free feed at display rate and calls commit(), and every panel reads it.
 */
class RunHistory : public QObject
{
    Q_OBJECT

public:
    explicit RunHistory(QObject *parent = nullptr);

    /** Forgets everything and describes the new run; emits `reset()`. */
    void start(const std::vector<RunDevice> &devices,
               const std::array<GripperThresholds, 2> &thresholds, const QStringList &nodeIds);
    /**
     * Holds what `other` holds instead, as a run shown anew: views drop what they show
     * (`reset()`), then read it all (`updated()`); what is older than keepSeconds() goes.
     * How a run set aside for a replay comes back with its plots and log.
     */
    void assign(const RunHistory &other);

    /**
     * Describes a router swapped into the running session (the router editor's Apply),
     * keeping the contact frames, events and spans seen so far: device series carry over by
     * device name, and events keep naming the detectors they came from. Emits
     * `routerChanged()`. Drain the old router's output first: frames and events appended
     * afterwards are read with the new router's numbering.
     */
    void setRouter(const std::vector<RunDevice> &devices,
                   const std::array<GripperThresholds, 2> &thresholds, const QStringList &nodeIds);

    void append(const ContactFrame &frame);
    /** Keeps `event`, its `node` renumbered from the running router's to the history's. */
    void append(const SemanticEvent &event);
    /**
     * Keeps what a device was sent. A frame earlier than the device's newest takes the time
     * after it back: the paused run goes on from where it stopped, and what an audition drew
     * ahead of it leaves the device's series (and now() follows).
     */
    void append(const DeviceFrame &frame);
    /** Keeps a router node's activity, its `node` renumbered like an event's. */
    void append(const NodeActivity &activity);
    void setMetrics(const QJsonObject &metrics);
    /** Trims what is older than the kept window and emits `updated()` if anything came. */
    void commit();

    /** How much pipeline time is kept (s); at least the plots' widest window. */
    double keepSeconds() const { return m_keepSeconds; }
    void setKeepSeconds(double seconds);

    /** The latest time seen (s): the run's, or an audition's drawn on past a paused run. */
    double now() const { return m_now; }

    const RunSeries<ContactFrame> &frames(Gripper gripper) const
    {
        return m_frames[size_t(gripper)];
    }
    const RunSeries<SemanticEvent> &events() const { return m_events; }
    const std::vector<MessageSpan> &spans() const { return m_spans; }
    /** Router nodes' activity changes, in order (node: nodeName()'s index). */
    const RunSeries<NodeActivity> &activity() const { return m_activity; }
    const std::vector<RunDevice> &devices() const { return m_devices; }
    const RunSeries<DeviceFrame> &deviceFrames(int device) const
    {
        return m_deviceFrames[size_t(device)];
    }
    const std::array<GripperThresholds, 2> &thresholds() const { return m_thresholds; }
    /** The node id of an event or activity (`right.force`), under any router of the session. */
    QString nodeName(int node) const;
    const QJsonObject &metrics() const { return m_metrics; }

signals:
    /** A new run started: views drop what they show. */
    void reset();
    /** The router changed while the session goes on: views rebuild what depends on it. */
    void routerChanged();
    /** New data arrived (at most once per display frame). */
    void updated();
    void metricsChanged();

private:
    void mapNodes(const QStringList &nodeIds);
    /** The newest time any series holds. */
    double latest() const;
    /** The running router's node index as the history's. */
    int mapNode(int node) const;

    std::array<RunSeries<ContactFrame>, 2> m_frames;
    RunSeries<SemanticEvent> m_events;
    RunSeries<NodeActivity> m_activity;
    std::vector<MessageSpan> m_spans;
    std::vector<RunDevice> m_devices;
    std::vector<RunSeries<DeviceFrame>> m_deviceFrames;
    std::array<GripperThresholds, 2> m_thresholds{};
    QStringList m_nodeIds;      ///< every node id seen this session; events index it
    std::vector<int> m_nodeMap; ///< the running router's node index -> index in m_nodeIds
    QJsonObject m_metrics;
    double m_keepSeconds = 120.0;
    double m_now = 0.0;
    double m_runNow = 0.0; ///< the run's own latest time (not a device's): where open spans end
    bool m_dirty = false;
    bool m_rewound = false; ///< a device series was taken back since the last commit
};

} // namespace semhap
