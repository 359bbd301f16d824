// SPDX-License-Identifier: MIT
#pragma once

#include "contactframe.h"
#include "eventbuffer.h"
#include "loaderror.h"
#include "nodeactivity.h"
#include "player.h"
#include "routercontext.h"
#include "routergraph.h"

#include <QStringList>

#include <memory>
#include <vector>

namespace semhap {

class Detector;
class DetectorNode;
class RouterActivity;
class RuntimeNode;
class MessageSourceNode;
class SignalNode;
class VoiceInput;

/**
 * What a threshold node watches and at which levels, as compiled: what plots draw a
 * signal's levels and shade its message's spans from (Router::thresholds()).
 */
struct ThresholdLevels
{
    QString node;                     ///< the threshold node's id
    Gripper gripper = Gripper::Right; ///< the gripper its events name
    Message message = Message::Break;
    Category category = Category::Exception;
    QString condition;  ///< above, below, inside or outside
    bool range = false; ///< inside, outside: [begin, beginHigh] and [end, endHigh]
    double begin = 0.0;
    double beginHigh = 0.0;
    double end = 0.0;
    double endHigh = 0.0;
    /**
     * The quantity of the signal node its input comes from (`F`, `plug.angle`), through
     * `via`; empty when its input is not linked to one.
     */
    QString quantity;
    Gripper signalGripper = Gripper::Right; ///< that signal node's gripper
    QStringList via; ///< the derivative and predict node types between, signal side first
    /** No derivative on the way: the levels are in the quantity's units, drawn on its plot. */
    bool levelsInSignalUnits = false;
};

/** A message that plays a pattern on a device: what Router::messageRoutes finds. */
struct MessageRoute
{
    int source = -1;        ///< the node that sends the message (graph order)
    SemanticEvent message;  ///< a begin of it, as sent: gripper, message, category
    double intensity = 0.0; ///< as it reaches the pattern (curves on the way map it)
    int pattern = -1;       ///< the pattern node (graph order)
    PatternPtr played;      ///< the pattern it plays, its node's parameters baked in
    int device = -1;        ///< the player's index of the device
    std::vector<PlayerInput::Route> routes; ///< which device channel each track drives
};

/**
 * A router graph compiled to run: detectors, logic, pattern voices and the player with its
 * devices. Compiling checks everything (types, ports, cycles, patterns, models, channels)
 * and names the node and the reason of the first problem. Running allocates nothing.
 */
class Router
{
public:
    /**
     * Compiles `graph` for a run described by `context`; on failure returns null with
     * `error` (file and JSON pointer).
     */
    static std::unique_ptr<Router> compile(const RouterGraph &graph, LoadError *error,
                                           const RouterContext &context = {});
    ~Router();

    /** Starts the player's clocks and the continuous patterns at the first frame's time. */
    void start(double t0);
    bool isStarted() const { return m_started; }

    /** Runs the detectors (and signal sources) of the frame's gripper; appends and routes. */
    void process(const ContactFrame &frame, EventBuffer &events);
    /** Ends every active message of every detector at t (end of a run, router swap). */
    void endAll(double t, EventBuffer &events);
    /**
     * Appends a begin at t for every message active now, in graph order, without routing
     * them: what a stream that starts mid-run (a recording) needs to show them open.
     */
    void appendActive(double t, EventBuffer &events) const;

    /** When a logic node next needs fireTimers; infinity when none waits. */
    double nextTimer() const;
    /** Fires the timers due at or before t, in time order; messages raised go to `events`. */
    void fireTimers(double t, EventBuffer &events);

    Player &player() { return m_player; }
    const Player &player() const { return m_player; }
    /**
     * The hand that feels device `device` (a player index): its node's `hand`, or the id's
     * first part when that names a gripper. False for a device of no hand (the overlay).
     */
    bool deviceHand(int device, Gripper *hand) const;
    /**
     * Every node's activity (what it passes on), in graph order, as of the last frame or
     * timer: the router's own account of what routed. Devices are never active here; their
     * frames tell. Kept up to date without allocating.
     */
    const std::vector<NodeActivity> &activity() const;
    /** The nodes whose activity changed since clearActivityChanges(), in order of change. */
    const std::vector<int> &activityChanges() const;
    void clearActivityChanges();
    /**
     * The compiled detectors (force, slip), in graph order: what plots take thresholds from.
     * Their params() are what they run with, fitted to the context's grippers; the graph
     * keeps the nodes' own.
     */
    std::vector<const Detector *> detectors() const;
    /** The threshold nodes, in graph order: the signals they read and their levels. */
    std::vector<ThresholdLevels> thresholds() const;
    /**
     * Every message a detector, threshold or compose node may send, followed through the
     * graph at `intensity` to each pattern it plays on each device: filters match it, curves
     * map its intensity, gates are taken as open. In graph order of the sources, then of the
     * patterns, then of the devices. What `semhap distinct` compares per band.
     */
    std::vector<MessageRoute> messageRoutes(double intensity) const;
    /**
     * The pattern node (graph order) whose voice sounds on `device` (a player index) in the
     * highest priority class, the first in link order among equals; -1 when none sounds. What
     * a person feeling that band is feeling, to be told from the band's other patterns.
     */
    int soundingPattern(int device) const;
    /** Node ids in graph order: SemanticEvent::node indexes this list. */
    const QStringList &nodeIds() const { return m_nodeIds; }
    const RouterGraph &graph() const { return m_graph; }
    /**
     * The graph with every pattern and device model it uses embedded (built-ins too, since
     * they may change between versions) and its nodes naming them: a document that compiles
     * to the same router on any machine. What a session keeps.
     */
    RouterGraph selfContained() const;

private:
    Router() = default;

    RouterGraph m_graph;
    QStringList m_nodeIds;
    std::vector<std::unique_ptr<RuntimeNode>> m_nodes; ///< graph order; null for devices
    std::vector<DetectorNode *> m_detectors;
    std::vector<SignalNode *> m_signals;
    std::vector<MessageSourceNode *> m_messageSources; ///< threshold and compose nodes
    std::vector<RuntimeNode *> m_timed;                ///< nodes that may hold timers
    /** Every pattern voice with its node (graph order), in link order. */
    std::vector<std::pair<int, const VoiceInput *>> m_voices;
    /** What a node's pattern or model parameter resolved to, for selfContained(). */
    struct Sources
    {
        PatternPtr pattern; ///< before the node's parameter overrides are baked in
        DeviceModelPtr model;
    };
    std::vector<Sources> m_sources; ///< graph order
    std::vector<int> m_deviceHands; ///< player device index -> Gripper, or -1 for none
    std::unique_ptr<RouterActivity> m_activity;
    Player m_player;
    bool m_started = false;
    friend class RouterCompiler;
};

/**
 * Loads a router preset or file, applies `NODE.PARAM=VALUE` overrides and compiles it. An
 * error caused by an override is reported against the override (`--set NODE.PARAM=VALUE:
 * reason`), not against the file.
 */
std::unique_ptr<Router> loadRouter(const QString &nameOrPath, const QStringList &overrides,
                                   LoadError *error, const RouterContext &context = {});
/** What loadRouter() does once the graph is loaded (a session's router, an editor's). */
std::unique_ptr<Router> compileWithOverrides(RouterGraph graph, const QStringList &overrides,
                                             LoadError *error, const RouterContext &context = {});
/**
 * Whether `router` routes as the preset or file `nameOrPath` does: the same nodes, links
 * and parameters, and patterns and device models of the same content. Where the editor drew
 * the nodes, the name and the description do not count. False when nothing of that name
 * loads: a router that differs is an edit of it (`C3*`).
 */
bool routesAs(const Router &router, const QString &nameOrPath);

} // namespace semhap
