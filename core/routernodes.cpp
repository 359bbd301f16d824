// SPDX-License-Identifier: MIT
#include "routernodes.h"

#include <algorithm>
#include <cmath>

namespace semhap {

void RuntimeNode::onEvent(int, const SemanticEvent &) {}

void RuntimeNode::onSignal(int, double, double) {}

void RuntimeNode::start(double) {}

double RuntimeNode::nextTimer() const
{
    return std::numeric_limits<double>::infinity();
}

void RuntimeNode::fireTimers(double) {}

void RouterActivity::resize(int nodes)
{
    m_nodes.assign(size_t(nodes), NodeActivity());
    for (int i = 0; i < nodes; ++i)
        m_nodes[size_t(i)].node = i;
    m_dirty.assign(size_t(nodes), 0);
    m_changed.clear();
    m_changed.reserve(size_t(nodes));
}

void RouterActivity::set(int node, double t, const PassedMessages &passing)
{
    NodeActivity now;
    now.t = t;
    now.node = node;
    for (const PassedEntry &entry : passing) {
        now.level = std::max(now.level, entry.intensity);
        now.addMessage(int(entry.message));
        now.exception = now.exception || entry.category == Category::Exception;
    }
    NodeActivity &was = m_nodes[size_t(node)];
    if (now.level == was.level && now.sameMessages(was) && now.exception == was.exception)
        return;
    was = now;
    if (!m_dirty[size_t(node)]) {
        m_dirty[size_t(node)] = 1;
        m_changed.push_back(node);
    }
}

void RouterActivity::clearChanges()
{
    for (int node : m_changed)
        m_dirty[size_t(node)] = 0;
    m_changed.clear();
}

void RuntimeNode::emitEvent(const SemanticEvent &event)
{
    reportActivity(event);
    for (const RouteTarget &target : eventTargets)
        target.node->onEvent(target.port, event);
}

void RuntimeNode::probe(int port, const SemanticEvent &event, ProbeWalk *walk) const
{
    if (walk->visited.insert({this, port}).second)
        probeTargets(event, walk);
}

void RuntimeNode::probeTargets(const SemanticEvent &event, ProbeWalk *walk) const
{
    for (const RouteTarget &target : eventTargets)
        target.node->probe(target.port, event, walk);
}

void RuntimeNode::reportActivity(const SemanticEvent &event)
{
    const MessageKey key = PassedMessages::keyOf(event);
    if (event.phase == EventPhase::End)
        m_passed.remove(key);
    else if (PassedEntry *entry = m_passed.insert(key))
        entry->set(event);
    if (m_activity)
        m_activity->set(m_node, event.t, m_passed);
}

void RuntimeNode::emitSignal(double value, double t) const
{
    for (const RouteTarget &target : signalTargets)
        target.node->onSignal(target.port, value, t);
}

void RuntimeNode::emitEvents(const EventBuffer &events, int from)
{
    // Only this node's: nodes downstream (compose) append their own as these flow.
    const int to = events.size();
    for (int i = from; i < to; ++i)
        emitEvent(events[i]);
}

void DetectorNode::process(const ContactFrame &frame, EventBuffer &events)
{
    const int from = events.size();
    m_detector->update(frame, events);
    emitEvents(events, from);
}

void DetectorNode::endAll(double t, EventBuffer &events)
{
    const int from = events.size();
    m_detector->endAll(t, events);
    emitEvents(events, from);
}

bool SignalNode::quantityFromName(const QString &name, Quantity *quantity)
{
    const QStringList names = quantityNames();
    const int index = int(names.indexOf(name));
    if (index < 0)
        return false;
    *quantity = Quantity(index);
    return true;
}

QStringList SignalNode::quantityNames()
{
    // In Quantity's order.
    return {QStringLiteral("F"),
            QStringLiteral("N"),
            QStringLiteral("left.f"),
            QStringLiteral("right.f"),
            QStringLiteral("left.n"),
            QStringLiteral("right.n"),
            QStringLiteral("friction"),
            QStringLiteral("left.friction"),
            QStringLiteral("right.friction")};
}

double SignalNode::frictionUse(const Fingertip &tip) const
{
    return tip.frictionUse(m_mu > 0.0 ? m_mu : tip.mu);
}

void SignalNode::process(const ContactFrame &frame) const
{
    double value = 0.0;
    switch (m_quantity) {
    case Quantity::F:
        value = frame.totalForce();
        break;
    case Quantity::N:
        value = frame.totalContacts();
        break;
    case Quantity::FLeft:
        value = frame.left.f;
        break;
    case Quantity::FRight:
        value = frame.right.f;
        break;
    case Quantity::NLeft:
        value = frame.left.n;
        break;
    case Quantity::NRight:
        value = frame.right.n;
        break;
    case Quantity::Friction:
        value = std::max(frictionUse(frame.left), frictionUse(frame.right));
        break;
    case Quantity::FrictionLeft:
        value = frictionUse(frame.left);
        break;
    case Quantity::FrictionRight:
        value = frictionUse(frame.right);
        break;
    case Quantity::Named: {
        const double *named = frame.signalValues.find(m_signal);
        if (!named)
            return;
        value = *named;
        break;
    }
    }
    emitSignal(value, frame.t);
}

void DerivativeNode::onSignal(int, double value, double t)
{
    emitSignal(m_slope.update(value, t), t);
}

void PredictNode::onSignal(int, double value, double t)
{
    emitSignal(value + m_horizon * m_slope.update(value, t), t);
}

void MessageSourceNode::update(double t, bool condition, double intensity)
{
    if (!m_out)
        return;
    const int from = m_out->size();
    m_tracker.update(t, condition, intensity, *m_out);
    emitEvents(*m_out, from);
}

void MessageSourceNode::endAll(double t, EventBuffer &events)
{
    const int from = events.size();
    m_tracker.forceEnd(t, events);
    emitEvents(events, from);
}

QStringList ThresholdNode::conditionNames()
{
    // In Condition's order.
    return {QStringLiteral("above"), QStringLiteral("below"), QStringLiteral("inside"),
            QStringLiteral("outside")};
}

ThresholdNode::ThresholdNode(int node, Gripper gripper, const Params &params)
    : m_gripper(gripper), m_params(params)
{
    m_tracker.configure(gripper, node, DetectorKind::Threshold, params.message, params.category,
                        params.minDuration);
}

void ThresholdNode::onSignal(int, double value, double t)
{
    // An active message holds at the end levels; with end = begin, above is the strict
    // x > level of the detectors.
    const bool active = m_tracker.isActive();
    const double low = active ? m_params.end : m_params.begin;
    const double high = active ? m_params.endHigh : m_params.beginHigh;
    bool condition = false;
    switch (m_params.condition) {
    case Condition::Above:
        condition = value > low;
        break;
    case Condition::Below:
        condition = value < low;
        break;
    case Condition::Inside:
        condition = value >= low && value <= high;
        break;
    case Condition::Outside:
        condition = value < low || value > high;
        break;
    }
    double intensity = 1.0;
    if (m_params.mapsIntensity) {
        // In steps of IntensityStep: a signal that changes every tick (a friction ratio, a
        // prediction) would otherwise flood the log with updates no band can render.
        const double share = std::clamp((value - m_params.intensityFrom) /
                                            (m_params.intensityTo - m_params.intensityFrom),
                                        0.0, 1.0);
        intensity = std::round(share / IntensityStep) * IntensityStep;
    }
    update(t, condition, intensity);
}

QStringList ComposeNode::modeNames()
{
    // In Mode's order.
    return {QStringLiteral("all"), QStringLiteral("any"), QStringLiteral("while")};
}

ComposeNode::ComposeNode(int node, const Params &params) : m_params(params)
{
    m_tracker.configure(params.gripper, node, DetectorKind::Compose, params.message,
                        params.category);
}

void ComposeNode::onEvent(int port, const SemanticEvent &event)
{
    ActiveMessages &input = m_inputs[size_t(port)];
    const MessageKey key = ActiveMessages::keyOf(event);
    if (event.phase == EventPhase::End)
        input.remove(key);
    else if (ActiveMessages::Entry *entry = input.insert(key))
        entry->last = event;

    // Each input's strongest active message.
    std::array<const SemanticEvent *, 2> strongest{};
    for (size_t i = 0; i < 2; ++i) {
        for (const ActiveEntry &entry : m_inputs[i]) {
            if (!strongest[i] || entry.last.intensity > strongest[i]->intensity)
                strongest[i] = &entry.last;
        }
    }
    const SemanticEvent *a = strongest[0];
    const SemanticEvent *b = strongest[1];
    bool condition = false;
    double intensity = 0.0;
    const SemanticEvent *origin = a;
    switch (m_params.mode) {
    case Mode::All:
        condition = a && b;
        intensity = condition ? std::min(a->intensity, b->intensity) : 0.0;
        break;
    case Mode::Any:
        condition = a || b;
        origin = a && (!b || a->intensity >= b->intensity) ? a : b;
        intensity = origin ? origin->intensity : 0.0;
        break;
    case Mode::While:
        condition = a && b;
        intensity = a ? a->intensity : 0.0;
        break;
    }
    // A message keeps the gripper it began with: downstream knows it by its origin.
    if (!m_params.fixedGripper && condition && !m_tracker.isActive())
        m_tracker.setGripper(origin->gripper);
    update(event.t, condition, intensity);
}

bool FilterNode::passes(const SemanticEvent &event) const
{
    const auto bit = [](auto value) { return 1u << unsigned(value); };
    return (m_messages.empty() ||
            std::find(m_messages.begin(), m_messages.end(), event.message) != m_messages.end()) &&
           (!m_categories || (m_categories & bit(event.category))) &&
           (!m_grippers || (m_grippers & bit(event.gripper)));
}

void FilterNode::onEvent(int, const SemanticEvent &event)
{
    if (passes(event))
        emitEvent(event);
}

void FilterNode::probe(int port, const SemanticEvent &event, ProbeWalk *walk) const
{
    if (passes(event))
        RuntimeNode::probe(port, event, walk);
}

void GateNode::probe(int port, const SemanticEvent &event, ProbeWalk *walk) const
{
    if (port == 0)
        RuntimeNode::probe(port, event, walk);
}

void GateNode::onEvent(int port, const SemanticEvent &event)
{
    const MessageKey key = ActiveMessages::keyOf(event);
    if (port == 0) {
        if (event.phase == EventPhase::End)
            m_inputs.remove(key);
        else if (ActiveMessages::Entry *entry = m_inputs.insert(key))
            entry->last = event;
        if (isOpen())
            emitEvent(event);
        return;
    }

    const bool wasOpen = isOpen();
    if (event.phase == EventPhase::End)
        m_control.remove(key);
    else
        m_control.insert(key);
    const bool open = isOpen();
    if (open == wasOpen)
        return;
    // Closing ends what was passing; opening resumes what is still active, at its intensity.
    for (const ActiveMessages::Entry &entry : m_inputs) {
        SemanticEvent e = entry.last;
        e.t = event.t;
        e.phase = open ? EventPhase::Begin : EventPhase::End;
        emitEvent(e);
    }
}

void DebounceNode::onEvent(int, const SemanticEvent &event)
{
    const MessageKey key = ActiveMessages::keyOf(event);
    ActiveMessages::Entry *entry = m_active.find(key);
    switch (event.phase) {
    case EventPhase::Begin:
        if (entry && entry->endPending) {
            // The message came back within the hold: downstream never saw it end.
            entry->endPending = false;
            if (entry->last.intensity != event.intensity) {
                entry->last = event;
                entry->last.phase = EventPhase::Update;
                emitEvent(entry->last);
            }
            return;
        }
        if ((entry = m_active.insert(key))) {
            entry->last = event;
            emitEvent(event);
        }
        return;
    case EventPhase::Update: {
        if (!entry)
            return;
        const double change = std::abs(event.intensity - entry->last.intensity);
        const bool extreme = event.intensity <= 0.0 || event.intensity >= 1.0;
        if (m_band > 0 && change < m_band && !extreme)
            return;
        entry->last = event;
        emitEvent(event);
        return;
    }
    case EventPhase::End:
        if (!entry)
            return;
        if (m_hold > 0) {
            entry->endPending = true;
            entry->pendingEnd = event.t + m_hold;
            return;
        }
        SemanticEvent end = entry->last;
        end.t = event.t;
        end.phase = EventPhase::End;
        m_active.remove(key);
        emitEvent(end);
        return;
    }
}

double DebounceNode::nextTimer() const
{
    double next = std::numeric_limits<double>::infinity();
    for (const ActiveMessages::Entry &entry : m_active) {
        if (entry.endPending)
            next = std::min(next, entry.pendingEnd);
    }
    return next;
}

void DebounceNode::fireTimers(double t)
{
    for (;;) {
        ActiveMessages::Entry *due = nullptr;
        for (ActiveMessages::Entry &entry : m_active) {
            if (entry.endPending && entry.pendingEnd <= t &&
                (!due || entry.pendingEnd < due->pendingEnd))
                due = &entry;
        }
        if (!due)
            return;
        SemanticEvent end = due->last;
        end.t = due->pendingEnd;
        end.phase = EventPhase::End;
        m_active.remove(due->key);
        emitEvent(end);
    }
}

void CurveNode::probe(int port, const SemanticEvent &event, ProbeWalk *walk) const
{
    SemanticEvent mapped = event;
    mapped.intensity = std::clamp(m_curve.map(event.intensity), 0.0, 1.0);
    RuntimeNode::probe(port, mapped, walk);
}

void CurveNode::onEvent(int, const SemanticEvent &event)
{
    const MessageKey key = ActiveMessages::keyOf(event);
    SemanticEvent mapped = event;
    mapped.intensity = std::clamp(m_curve.map(event.intensity), 0.0, 1.0);
    if (event.phase == EventPhase::End) {
        if (const ActiveMessages::Entry *entry = m_active.find(key))
            mapped.intensity = entry->last.intensity;
        m_active.remove(key);
        emitEvent(mapped);
        return;
    }
    ActiveMessages::Entry *entry = m_active.insert(key);
    if (!entry)
        return;
    if (event.phase == EventPhase::Update && entry->last.intensity == mapped.intensity)
        return;
    entry->last = mapped;
    emitEvent(mapped);
}

void PatternNode::probe(int port, const SemanticEvent &event, ProbeWalk *walk) const
{
    if (walk->visited.insert({this, port}).second)
        walk->hits.emplace_back(this, event);
}

void PatternNode::onEvent(int, const SemanticEvent &event)
{
    const MessageKey key = ActiveMessages::keyOf(event);
    const bool wasActive = !m_active.isEmpty();
    if (event.phase == EventPhase::End) {
        m_active.remove(key);
    } else if (ActiveMessages::Entry *entry = m_active.insert(key)) {
        entry->last = event;
    }

    reportActivity(event); // what it plays
    if (m_active.isEmpty()) {
        if (wasActive) {
            for (const auto &input : voices)
                input->voice.end(event.t);
        }
        return;
    }
    bool exception = false;
    for (const ActiveMessages::Entry &entry : m_active)
        exception = exception || entry.last.category == Category::Exception;
    for (const auto &input : voices)
        input->currentPriority = exception ? PlayerInput::Exception : PlayerInput::Confirmation;
    applyIntensity(event.t);
    if (!wasActive) {
        for (const auto &input : voices)
            input->voice.begin(event.t);
    }
}

void PatternNode::applyIntensity(double t)
{
    double intensity = 0.0;
    for (const ActiveMessages::Entry &entry : m_active)
        intensity = std::max(intensity, entry.last.intensity);
    if (intensity == m_intensity)
        return;
    m_intensity = intensity;
    for (const auto &input : voices)
        input->voice.setParam(ParamTable::Intensity, intensity, t);
}

void PatternNode::onSignal(int port, double value, double t)
{
    const int param = signalParams[size_t(port)];
    for (const auto &input : voices)
        input->voice.setParam(param, value, t);
}

void PatternNode::start(double t)
{
    if (!m_continuous)
        return;
    for (const auto &input : voices) {
        input->currentPriority = PlayerInput::Continuous;
        input->voice.begin(t);
    }
}

void ProportionalNode::onSignal(int, double value, double)
{
    m_value = std::clamp(value / m_ref, 0.0, 1.0);
}

void ProportionalNode::start(double)
{
    m_started = true;
}

} // namespace semhap
