// SPDX-License-Identifier: MIT
#pragma once

// The running forms of router nodes. Private to the core: Router builds them from a graph.

#include "contactframe.h"
#include "detector.h"
#include "eventbuffer.h"
#include "messagetracker.h"
#include "nodeactivity.h"
#include "player.h"
#include "slopefilter.h"
#include "voice.h"
#include "waveform.h"

#include <array>
#include <limits>
#include <memory>
#include <set>
#include <vector>

namespace semhap {

class RuntimeNode;
class PatternNode;

/**
 * A probe's walk through the graph (Router::messageRoutes): the pattern nodes it reached,
 * each with the message as it arrived there, and the inputs already visited, so each is
 * walked once however many ways lead to it.
 */
struct ProbeWalk
{
    std::vector<std::pair<const PatternNode *, SemanticEvent>> hits;
    std::set<std::pair<const RuntimeNode *, int>> visited; ///< node and input port
};

/** Where a node's output goes: a node and its input port index. */
struct RouteTarget
{
    RuntimeNode *node;
    int port;
};

/** A message's origin: its detector node and its Message id, in one number. */
using MessageKey = long long;

/**
 * A set of messages keyed by their origin (detector node and message), each with an `Entry`
 * of what a node keeps of it. Fixed capacity: a node listens to at most Capacity distinct
 * messages, which the compiler checks, so nothing allocates while events flow.
 */
template<typename EntryType> class MessageSet
{
public:
    using Entry = EntryType;
    static constexpr int Capacity = 16;

    static MessageKey keyOf(const SemanticEvent &e)
    {
        return MessageKey(e.node) << 32 | MessageKey(unsigned(e.message));
    }

    Entry *find(MessageKey key)
    {
        for (Entry &entry : *this) {
            if (entry.key == key)
                return &entry;
        }
        return nullptr;
    }
    /** The entry of `key`, new (default values) when there was none; null when full. */
    Entry *insert(MessageKey key)
    {
        if (Entry *existing = find(key))
            return existing;
        if (m_size == Capacity)
            return nullptr;
        Entry &entry = m_entries[size_t(m_size++)];
        entry = Entry();
        entry.key = key;
        return &entry;
    }
    void remove(MessageKey key)
    {
        for (int i = 0; i < m_size; ++i) {
            if (m_entries[size_t(i)].key == key) {
                // Keep insertion order: replays (gate reopening) follow the order messages
                // began.
                std::move(m_entries.begin() + i + 1, m_entries.begin() + m_size,
                          m_entries.begin() + i);
                --m_size;
                return;
            }
        }
    }
    int size() const { return m_size; }
    bool isEmpty() const { return m_size == 0; }
    Entry *begin() { return m_entries.data(); }
    Entry *end() { return m_entries.data() + m_size; }
    const Entry *begin() const { return m_entries.data(); }
    const Entry *end() const { return m_entries.data() + m_size; }

private:
    std::array<Entry, Capacity> m_entries{};
    int m_size = 0;
};

/** What a logic node keeps of an active message: the last event, and a held-back end. */
struct ActiveEntry
{
    MessageKey key = -1;
    SemanticEvent last;      ///< the last event passed on for this message
    double pendingEnd = 0.0; ///< hysteresis: time the held-back end is due
    bool endPending = false;
};
using ActiveMessages = MessageSet<ActiveEntry>;

/**
 * What a node's activity needs of a message it passes on: kept by every node, so kept small
 * (a router may have a million nodes).
 */
struct PassedEntry
{
    MessageKey key = -1;
    Message message = Message::Grasp;
    Category category = Category::Confirmation;
    double intensity = 0.0;

    void set(const SemanticEvent &event)
    {
        message = event.message;
        category = event.category;
        intensity = event.intensity;
    }
};
using PassedMessages = MessageSet<PassedEntry>;

/**
 * Every node's activity and which nodes changed since the router last reported them. Sized
 * when the router is compiled; updating it never allocates.
 */
class RouterActivity
{
public:
    void resize(int nodes);
    /** Node `node` passes `passing` from t on; recorded only when that changes what it shows. */
    void set(int node, double t, const PassedMessages &passing);
    const std::vector<NodeActivity> &nodes() const { return m_nodes; }
    /** The nodes whose activity changed since clearChanges(), in the order they changed. */
    const std::vector<int> &changed() const { return m_changed; }
    void clearChanges();

private:
    std::vector<NodeActivity> m_nodes;
    std::vector<int> m_changed; ///< capacity: every node once
    std::vector<char> m_dirty;  ///< per node: listed in m_changed
};

/** A node of a compiled router. Events flow depth-first along the links, in link order. */
class RuntimeNode
{
public:
    virtual ~RuntimeNode() = default;

    /** Where the node reports what it passes on; set by the compiler. */
    void setActivity(RouterActivity *activity, int node)
    {
        m_activity = activity;
        m_node = node;
    }

    virtual void onEvent(int port, const SemanticEvent &event);
    virtual void onSignal(int port, double value, double t);
    /** Starts the node at the session's first frame. */
    virtual void start(double t);
    /** When the node next needs fireTimers (infinity: never). */
    virtual double nextTimer() const;
    virtual void fireTimers(double t);
    /** Whether it may set timers: the router then asks nextTimer() after every tick. */
    virtual bool hasTimers() const { return false; }

    /**
     * Follows a begin of `event` arriving at input `port` to the pattern nodes it can reach,
     * as it would flow: filters match it, curves map its intensity, a gate is taken as open,
     * a compose node makes a message of its own (its own probe).
     */
    virtual void probe(int port, const SemanticEvent &event, ProbeWalk *walk) const;
    /** Follows `event` from this node's event output. */
    void probeTargets(const SemanticEvent &event, ProbeWalk *walk) const;

    std::vector<RouteTarget> eventTargets;
    std::vector<RouteTarget> signalTargets;

protected:
    /** Sends `event` on, and records what the node now passes. */
    void emitEvent(const SemanticEvent &event);
    /** Emits the events of `events` from index `from` on (those this node just added). */
    void emitEvents(const EventBuffer &events, int from);
    void emitSignal(double value, double t) const;
    /** Records `event` as passed on (or ended) and reports what the node now passes. */
    void reportActivity(const SemanticEvent &event);

private:
    RouterActivity *m_activity = nullptr;
    int m_node = -1;
    PassedMessages m_passed; ///< what the node passes on now
};

/** Runs a detector on its gripper's frames and sends its events on. */
class DetectorNode : public RuntimeNode
{
public:
    explicit DetectorNode(std::unique_ptr<Detector> detector) : m_detector(std::move(detector)) {}
    void process(const ContactFrame &frame, EventBuffer &events);
    void endAll(double t, EventBuffer &events);
    Detector &detector() { return *m_detector; }
    const Detector &detector() const { return *m_detector; }

private:
    std::unique_ptr<Detector> m_detector;
};

/** A continuous quantity of one gripper's frames. */
class SignalNode : public RuntimeNode
{
public:
    enum class Quantity
    {
        F,
        N,
        FLeft,
        FRight,
        NLeft,
        NRight,
        Friction,
        FrictionLeft,
        FrictionRight,
        Named ///< one of the frame's named signals
    };
    static bool quantityFromName(const QString &name, Quantity *quantity);
    /** The built-in quantities' names, in Quantity's order (Named has none). */
    static QStringList quantityNames();

    /**
     * `mu` > 0 overrides the frames' friction coefficient for the friction quantities;
     * `signal` is the named signal's signalNames() id for Named. A frame without that signal
     * sends no value.
     */
    SignalNode(Gripper gripper, Quantity quantity, double mu = 0.0, int signal = -1)
        : m_gripper(gripper), m_quantity(quantity), m_mu(mu), m_signal(signal)
    {}
    Gripper gripper() const { return m_gripper; }
    void process(const ContactFrame &frame) const;

private:
    double frictionUse(const Fingertip &tip) const;

    Gripper m_gripper;
    Quantity m_quantity;
    double m_mu;
    int m_signal;
};

/** Sends on the smoothed time derivative of its input. */
class DerivativeNode : public RuntimeNode
{
public:
    explicit DerivativeNode(double tau) : m_slope(tau) {}
    void onSignal(int port, double value, double t) override;

private:
    SlopeFilter m_slope;
};

/** Sends on its input extrapolated over a horizon: x + horizon * (smoothed slope). */
class PredictNode : public RuntimeNode
{
public:
    explicit PredictNode(double tau) : m_slope(tau) {}
    void setHorizon(double horizon) { m_horizon = horizon; }
    double horizon() const { return m_horizon; }
    void onSignal(int port, double value, double t) override;

private:
    SlopeFilter m_slope;
    double m_horizon = 0.0;
};

/**
 * A node that raises messages of its own inside the router (threshold, compose): its events
 * go into the tick's event buffer like a detector's, then on along its links.
 */
class MessageSourceNode : public RuntimeNode
{
public:
    /** Where events go from now on (the router sets it before each tick and timer). */
    void setOutput(EventBuffer *out) { m_out = out; }
    /** Ends the message now if active (end of a run, router swap). */
    void endAll(double t, EventBuffer &events);
    /** Appends a begin at t if the message is active (MessageTracker::appendActive). */
    void appendActive(double t, EventBuffer &events) const { m_tracker.appendActive(t, events); }
    /** A begin of its message at `intensity` (MessageTracker::probe). */
    SemanticEvent probeMessage(double intensity) const { return m_tracker.probe(intensity); }
    /** Its inputs make a message of its own: a probe stops here. */
    void probe(int, const SemanticEvent &, ProbeWalk *) const override {}

protected:
    /** Feeds the tracker one step and routes what it emits. */
    void update(double t, bool condition, double intensity);

    MessageTracker m_tracker;

private:
    EventBuffer *m_out = nullptr;
};

/**
 * A detector on a signal (docs/detectors.md, "threshold"): its message is active while the
 * input meets the condition at the begin levels, and stays active while it meets it at the
 * end levels; intensity is a clipped linear map of the input in steps of IntensityStep, or
 * 1; minDuration as the detectors'.
 */
class ThresholdNode : public MessageSourceNode
{
public:
    enum class Condition
    {
        Above,
        Below,
        Inside,
        Outside
    };
    static QStringList conditionNames();

    struct Params
    {
        Message message = Message::Break;
        Category category = Category::Exception;
        Condition condition = Condition::Above;
        double begin = 0.0;     ///< above, below: the level; inside, outside: the range's low
        double beginHigh = 0.0; ///< inside, outside: the range's high
        double end = 0.0;       ///< as begin, while active
        double endHigh = 0.0;
        double minDuration = 0.0;
        bool mapsIntensity = false; ///< false: intensity 1 while active
        double intensityFrom = 0.0; ///< the input at which intensity is 0
        double intensityTo = 1.0;   ///< the input at which intensity is 1
    };
    /** Intensities come in steps of this size. */
    static constexpr double IntensityStep = 0.01;

    ThresholdNode(int node, Gripper gripper, const Params &params);
    void onSignal(int port, double value, double t) override;
    const Params &params() const { return m_params; }
    Gripper gripper() const { return m_gripper; }

private:
    Gripper m_gripper;
    Params m_params;
};

/**
 * A message made of two others (docs/detectors.md, "compose"): active while both inputs
 * carry an active message (all), either does (any), or `a` does while `b` does (while).
 */
class ComposeNode : public MessageSourceNode
{
public:
    enum class Mode
    {
        All,
        Any,
        While
    };
    static QStringList modeNames();

    struct Params
    {
        Message message = Message::Grasp;
        Category category = Category::Confirmation;
        Mode mode = Mode::All;
        bool fixedGripper = false; ///< false: the gripper of the input that makes it active
        Gripper gripper = Gripper::Right;
    };

    ComposeNode(int node, const Params &params);
    void onEvent(int port, const SemanticEvent &event) override;

private:
    Params m_params;
    std::array<ActiveMessages, 2> m_inputs; ///< a and b: their active messages
};

/** Passes the messages that match; a message's whole lifecycle matches or none of it. */
class FilterNode : public RuntimeNode
{
public:
    /** The messages it passes (empty: any); bit sets over Category and Gripper (0: any). */
    FilterNode(std::vector<Message> messages, unsigned categories, unsigned grippers)
        : m_messages(std::move(messages)), m_categories(categories), m_grippers(grippers)
    {}
    void onEvent(int port, const SemanticEvent &event) override;
    void probe(int port, const SemanticEvent &event, ProbeWalk *walk) const override;

private:
    bool passes(const SemanticEvent &event) const;

    std::vector<Message> m_messages;
    unsigned m_categories;
    unsigned m_grippers;
};

/** Passes input messages only while the control allows; closing ends them, opening resumes. */
class GateNode : public RuntimeNode
{
public:
    explicit GateNode(bool openWhenControlActive) : m_openOnControl(openWhenControlActive) {}
    void onEvent(int port, const SemanticEvent &event) override;
    /** Its input passes on (the gate taken as open); its control goes nowhere. */
    void probe(int port, const SemanticEvent &event, ProbeWalk *walk) const override;

private:
    bool isOpen() const { return m_control.isEmpty() == !m_openOnControl; }
    bool m_openOnControl;
    ActiveMessages m_inputs;
    ActiveMessages m_control;
};

/** Delays ends by `hold` (a begin within it continues the message) and drops small updates. */
class DebounceNode : public RuntimeNode
{
public:
    DebounceNode(double hold, double band) : m_hold(hold), m_band(band) {}
    void onEvent(int port, const SemanticEvent &event) override;
    double nextTimer() const override;
    void fireTimers(double t) override;
    bool hasTimers() const override { return true; }

private:
    double m_hold;
    double m_band;
    ActiveMessages m_active;
};

/** Maps intensity through a curve, clipped to [0, 1]; updates that map equal are dropped. */
class CurveNode : public RuntimeNode
{
public:
    explicit CurveNode(Curve curve) : m_curve(std::move(curve)) {}
    void onEvent(int port, const SemanticEvent &event) override;
    void probe(int port, const SemanticEvent &event, ProbeWalk *walk) const override;

private:
    Curve m_curve;
    ActiveMessages m_active;
};

/** A voice feeding one device, with the priority of the messages that drive it. */
class VoiceInput : public PlayerInput
{
public:
    VoiceInput(PatternPtr played, int on) : voice(played), pattern(std::move(played)), device(on)
    {}
    void advance(double t) override { voice.advance(t); }
    bool isSounding() const override { return !voice.isIdle(); }
    Priority priority() const override { return currentPriority; }
    double value(int slot) const override { return voice.value(slot); }

    Voice voice;
    PatternPtr pattern; ///< what the voice plays
    int device;         ///< the player's index of the device it plays on
    Priority currentPriority = Confirmation;
};

/**
 * Plays a pattern on each linked device while any of its messages is active, at the highest
 * intensity among them. A pattern node with no event input plays from the start
 * (continuous patterns such as air.proportional); its signal inputs set parameters live.
 */
class PatternNode : public RuntimeNode
{
public:
    PatternNode(PatternPtr pattern, bool continuous)
        : m_pattern(std::move(pattern)), m_continuous(continuous)
    {}
    void onEvent(int port, const SemanticEvent &event) override;
    void onSignal(int port, double value, double t) override;
    void start(double t) override;
    /** A probe ends here: what it reached. */
    void probe(int port, const SemanticEvent &event, ProbeWalk *walk) const override;

    /** Port index -> pattern parameter index, for the signal inputs. */
    std::vector<int> signalParams;
    std::vector<std::unique_ptr<VoiceInput>> voices;
    const Pattern &pattern() const { return *m_pattern; }

private:
    void applyIntensity(double t);

    PatternPtr m_pattern;
    bool m_continuous;
    ActiveMessages m_active;
    double m_intensity = -1.0;
};

/** clip(signal / ref, 0, 1) on the linked devices' channels. */
class ProportionalNode : public RuntimeNode
{
public:
    explicit ProportionalNode(double ref) : m_ref(ref) {}
    void onSignal(int port, double value, double t) override;
    void start(double t) override;

    class Input : public PlayerInput
    {
    public:
        explicit Input(const ProportionalNode &node) : m_node(node) {}
        void advance(double) override {}
        bool isSounding() const override { return m_node.m_started; }
        Priority priority() const override { return Continuous; }
        double value(int) const override { return m_node.m_value; }

    private:
        const ProportionalNode &m_node;
    };
    std::vector<std::unique_ptr<Input>> inputs;

private:
    double m_ref;
    double m_value = 0.0;
    bool m_started = false;
};

} // namespace semhap
