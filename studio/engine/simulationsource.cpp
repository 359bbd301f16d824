// SPDX-License-Identifier: MIT
#include "simulationsource.h"

namespace semhap {

SimulationSource::SimulationSource(std::unique_ptr<SimRun> run)
    : m_run(std::move(run)), m_sceneFeed(std::make_unique<SceneFeed>(m_run->world()))
{}

Hands SimulationSource::hands() const
{
    const World &world = m_run->world();
    return {world.hasGripper(Gripper::Left), world.hasGripper(Gripper::Right)};
}

} // namespace semhap
