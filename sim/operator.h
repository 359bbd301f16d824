// SPDX-License-Identifier: MIT
#pragma once

#include "contactframe.h"
#include "routercontext.h"

#include <QJsonObject>
#include <QString>

#include <cstdint>
#include <memory>

namespace semhap {

class Perception;
struct PersonParameters;
class Task;
class World;

/**
 * What reaches the operator about one hand at a moment, each in [0, 1]: how strongly a
 * confirmation and a warning are felt on the wristbands, a continuous pressure (the sensory
 * baseline), and what the visual overlay on that gripper shows — which the operator sees
 * only while looking at that hand. Computed from the device output through the devices'
 * response models.
 */
struct Feeling
{
    double confirmation = 0.0;
    double warning = 0.0;
    double pressure = 0.0;
    double shownConfirmation = 0.0;
    double shownWarning = 0.0;
};

/**
 * Drives the grippers: sets pose targets and grip forces before each physics step. The
 * scripted operators here, the studio's keyboard and mouse, and live rigs over the network
 * all implement this one interface.
 */
class Operator
{
public:
    virtual ~Operator() = default;
    virtual QString name() const = 0;
    /** Sets the targets and grips for the next physics step. */
    virtual void act(World &world) = 0;
    /**
     * Takes the hands over as they are now, after another operator drove them (the studio
     * user handing back, or taking over): a plan made before is stale, and resuming it would
     * jump the targets to where it left off. Called before the first act() after a hand-over.
     */
    virtual void engage(const World &world) = 0;
    /** What `hand` perceives now (the previous tick's device output); default: ignored. */
    virtual void feel(Gripper hand, const Feeling &feeling, double t);
    /**
     * Before feel(): the whole of this tick's output band by band, and the task that judges
     * warnings, for an operator that perceives more than a hand's Feeling; default: ignored.
     */
    virtual void sense(const Perception &perception, const Task &task, double t);
    /** Adds what the operator itself counted to a run's metrics; default: nothing. */
    virtual void addMetrics(QJsonObject *metrics) const;
};

/** Operator names `makeOperator` knows. */
QStringList operatorNames();

/**
 * The named operator for `world`: `scripted` (performs the task with seeded human
 * variation, ignoring feedback), `reactive` (the same, reacting to what it feels after
 * `reactionTime` seconds) or `perceiving` (the reactive hands with `person`'s senses,
 * docs/operator.md). Null with `error` for an unknown name or a scene it cannot do.
 */
std::unique_ptr<Operator> makeOperator(const QString &name, const World &world, std::uint64_t seed,
                                       double reactionTime, const PersonParameters &person,
                                       QString *error);

} // namespace semhap
