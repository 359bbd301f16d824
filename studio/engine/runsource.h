// SPDX-License-Identifier: MIT
#pragma once

#include "runhistory.h"
#include "simrun.h"

#include <QJsonObject>
#include <QString>

#include <atomic>
#include <memory>
#include <optional>

namespace semhap {

class ActorTable;
class DriveOperator;
class Pipeline;
class Router;
class SceneFeed;
class SessionWriter;
class World;
struct RouterContext;
struct SessionInfo;

/**
 * What the engine runs: a simulation, a live rig or a recorded session. The engine holds
 * one at a time, runs a streaming one on its pipeline thread through advance(), and says
 * when it changes (Engine::sourceChanged). The engine and the windows ask the source what
 * it has — a scene to draw, a pipeline to route through, a pace, grippers to drive, a link
 * to report on — and never which kind it is, so a new source is its own class.
 */
class RunSource
{
public:
    /** Where advance() puts what the source made: the engine's outputs. */
    class Sink : public RunSink
    {
    public:
        /** A frame that came from outside at `arrival` (s, the source's clock), before it is
         * routed. */
        virtual void onReceivedFrame(const ContactFrame &frame, double arrival) = 0;
        /** The session being recorded, or null: a source writes its own tables into it. */
        virtual SessionWriter *recorder() = 0;
    };

    /** What one advance() may do. */
    struct Budget
    {
        /** A paced source's steps to take; one that is not paced takes what has arrived. */
        long steps = 0;
        /** Whether the user ran it when the batch began (else it was asked for steps). */
        bool running = false;
        /**
         * Whether the user runs it now, read as the source goes: a pause or a stop-all ends a
         * running batch at its next step, and what arrives while it is off is held (dropped
         * and counted). Never null.
         */
        const std::atomic<bool> *stillRunning = nullptr;
        /** The user's input drives the grippers (a source with a driveOperator()). */
        bool driving = false;
        /** A link that falls silent is acted on later (the run waits behind a replay). */
        bool holdSilence = false;
    };

    /** How an advance() ended. */
    enum class Outcome
    {
        Going,
        Silent ///< the link fell silent: its messages ended, the bands should rest
    };

    /** What a source that receives its frames over a link has seen since it opened. */
    struct LinkStats
    {
        quint64 datagrams = 0; ///< received, good or bad (a robot's: its messages)
        quint64 frames = 0;    ///< valid frames
        quint64 rejected = 0;  ///< malformed datagrams and invalid frames
        quint64 oversize = 0;  ///< datagrams over the size limit, not parsed
        quint64 held = 0;      ///< valid frames dropped while paused
        double framesPerSecond = 0.0;
        double jitter = 0.0; ///< spread of arrival minus `t` over the last second (s)
        int port = 0;        ///< the port bound to (useful when 0 was asked for)
        /** The latest rejection's reason (`udp:PORT: reason`, a robot's fatal error). */
        QString lastRejection;
        quint64 reasons = 0; ///< rejections with a reason so far: a new one changes it
    };

    virtual ~RunSource() = default;

    // What it has: any thread that holds the source (the GUI's).
    /**
     * The pipeline its contact frames go through; null for a replay, whose events and
     * device frames were recorded (Engine::setRouter re-routes it instead).
     */
    virtual Pipeline *pipeline() = 0;
    /** The scene the viewport draws; null when the source has none. */
    virtual const World *world() const { return nullptr; }
    /** The pictures of world() for the viewport; null when there is no scene. */
    virtual SceneFeed *sceneFeed() const { return nullptr; }
    /** The hands it reports: a scene's grippers; both for a rig, which may send either. */
    virtual Hands hands() const { return {true, true}; }
    /** What the user drives its grippers through; null when they are not the user's to drive. */
    virtual DriveOperator *driveOperator() { return nullptr; }
    bool isDrivable() { return driveOperator() != nullptr; }
    /** Whether it runs on the engine's pipeline thread (a replay is scrubbed instead). */
    virtual bool isStreaming() const { return true; }
    /**
     * Whether it runs at the speed the user picks, a timestep() per step (a simulation),
     * rather than as its frames arrive.
     */
    virtual bool isPaced() const { return false; }
    /** A paced source's step (s). */
    virtual double timestep() const { return 0.0; }
    /** Where its frames come from (`udp:ADDRESS:PORT`, a robot's URL); empty when it makes them.
     */
    virtual QString address() const { return QString(); }
    /** A link's counters since it opened; none for a source without a link. */
    virtual std::optional<LinkStats> linkStats() const { return std::nullopt; }
    /** What the viewport says over the run (a replay's "Replay"); empty for none. */
    virtual QString caption() const { return QString(); }
    /** What the viewport shows when world() is null: why there is no scene. */
    virtual QString sceneNote() const { return QString(); }

    // Running: the pipeline thread, or any thread holding the engine's set-up lock.
    /** Opens what it reads from, on the pipeline thread that will read it; false with a one-line
     * `error`. */
    virtual bool start(QString * /*error*/) { return true; }
    /** Closes what start() opened, on the same thread. */
    virtual void shutdown() {}
    /**
     * Blocks until there may be something to advance, or `msecs` passed (the set-up lock
     * not held). A source that is not paced waits for its link; the default sleeps.
     */
    virtual void wait(int msecs);
    /** Runs what `budget` allows into `sink`. A source scrubbed instead (a replay) has nothing to
     * run. */
    virtual Outcome advance(Sink & /*sink*/, const Budget & /*budget*/) { return Outcome::Going; }
    /** The time it reached (s): a simulation's, or the latest frame's `t`. */
    virtual double time() const = 0;
    /** Whether it reached its end (a simulation's duration): it runs no further. */
    virtual bool isDone() const { return false; }
    /** Swaps the router; the old one's active messages end now, their End events to `sink`. */
    virtual void setRouter(std::unique_ptr<Router> /*router*/, RunSink & /*sink*/) {}
    /**
     * What routers are compiled for: the reaction time and the signals its frames carry (a
     * scene's declared ones, or a rig's seen so far).
     */
    virtual RouterContext routerContext(double reactionTime) const;
    /** The actors its frames name, what recordings and Foxglove name them by; null for none. */
    virtual const ActorTable *actors() const { return nullptr; }
    /** The session metadata of a recording of it (the engine adds router, bindings, tags). */
    virtual SessionInfo sessionInfo() const;
    /** Its task's metrics now (docs/metrics.md); empty when it has no task. */
    virtual QJsonObject metrics() const { return QJsonObject(); }
    /** Lets it run `seconds` from its start (a study's trial); a source without an end ignores it.
     */
    virtual void setDuration(double /*seconds*/) {}
    /** A recording starts with the next advance(): a source that records at a rate starts now. */
    virtual void recordingStarted() {}
    /**
     * Whether it cannot open while `running` is open (the same port): the engine then stops
     * `running` first, and has nothing to go back to when this one fails.
     */
    virtual bool conflictsWith(const RunSource & /*running*/) const { return false; }
};

} // namespace semhap
