// SPDX-License-Identifier: MIT
#pragma once

#include "driveoperator.h"
#include "runsource.h"
#include "scenefeed.h"
#include "simrun.h"

#include <memory>

namespace semhap {

/**
 * A simulation as the engine's source: the SimRun stepped at the pace the user picks, the
 * pictures the viewport draws of its world, and the operator the user drives the grippers
 * through (their input recorded while driving).
 */
class SimulationSource : public RunSource
{
public:
    /** Takes the run, and a first picture of its world: a run loaded paused shows its scene. */
    explicit SimulationSource(std::unique_ptr<SimRun> run);

    Pipeline *pipeline() override { return &m_run->pipeline(); }
    const World *world() const override { return &m_run->world(); }
    SceneFeed *sceneFeed() const override { return m_sceneFeed.get(); }
    Hands hands() const override;
    DriveOperator *driveOperator() override { return &m_manualOperator; }
    bool isPaced() const override { return true; }
    double timestep() const override;

    Outcome advance(Sink &sink, const Budget &budget) override;
    double time() const override { return m_run->time(); }
    bool isDone() const override { return m_run->isDone(); }
    void setRouter(std::unique_ptr<Router> router, RunSink &sink) override;
    RouterContext routerContext(double reactionTime) const override;
    const ActorTable *actors() const override;
    SessionInfo sessionInfo() const override { return m_run->sessionInfo(); }
    QJsonObject metrics() const override { return m_run->metrics(); }
    void setDuration(double seconds) override { m_run->setDuration(seconds); }
    void recordingStarted() override { m_nextInput = 0.0; }

private:
    /** The user's commanded pose and grip, into the recording. */
    void recordInput(SessionWriter &recorder, double t);

    std::unique_ptr<SimRun> m_run;
    std::unique_ptr<SceneFeed> m_sceneFeed;
    DriveOperator m_manualOperator;
    double m_nextInput = 0.0; ///< when the user's input is recorded next
};

} // namespace semhap
