// SPDX-License-Identifier: MIT
#pragma once

#include "driveoperator.h"
#include "runsource.h"
#include "scenefeed.h"
#include "simrun.h"

#include <memory>

namespace semhap {

/**
 * A simulation as the engine's source: the SimRun, the pictures the viewport draws of its
 * world, and the operator the user drives the grippers through.
 */
class SimulationSource : public RunSource
{
public:
    explicit SimulationSource(std::unique_ptr<SimRun> run);

    Kind kind() const override { return Kind::Simulation; }
    Pipeline *pipeline() override { return &m_run->pipeline(); }
    const World *world() const override { return &m_run->world(); }
    SceneFeed *sceneFeed() const override { return m_sceneFeed.get(); }
    Hands hands() const override;

    SimRun &run() { return *m_run; }
    const SimRun &run() const { return *m_run; }
    DriveOperator &driveOperator() { return m_manualOperator; }

private:
    std::unique_ptr<SimRun> m_run;
    std::unique_ptr<SceneFeed> m_sceneFeed;
    DriveOperator m_manualOperator;
};

} // namespace semhap
