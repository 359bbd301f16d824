// SPDX-License-Identifier: MIT
#pragma once

#include "metricspec.h"
#include "operator.h"
#include "perception.h"
#include "personparameters.h"
#include "pipeline.h"
#include "scenestate.h"
#include "sessioninfo.h"
#include "task.h"
#include "world.h"

#include <QJsonObject>
#include <QStringList>

#include <cstdint>
#include <memory>

namespace semhap {

class JsonReader;
class SessionWriter;

/** Everything that defines a headless run; same options, same run. */
struct RunOptions
{
    QString scene = QStringLiteral("box_and_block");
    SceneOptions sceneOptions;
    QString router = QStringLiteral("C3");
    QStringList overrides; ///< NODE.PARAM=VALUE
    QString operatorName = QStringLiteral("scripted");
    std::uint64_t seed = 1;
    double duration = 60.0;                    ///< simulated seconds
    double reactionTime = DefaultReactionTime; ///< the reactive operator's delay (s)
    double horizon = DefaultHorizon; ///< how early a warning's onset may be and count (s)
    PersonParameters person;         ///< the perceiving operator's senses

    /** The largest seed: whole numbers above 2^53 do not survive a JSON number. */
    static constexpr double MaxSeed = 9e15;
    /** The most cubes a scene may be asked to keep in play. */
    static constexpr int MaxCubes = 1000;
    /** The longest horizon (s): a minute before a failure is no warning of it. */
    static constexpr double MaxHorizon = 60.0;

    /**
     * What makes the run, as JSON: `scene`, `cubes` (when not the scene's default),
     * `router`, `overrides`, `operator`, `seed`, `reaction_time`, `horizon` (when not
     * DefaultHorizon), `person` (the parameters not at their defaults, when any); not the
     * duration.
     */
    QJsonObject toJson() const;
    /**
     * Reads toJson()'s object at `pointer` over `options` (a key left out keeps its value),
     * checking each value's type and range; false with the located reason in `reader`.
     */
    static bool fromJson(JsonReader &reader, const QJsonObject &json, const QString &pointer,
                         RunOptions *options);
};

/** Receives a run's streams: contact frames besides the pipeline's events and frames. */
class RunSink : public PipelineSink
{
public:
    virtual void onContactFrame(const ContactFrame &) {}
};

/**
 * The whole pipeline on the simulation: each physics step the operator acts on what it
 * felt, the world steps, its contact frames go through detectors, router and player, and
 * the task counts. Deterministic: the same options give the same streams, bit for bit.
 */
class SimRun
{
public:
    /** Loads scene, router and operator; null with a one-line `error`. */
    static std::unique_ptr<SimRun> create(const RunOptions &options, QString *error);
    /**
     * What a router for `world` is compiled with: the reaction time, and the signals the
     * scene declares, so a signal node naming another is refused at once.
     */
    static RouterContext routerContext(const World &world, double reactionTime);

    /** One physics step and the pipeline tick it makes; false once the duration is done. */
    bool step(RunSink &sink);
    bool isDone() const;
    /**
     * Runs for `seconds` (simulated, from the start) instead of options().duration: a study's
     * trial in the studio. A run already past it is done.
     */
    void setDuration(double seconds);
    /** Simulated seconds so far. */
    double time() const;

    /** The task metrics so far, and the run's own operator's (Operator::addMetrics). */
    QJsonObject metrics() const;
    /**
     * The report of a run that took `wallSeconds`: metrics(), then the run's inputs (scene,
     * router, operator, seed) and its own measures (simulated and wall time, their ratio).
     */
    QJsonObject report(double wallSeconds) const;
    /** What report() adds to metrics(), a row each (docs/metrics.md). */
    static const std::vector<MetricSpec> &metricSpecs();

    /**
     * Drives the grippers with `op` instead of the run's own operator while it is set (the
     * studio user driving); null gives them back. Not owned. Whichever takes the hands over
     * at the next step is engaged first (Operator::engage), so no target jumps.
     */
    void setDriveOperator(Operator *op) { m_driveOperator = op; }
    /** What each hand perceives of the device output (the overlay is drawn from it). */
    const Perception &perception() const { return *m_perception; }
    /** A session records the scene state this often (simulated seconds): display rate. */
    static constexpr double SceneStatePeriod = 1.0 / 30.0;
    /** Where the scene's bodies are now and the overlay shown, for a session's replay. */
    SceneState sceneState() const;
    /**
     * Records the scene state into `session` when one is due (every SceneStatePeriod of
     * simulated time, the first at once); call it after each step while recording.
     */
    void recordSceneState(SessionWriter &session);
    /**
     * What a session records of this run: the scene, the router as loaded, the operator, the
     * seed and the options that make the same run again. The caller adds source, bindings
     * and notes.
     */
    SessionInfo sessionInfo() const;

    /**
     * Swaps the router between two steps (the studio's live edits): the old router's active
     * messages end now, their End events going to `sink`, and the new one starts with the
     * next frame in a fresh pipeline and perception; world, operator and task go on.
     */
    void setRouter(std::unique_ptr<Router> router, RunSink &sink);

    World &world() { return *m_world; }
    Pipeline &pipeline() { return *m_pipeline; }
    const RunOptions &options() const { return m_options; }

private:
    SimRun() = default;

    RunOptions m_options;
    std::unique_ptr<World> m_world;
    std::unique_ptr<Pipeline> m_pipeline;
    std::unique_ptr<Operator> m_operator;
    Operator *m_driveOperator = nullptr;
    /** The operator that acted at the last step (null before the first). */
    Operator *m_acting = nullptr;
    std::unique_ptr<Perception> m_perception;
    std::unique_ptr<Task> m_task;
    double m_nextSceneState = 0.0;
    long m_steps = 0;
    long m_totalSteps = 0;
};

} // namespace semhap
