// SPDX-License-Identifier: MIT
#include "simulationsource.h"

#include "perception.h"
#include "sessionwriter.h"

namespace semhap {

namespace {

/** The user's commanded pose and grip are recorded this often while driving (s). */
constexpr double InputPeriod = 0.01;

} // namespace

SimulationSource::SimulationSource(std::unique_ptr<SimRun> run)
    : m_run(std::move(run)), m_sceneFeed(std::make_unique<SceneFeed>(m_run->world()))
{
    m_sceneFeed->capture(m_run->world(), SceneOverlay());
}

Hands SimulationSource::hands() const
{
    const World &world = m_run->world();
    return {world.hasGripper(Gripper::Left), world.hasGripper(Gripper::Right)};
}

double SimulationSource::timestep() const
{
    return m_run->world().timestep();
}

RunSource::Outcome SimulationSource::advance(Sink &sink, const Budget &budget)
{
    SimRun &run = *m_run;
    run.setDriveOperator(budget.driving ? &m_manualOperator : nullptr);
    SessionWriter *recorder = sink.recorder();
    for (long k = 0;
         k < budget.steps && !run.isDone() && (!budget.running || budget.stillRunning->load());
         ++k) {
        run.step(sink);
        const double t = run.time();
        if (recorder) {
            if (budget.driving && t >= m_nextInput) {
                m_nextInput = t + InputPeriod;
                recordInput(*recorder, t);
            }
            run.recordSceneState(*recorder);
        }
        if (m_sceneFeed->wantsCapture()) {
            const Perception &perception = run.perception();
            const Feeling left = perception.feeling(Gripper::Left);
            const Feeling right = perception.feeling(Gripper::Right);
            m_sceneFeed->capture(run.world(), {left.shownConfirmation, left.shownWarning,
                                               right.shownConfirmation, right.shownWarning});
        }
    }
    return Outcome::Going;
}

void SimulationSource::setRouter(std::unique_ptr<Router> router, RunSink &sink)
{
    m_run->setRouter(std::move(router), sink);
}

RouterContext SimulationSource::routerContext(double reactionTime) const
{
    return SimRun::routerContext(m_run->world(), reactionTime);
}

const ActorTable *SimulationSource::actors() const
{
    return &m_run->world().actors();
}

void SimulationSource::recordInput(SessionWriter &recorder, double t)
{
    for (std::optional<HandCommand> command : currentCommands(m_run->world())) {
        if (!command)
            continue;
        command->t = t;
        recorder.recordHandCommand(*command);
    }
}

} // namespace semhap
