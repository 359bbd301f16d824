// SPDX-License-Identifier: MIT
#pragma once

#include "runhistory.h"

#include <QString>

namespace semhap {

class Pipeline;
class SceneFeed;
class World;

/**
 * What the engine runs: a simulation, a live rig or a recorded session. The engine holds
 * one at a time and says when it changes (Engine::sourceChanged); the windows ask the
 * source what it has — a scene to draw, a pipeline to route through, which hands — instead
 * of telling the kinds apart themselves.
 */
class RunSource
{
public:
    enum class Kind
    {
        Simulation, ///< a MuJoCo scene stepped on the pipeline thread (SimulationSource)
        Rig,        ///< contact frames from an external rig over UDP (LiveRig)
        Replay      ///< a recorded session, scrubbed on the GUI thread (SessionReplay)
    };

    virtual ~RunSource() = default;

    virtual Kind kind() const = 0;
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
    /** Whether the user can drive its grippers: only a simulation's respond. */
    bool isDrivable() const { return kind() == Kind::Simulation; }
    /** Whether it runs on the engine's pipeline thread (a replay is scrubbed instead). */
    bool isStreaming() const { return kind() != Kind::Replay; }
};

} // namespace semhap
