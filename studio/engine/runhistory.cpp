// SPDX-License-Identifier: MIT
#include "runhistory.h"

#include "player.h"
#include "router.h"

#include <algorithm>

namespace semhap {

bool isIdleDevice(const Router &router, int device, const Hands &present)
{
    Gripper hand = Gripper::Right;
    return router.deviceHand(device, &hand) && !present[size_t(hand)];
}

std::vector<RunDevice> liveDevicesOf(const Router &router, const Hands &present)
{
    const Player &player = router.player();
    std::vector<RunDevice> devices;
    for (int d = 0; d < player.deviceCount(); ++d) {
        devices.push_back({player.deviceName(d), player.deviceModel(d).name(),
                           player.deviceModel(d).channelNames(),
                           isIdleDevice(router, d, present)});
    }
    return devices;
}

std::array<GripperThresholds, 2> thresholdsOf(const Router &router, const Hands &present)
{
    std::array<GripperThresholds, 2> result{};
    for (const Detector *detector : router.detectors()) {
        if (!present[size_t(detector->gripper())])
            continue;
        std::vector<DetectorLevel> &levels = result[size_t(detector->gripper())].levels;
        for (const DetectorLevel &level : detector->levels())
            levels.push_back(level);
    }
    for (const ThresholdLevels &levels : router.thresholds()) {
        if (!levels.quantity.isEmpty() && present[size_t(levels.signalGripper)])
            result[size_t(levels.signalGripper)].signalThresholds.push_back(levels);
    }
    return result;
}

RunHistory::RunHistory(QObject *parent) : QObject(parent) {}

void RunHistory::start(const std::vector<RunDevice> &devices,
                       const std::array<GripperThresholds, 2> &thresholds,
                       const QStringList &nodeIds)
{
    for (auto &series : m_frames)
        series.clear();
    m_events.clear();
    m_activity.clear();
    m_spans.clear();
    m_devices = devices;
    m_deviceFrames.assign(devices.size(), RunSeries<DeviceFrame>());
    m_thresholds = thresholds;
    m_nodeIds.clear();
    m_nodeMap.clear();
    mapNodes(nodeIds);
    m_metrics = QJsonObject();
    m_now = 0.0;
    m_runNow = 0.0;
    m_dirty = false;
    m_rewound = false;
    emit reset();
}

void RunHistory::assign(const RunHistory &other)
{
    start(other.m_devices, other.m_thresholds, QStringList());
    m_nodeIds = other.m_nodeIds;
    m_nodeMap = other.m_nodeMap;
    for (size_t g = 0; g < m_frames.size(); ++g)
        m_frames[g].appendAll(other.m_frames[g]);
    m_events.appendAll(other.m_events);
    m_activity.appendAll(other.m_activity);
    for (size_t d = 0; d < m_deviceFrames.size(); ++d)
        m_deviceFrames[d].appendAll(other.m_deviceFrames[d]);
    m_spans = other.m_spans;
    m_now = other.m_now;
    m_runNow = other.m_runNow;
    m_dirty = true;
    setMetrics(other.m_metrics);
    commit();
}

void RunHistory::setRouter(const std::vector<RunDevice> &devices,
                           const std::array<GripperThresholds, 2> &thresholds,
                           const QStringList &nodeIds)
{
    std::vector<RunSeries<DeviceFrame>> series(devices.size());
    for (size_t d = 0; d < devices.size(); ++d) {
        for (size_t old = 0; old < m_devices.size(); ++old) {
            if (m_devices[old].name == devices[d].name)
                series[d] = std::move(m_deviceFrames[old]);
        }
    }
    m_devices = devices;
    m_deviceFrames = std::move(series);
    m_thresholds = thresholds;
    m_nodeMap.clear();
    mapNodes(nodeIds);
    emit routerChanged();
}

void RunHistory::mapNodes(const QStringList &nodeIds)
{
    for (const QString &id : nodeIds) {
        int index = int(m_nodeIds.indexOf(id));
        if (index < 0) {
            index = int(m_nodeIds.size());
            m_nodeIds.append(id);
        }
        m_nodeMap.push_back(index);
    }
}

void RunHistory::append(const ContactFrame &frame)
{
    m_frames[size_t(frame.gripper)].append(frame);
    m_now = std::max(m_now, frame.t);
    m_runNow = std::max(m_runNow, frame.t);
    m_dirty = true;
}

int RunHistory::mapNode(int node) const
{
    return node >= 0 && size_t(node) < m_nodeMap.size() ? m_nodeMap[size_t(node)] : -1;
}

void RunHistory::append(const NodeActivity &routed)
{
    NodeActivity activity = routed;
    activity.node = mapNode(routed.node);
    m_activity.append(activity);
    m_now = std::max(m_now, activity.t);
    m_runNow = std::max(m_runNow, activity.t);
    m_dirty = true;
}

void RunHistory::append(const SemanticEvent &routed)
{
    SemanticEvent event = routed;
    event.node = mapNode(routed.node);
    m_events.append(event);
    m_now = std::max(m_now, event.t);
    m_runNow = std::max(m_runNow, event.t);
    m_dirty = true;
    const QString node = nodeName(event.node);
    if (event.phase == EventPhase::Begin) {
        MessageSpan span;
        span.gripper = event.gripper;
        span.node = node;
        span.detector = event.detector;
        span.message = event.message;
        span.category = event.category;
        span.begin = event.t;
        span.end = event.t;
        span.peak = event.intensity;
        m_spans.push_back(span);
        return;
    }
    // The newest open span of this detector and message.
    for (auto it = m_spans.rbegin(); it != m_spans.rend(); ++it) {
        if (!it->active || it->node != node || it->message != event.message)
            continue;
        it->end = event.t;
        it->peak = std::max(it->peak, event.intensity);
        it->active = event.phase != EventPhase::End;
        break;
    }
}

void RunHistory::append(const DeviceFrame &frame)
{
    if (frame.device < 0 || size_t(frame.device) >= m_deviceFrames.size())
        return;
    RunSeries<DeviceFrame> &series = m_deviceFrames[size_t(frame.device)];
    if (!series.isEmpty() && frame.t < series.last().t) {
        series.dropAfter(frame.t);
        m_rewound = true;
    }
    series.append(frame);
    m_now = std::max(m_now, frame.t);
    m_dirty = true;
}

double RunHistory::latest() const
{
    double t = 0.0;
    const auto newest = [&t](const auto &series) {
        if (!series.isEmpty())
            t = std::max(t, series.last().t);
    };
    for (const auto &series : m_frames)
        newest(series);
    newest(m_events);
    newest(m_activity);
    for (const auto &series : m_deviceFrames)
        newest(series);
    return t;
}

void RunHistory::setMetrics(const QJsonObject &metrics)
{
    if (metrics == m_metrics)
        return;
    m_metrics = metrics;
    emit metricsChanged();
}

void RunHistory::commit()
{
    if (!m_dirty)
        return;
    m_dirty = false;
    if (m_rewound) {
        m_rewound = false;
        m_now = latest();
    }
    const double oldest = m_now - m_keepSeconds;
    for (auto &series : m_frames)
        series.trimBefore(oldest);
    m_events.trimBefore(oldest);
    m_activity.trimBefore(oldest);
    for (auto &series : m_deviceFrames)
        series.trimBefore(oldest);
    // Open spans grow with the run's time even without events (not with an audition's).
    for (auto &span : m_spans) {
        if (span.active)
            span.end = m_runNow;
    }
    m_spans.erase(
        std::remove_if(m_spans.begin(), m_spans.end(),
                       [oldest](const MessageSpan &s) { return !s.active && s.end < oldest; }),
        m_spans.end());
    emit updated();
}

void RunHistory::setKeepSeconds(double seconds)
{
    m_keepSeconds = std::max(1.0, seconds);
}

QString RunHistory::nodeName(int node) const
{
    return node >= 0 && node < m_nodeIds.size() ? m_nodeIds[node] : QString();
}

} // namespace semhap
