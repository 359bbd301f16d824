// SPDX-License-Identifier: MIT
#pragma once

#include "actortable.h"
#include "contactframe.h"
#include "grippercomposer.h"
#include "grippergeometry.h"
#include "pose.h"
#include "routercontext.h"
#include "sceneoptions.h"

#include <QString>
#include <QStringList>

#include <array>
#include <memory>
#include <optional>
#include <vector>

// MuJoCo's handles, for the renderer in sim/ (its header stays out of the others' way).
struct mjModel_;
struct mjData_;

namespace semhap {

/** A box-shaped region of the scene (a `<site>`): centre and half sizes, world axes. */
struct Region
{
    std::array<double, 3> center{};
    std::array<double, 3> half{};

    bool contains(const std::array<double, 3> &p) const;
};

/** A movable object of the scene: a free body that fingertips can touch. */
struct SceneObject
{
    QString name;
    int body = -1;             ///< MuJoCo body id
    int actor = -1;            ///< ActorTable id, as contact frames name it
    double fragileForce = 0.0; ///< grip force that fractures it (N); 0: not fragile
    bool broken = false;
    double mass = 0.0;             ///< kg
    double friction = 1.0;         ///< the lowest sliding friction of its geoms
    std::array<double, 3> lower{}; ///< the box around its geoms, in its body frame
    std::array<double, 3> upper{};
};

/** A fracture: a fragile object gripped harder than it can take. */
struct Fracture
{
    double t = 0.0;
    int object = -1;
    double force = 0.0; ///< the grip force on it when it broke (N)
};

/**
 * A MuJoCo scene with semhap's grippers in it: pose targets and grip forces in, one
 * ContactFrame per gripper per physics step out, fragile objects that fracture. The naming
 * convention that makes a user's MJCF work is in sim/README.md. Not thread-safe; one owner.
 */
class World
{
public:
    /** Loads a scene (built-in name or MJCF path); null with a one-line `error`. */
    static std::unique_ptr<World> load(const QString &nameOrPath, const SceneOptions &options,
                                       QString *error);
    /** The bundled scenes' names, for pickers that must not see MuJoCo's headers. */
    static QStringList builtinScenes();
    ~World();

    const QString &sceneName() const { return m_sceneName; }
    double time() const;
    double timestep() const;

    /** One physics step; then fractures, and a fresh ContactFrame per gripper. */
    void step();
    /** Wall-clock seconds spent in MuJoCo's mj_step so far (what benchmarks compare to). */
    double physicsSeconds() const;

    bool hasGripper(Gripper gripper) const;
    /**
     * The signals the scene declares for `gripper`'s frames, in the order declared
     * (sim/README.md, "Signals"); every frame of that gripper carries them.
     */
    QStringList signalNames(Gripper gripper) const;
    /** The scene's task (`<text name="semhap:task">`); empty when it names none. */
    const QString &taskName() const { return m_taskName; }
    /** Where the wrist should be: the gripper follows this target through a soft weld. */
    void setTarget(Gripper gripper, const Pose &target);
    Pose target(Gripper gripper) const;
    /** Total closing force of both fingers (N); negative opens the gripper. */
    void setGrip(Gripper gripper, double force);
    double grip(Gripper gripper) const;
    /** Where the gripper is now (its body frame). */
    Pose gripperPose(Gripper gripper) const;
    /** How far the fingers have closed from fully open (m, the mean of both fingers). */
    double fingerTravel(Gripper gripper) const;
    /**
     * The total grip force (N) that closes the free fingers at `speed` (m/s) against their
     * joints' damping; 0 when the joints have none (the speed is then not the force's).
     */
    double closingForce(Gripper gripper, double speed) const;
    /**
     * How far below the wrist, along the fingers, the pads' centre is when the pads are `gap`
     * apart (m): measured from the model at load (a linkage's pads drop as they close).
     */
    double padDrop(Gripper gripper, double gap) const;
    /** How far below the wrist the pads reach at `gap`: their lowest point (m). */
    double padReach(Gripper gripper, double gap) const;
    /**
     * How many pad geoms of both fingertips a flat object held between them touches: the
     * contact count `n` of a full, steady grasp (32 for the bundled 4 × 4 taxel pads).
     */
    int fullContacts(Gripper gripper) const;
    /**
     * What routers on this gripper's frames are fitted to (docs/detectors.md): the full-grasp
     * contact count measured, and the force ripple, each unless its adapter states it.
     */
    GripperTraits gripperTraits(Gripper gripper) const;
    /** The geoms of fingertip `finger` (0 left, 1 right) of `gripper`: its pads, MuJoCo ids. */
    std::vector<int> fingertipGeoms(Gripper gripper, int finger) const;
    /** What the gripper's fingers do as they close, measured at load (GripperGeometry). */
    const GripperGeometry &gripperGeometry(Gripper gripper) const;
    /**
     * Where a gripper adapter's model sits in the wrists (its own, or the one the loader
     * fitted); none for a scene's own grippers.
     */
    const std::optional<GripperComposer::Mount> &gripperMount() const { return m_mount; }
    /** The highest total grip force the actuators can give (N). */
    double maxGrip(Gripper gripper) const;
    /**
     * How hard the surfaces under the gripper push its fingertips up (N, the world's vertical
     * component of the fingertips' contact forces): pads resting on a cube, or a held cube
     * set down on a stack. A carried cube's weight pulls down and does not count.
     */
    double supportForce(Gripper gripper) const;
    /**
     * The height (m) of the first surface straight below `point` that is neither part of the
     * gripper nor an object its fingertips touch (what a held cube would land on); none
     * when nothing is below.
     */
    std::optional<double> surfaceBelow(Gripper gripper, const std::array<double, 3> &point) const;
    /**
     * How far (m) the gripper can go straight down before what touches first (a fingertip,
     * or an object its fingertips touch) meets something: the smallest vertical gap between
     * the boxes around them and the boxes around what lies below them; 0 once they touch.
     * Conservative for tilted shapes (their boxes are larger); none when nothing is below.
     */
    std::optional<double> clearanceBelow(Gripper gripper) const;

    /**
     * The object both fingertips of `gripper` touched at the last step (the one they pressed
     * hardest, if several), or -1: what the fingers are closing on, or rest on.
     */
    int objectBetween(Gripper gripper) const;
    /**
     * As objectBetween(), but only an object that pushes both pads open: what the fingers
     * hold. Closed fingertips resting on top of a cube touch it, but do not hold it.
     */
    int objectSqueezed(Gripper gripper) const;
    /** Whether both fingertips of `gripper` touched `object` at the last step. */
    bool isBetween(Gripper gripper, int object) const;

    /** The contact frame of the last step (t = the time its contacts were computed). */
    const ContactFrame &frame(Gripper gripper) const;
    const ActorTable &actors() const { return m_actors; }

    const std::vector<SceneObject> &objects() const { return m_objects; }
    /** The object with this name, or -1. */
    int objectIndex(const QString &name) const;
    std::array<double, 3> objectPosition(int object) const;
    Pose objectPose(int object) const;
    std::array<double, 3> objectVelocity(int object) const;
    /** Puts an object back at `pos`, upright and at rest (a respawned container). */
    void placeObject(int object, const std::array<double, 3> &pos);
    /** Puts an object at `pose`, at rest (a plug the task lays out again). */
    void setObjectPose(int object, const Pose &pose);
    /**
     * Moves a mocap body that is no gripper's target (a fixture the task lays out, such as
     * usb_insertion's port); false when there is no such body.
     */
    bool placeFixture(const QString &body, const Pose &pose);
    /** Where body `name` is, with its orientation; none when the scene has no such body. */
    std::optional<Pose> bodyPose(const QString &name) const;
    /** Where site `name` is, with its orientation; none when the scene has no such site. */
    std::optional<Pose> sitePose(const QString &name) const;
    /** Where the scene put the object at the start (its free joint's initial position). */
    std::array<double, 3> homePosition(int object) const;
    /**
     * Puts an object back in play at `pos`, upright and at rest; a broken one is whole again
     * (it collides and shows as before it broke): a cube the task replaces.
     */
    void restoreObject(int object, const std::array<double, 3> &pos);
    /** The region of site `name`; false when the scene has no such site. */
    bool region(const QString &name, Region *region) const;

    /**
     * Where every body is, to draw the scene again later (SceneState::pose): the
     * generalized positions, then each mocap body's position and quaternion.
     */
    std::vector<double> sceneState() const;
    /** How many numbers sceneState() gives for this scene. */
    int sceneStateSize() const;
    /**
     * Puts the bodies where `pose` says, at rest, and updates what the renderer and the
     * contact arrows read (a replay's world; it is not stepped afterwards). False when the
     * pose is not one of this scene's (another scene, another number of cubes).
     */
    bool setSceneState(const std::vector<double> &pose);
    /**
     * Objects asleep now: at rest with nothing awake near them, they keep their pose without
     * contacts until something comes near (sim/README.md, "Sleeping objects").
     */
    int sleepingObjects() const;

    /** The fractures of the last step. */
    const std::vector<Fracture> &fractures() const { return m_fractures; }
    /**
     * Breaks `object` now, as a fracture does (it leaves play and is listed in fractures()):
     * a task's own rule, such as a plate pressed too hard by a tool rather than by fingertips.
     */
    void breakObject(int object, double force);

    /**
     * Sets the control of the scene's actuator `name` (a task changing the scene); false when
     * it has none.
     */
    bool setControl(const QString &actuator, double value);
    /** The geom named `name`, or -1. */
    int geomIndex(const QString &name) const;
    /** Sets how opaque a geom is drawn, 0 to 1 (a stain wiped off). */
    void setGeomAlpha(int geom, double alpha);

    /** The MuJoCo model and state, for the renderer (sim/ only). */
    const mjModel_ *model() const;
    const mjData_ *data() const;

private:
    World();
    /** The object both fingertips touched hardest; with `squeezed`, only one pushing them open. */
    int hardestTouched(Gripper gripper, bool squeezed) const;

    struct Private;
    std::unique_ptr<Private> d;

    QString m_sceneName;
    QString m_taskName;
    std::optional<GripperComposer::Mount> m_mount;
    int m_adapterFullContacts = 0;   ///< the adapter's, 0: measured
    double m_adapterForceRipple = 0; ///< the adapter's, N
    ActorTable m_actors;
    std::vector<SceneObject> m_objects;
    std::vector<Fracture> m_fractures;
};

} // namespace semhap
