// SPDX-License-Identifier: MIT
#pragma once

// World's insides, shared by its files: world.cpp (loading, stepping, the scene's queries),
// worldcontacts.cpp (what the fingertips touch, fractures) and worldsleep.cpp (resting
// objects put to sleep). Not a public header.
#include "world.h"

#include "grippergeometry.h"
#include "mujocohandles.h"
#include "scenesignals.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <memory>
#include <vector>

namespace semhap {

/** An axis-aligned box in world coordinates. */
struct Aabb
{
    std::array<double, 3> low{};
    std::array<double, 3> high{};

    bool overlaps(const Aabb &other) const
    {
        for (size_t i = 0; i < 3; ++i) {
            if (low[i] > other.high[i] || other.low[i] > high[i])
                return false;
        }
        return true;
    }
    void grow(double by)
    {
        for (size_t i = 0; i < 3; ++i) {
            low[i] -= by;
            high[i] += by;
        }
    }
    void unite(const Aabb &other)
    {
        for (size_t i = 0; i < 3; ++i) {
            low[i] = std::min(low[i], other.low[i]);
            high[i] = std::max(high[i], other.high[i]);
        }
    }
};

// Distinct bodies one fingertip is tracked touching at once; more are not told apart.
constexpr int MaxTouched = 8;

struct World::Private
{
    struct Touch
    {
        int actor = -1;
        double force = 0.0;
        int contacts = 0;
        std::array<double, 3> fworld{}; ///< the resultant force on the tip, world frame
    };
    struct Tip
    {
        int gripperBody = -1;
        double force = 0.0;
        int contacts = 0;
        std::array<double, 3> fworld{};
        std::array<Touch, MaxTouched> touched{};
        int touchedCount = 0;
        // The last force reported, and for how many steps it has been held over a dropout.
        double heldForce = 0.0;
        std::array<double, 3> heldFworld{};
        int heldSteps = 0;
    };
    struct Hand
    {
        bool present = false;
        int body = -1;
        int mocap = -1;
        int actuators[2] = {-1, -1};
        int slides[2] = {-1, -1};
        ContactFrame frame;
        /** What its fingers do as they close, measured at load. */
        GripperGeometry geometry;
        /**
         * A gripper model brought in by an adapter: its motors' gears follow the moment arm
         * of each finger's joint at every step, so a control in newtons presses the pad with
         * that many newtons whatever the linkage.
         */
        bool adapted = false;
        /** The adapter's damping of each pad's motion (N·s/m), as the model's servo had. */
        double padDamping = 0.0;
    };

    MjModelPtr model;
    MjDataPtr data;
    std::array<Hand, 2> hands;
    SceneSignals sceneSignals;
    std::array<Tip, 4> tips;          ///< gripper * 2 + finger (0 left, 1 right)
    std::vector<int> tipOfGeom;       ///< per geom: its tip, or -1
    std::vector<long> taxelStamp;     ///< per geom: the step it was last counted in
    std::vector<int> objectOfBody;    ///< per body: its object index, or -1
    std::vector<double> gripOnObject; ///< per object: tip force this step
    std::vector<int> overForceSteps;  ///< per object: steps in a row above its limit
    /** Per geom: whether it collides as loaded (sleeping clears the model's bits). */
    std::vector<char> collides;
    long stepCount = 0;
    std::chrono::steady_clock::duration physics{};

    /** A collidable geom and the contact bits it has while awake. */
    struct Collider
    {
        int geom = -1;
        int contype = 0;
        int conaffinity = 0;
    };
    /** Per object: whether and since when it rests, and where it sleeps. */
    struct Rest
    {
        bool canSleep = false; ///< a single free body with collidable geoms
        bool asleep = false;
        int stillSteps = 0;
        std::vector<Collider> colliders;
        std::array<double, 7> qpos{};
        std::vector<float> alphas; ///< while broken: each geom's alpha before it vanished
        Aabb box;                  ///< while asleep: the box around it, margins included
    };
    std::vector<Rest> rests; ///< per object
    /** Collidable geoms that move but never sleep (the grippers'), in body order. */
    std::vector<int> moverGeoms;
    int sleeping = 0;          ///< objects asleep now
    std::vector<Aabb> awake;   ///< scratch: boxes around what is awake
    std::vector<char> blocked; ///< scratch: per object, stays awake this step

    /** A World on a compiled model: its grippers, objects and signals found and measured. */
    static std::unique_ptr<World> assemble(MjModelPtr model, const QString &nameOrPath,
                                           const GripperAdapter *adapter, QString *error);
    /** The moment arm of `finger`'s motor now (m; 1 for a finger on a slide of its own). */
    double arm(const Hand &hand, int finger) const
    {
        return hand.adapted
                   ? hand.geometry.arm(finger, data->qpos[model->jnt_qposadr[hand.slides[finger]]])
                   : 1.0;
    }
    void extract(World &world, double t);
    void checkFractures(World &world, double t);
    /** Object `i` breaks at `t` under `force`: it stops colliding, vanishes and is parked. */
    void fracture(World &world, size_t i, double t, double force);
    /** Whether a fingertip of `gripper` touched `object` at the last step. */
    bool touches(const World &world, Gripper gripper, int object) const;
    /**
     * Whether `touch` pushes `finger` (0 left, 1 right) of `gripper` open, as an object
     * between the pads does: mostly across the jaws (SqueezeShare).
     */
    bool pushesApart(const World &world, Gripper gripper, int finger, const Touch &touch) const;
    /** The box around a geom and its margin, as placed at the last step's start. */
    Aabb geomBox(int geom) const;
    /**
     * The box around the moving body whose geoms start at moverGeoms[*k] (a finger's pad of
     * taxels is one box: fewer tests, a little more caution); *k moves past them.
     */
    Aabb moverBox(size_t *k) const;
    /** An upper bound on the speed of `point`, fixed to `body`. */
    double speedAt(int body, const double *point) const;
    /** The box around an object; if `moving`, grown by the wake margin and 2 steps' travel. */
    Aabb objectBox(const World &world, size_t object, bool moving) const;
    /** Fills `awake` with the movers and the awake objects (only those `moving` marks). */
    void collectAwake(const World &world, const std::vector<char> *moving);
    /** Gives a sleeping object its contacts back (broken ones stay without). */
    void wake(const World &world, size_t object);
    /** Before a step: wakes what sleeps near anything awake, and what sleeps near those. */
    void wakeNearAwake(const World &world);
    /** After a step: sleeping objects stay exactly where they fell asleep, at rest. */
    void holdSleeping(const World &world);
    /** After a step: objects still long enough, with nothing awake near, fall asleep. */
    void sleepResting(const World &world);
};

} // namespace semhap
