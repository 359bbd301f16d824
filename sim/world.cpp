// SPDX-License-Identifier: MIT
#include "world.h"

#include "gripperadapter.h"
#include "grippergeometry.h"
#include "gripperlibrary.h"
#include "mujocohandles.h"
#include "scenelibrary.h"
#include "scenesignals.h"

#include <QByteArray>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace semhap {

namespace {

// A fragile object breaks when gripped above its force for this many steps in a row: a
// single-step impact spike (a finger arriving fast) is physics noise, not a squeeze.
constexpr int FractureSteps = 3;
// Where broken objects are parked, out of sight and out of play.
constexpr double ParkingDepth = -2.0;
// Distinct bodies one fingertip is tracked touching at once; more are not told apart.
constexpr int MaxTouched = 8;
// The least share of a pad's force from an object that must push it open for the object to be
// between the pads (cos 60 degrees). A held cube's weight, borne by the pads' friction, tilts
// that force from the closing axis, by less than 60 degrees while each pad presses with more
// than 0.29 times the weight: any grip that holds it with a friction coefficient up to 1.7.
constexpr double SqueezeShare = 0.5;
// Steps a fingertip's force is held while its force contacts drop out but it still touches.
constexpr int MaxForceHoldSteps = 2;
// Resting objects sleep (sim/README.md, "Sleeping objects"): still for this many steps in a
// row, slower than these speeds, with nothing awake within WakeMargin.
constexpr int SleepAfterSteps = 100;
constexpr double StillSpeed = 0.002;       // m/s
constexpr double StillAngularSpeed = 0.05; // rad/s
// Clearance kept between anything awake and a sleeping object, on top of the distance the
// awake thing covers in two steps: a sleeping object wakes before anything can touch it.
constexpr double WakeMargin = 0.008; // m
// Where a mounted model's pads' centre goes below the wrist when no mount is given: where
// the bundled grippers have theirs.
constexpr double PadsBelowWrist = 0.06; // m

int id(const mjModel *m, mjtObj type, const QString &name)
{
    return mj_name2id(m, type, name.toUtf8().constData());
}

QString name(const mjModel *m, mjtObj type, int index)
{
    const char *text = mj_id2name(m, type, index);
    return text ? QString::fromUtf8(text) : QString();
}

/**
 * Whether actuator `a` turns its control into a force on a joint, as operators command
 * grips in newtons: no activation dynamics, a fixed gain, no bias. A position servo (a
 * bias) would read newtons as a position, and a run would grasp nothing without a word.
 */
bool isForceMotorOnJoint(const mjModel *m, int a)
{
    return m->actuator_trntype[a] == mjTRN_JOINT && m->actuator_dyntype[a] == mjDYN_NONE &&
           m->actuator_gaintype[a] == mjGAIN_FIXED && m->actuator_biastype[a] == mjBIAS_NONE;
}

/** What actuator `a` is instead, for the error that refuses it. */
QString actuatorKind(const mjModel *m, int a)
{
    if (m->actuator_trntype[a] != mjTRN_JOINT)
        return QStringLiteral("it drives a tendon, a site or a body, not a joint");
    if (m->actuator_biastype[a] != mjBIAS_NONE)
        return QStringLiteral("it is a servo (it has a bias: a position or velocity actuator)");
    if (m->actuator_dyntype[a] != mjDYN_NONE)
        return QStringLiteral("it has activation dynamics (a filter or an integrator)");
    return QStringLiteral("its gain is not fixed");
}

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

/**
 * The mount that turns a model measured at the identity mount so its fingers point down (-z)
 * and close along y, left finger at +y, with the pads' centre 6 cm below the wrist when open:
 * where semhap's own grippers have them.
 */
GripperComposer::Mount fittingMount(const GripperGeometry &geometry)
{
    const auto &y = geometry.closingAxis();
    const auto &a = geometry.approachAxis();
    const std::array<double, 3> z{-a[0], -a[1], -a[2]};
    const std::array<double, 3> x{y[1] * z[2] - y[2] * z[1], y[2] * z[0] - y[0] * z[2],
                                  y[0] * z[1] - y[1] * z[0]};
    // Rows x, y, z: the rotation taking the model's axes to the wrist's.
    const mjtNum rotation[9] = {x[0], x[1], x[2], y[0], y[1], y[2], z[0], z[1], z[2]};
    GripperComposer::Mount mount;
    mjtNum quat[4];
    mju_mat2Quat(quat, rotation);
    const auto &c = geometry.openCentre();
    for (int i = 0; i < 3; ++i)
        mount.pos[size_t(i)] =
            (i == 2 ? -PadsBelowWrist : 0.0) -
            (rotation[3 * i] * c[0] + rotation[3 * i + 1] * c[1] + rotation[3 * i + 2] * c[2]);
    for (int i = 0; i < 4; ++i)
        mount.quat[size_t(i)] = quat[i];
    return mount;
}

} // namespace

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

World::World() : d(std::make_unique<Private>()) {}

World::~World() = default;

QStringList World::builtinScenes()
{
    return SceneLibrary::builtinNames();
}

std::unique_ptr<World> World::load(const QString &nameOrPath, const SceneOptions &options,
                                   QString *error)
{
    if (options.gripper.isEmpty()) {
        MjModelPtr model = SceneLibrary::load(nameOrPath, options, error);
        return model ? Private::assemble(std::move(model), nameOrPath, nullptr, error) : nullptr;
    }
    const QString path = GripperLibrary::find(options.gripper);
    if (path.isEmpty()) {
        *error = QStringLiteral("%1: no such gripper adapter (adapters: %2)")
                     .arg(options.gripper, GripperLibrary::names().join(QStringLiteral(", ")));
        return nullptr;
    }
    GripperAdapter adapter;
    LoadError adapterError;
    if (!GripperAdapter::read(path, &adapter, &adapterError)) {
        *error = adapterError.toString();
        return nullptr;
    }
    GripperComposer::Mount mount;
    if (adapter.hasMount)
        mount = {adapter.mountPos, adapter.mountQuat};
    const QString where = nameOrPath + QStringLiteral(" with ") + path;
    MjModelPtr model = SceneLibrary::load(nameOrPath, options, &adapter, mount, error);
    std::unique_ptr<World> world =
        model ? Private::assemble(std::move(model), where, &adapter, error) : nullptr;
    // What the loaded world keeps of its adapter.
    const auto adopt = [&](World &w) {
        w.m_mount = mount;
        w.m_adapterFullContacts = adapter.fullContacts;
        w.m_adapterForceRipple = std::max(0.0, adapter.forceRipple);
    };
    if (world)
        adopt(*world);
    if (!world || adapter.hasMount)
        return world;
    // No mount given: turn the model so its fingers point down and close along y, the pads'
    // centre 6 cm below the wrist when open (docs/grippers.md), as measured on this first load.
    const Gripper hand = world->hasGripper(Gripper::Right) ? Gripper::Right : Gripper::Left;
    mount = fittingMount(world->d->hands[size_t(hand)].geometry);
    model = SceneLibrary::load(nameOrPath, options, &adapter, mount, error);
    world = model ? Private::assemble(std::move(model), where, &adapter, error) : nullptr;
    if (world)
        adopt(*world);
    return world;
}

std::unique_ptr<World> World::Private::assemble(MjModelPtr model, const QString &nameOrPath,
                                                const GripperAdapter *adapter, QString *error)
{
    std::unique_ptr<World> world(new World);
    world->m_sceneName = nameOrPath;
    Private &p = *world->d;
    const mjModel *m = model.get();
    p.data.reset(mj_makeData(m));
    p.model = std::move(model);

    p.tipOfGeom.assign(size_t(m->ngeom), -1);
    p.taxelStamp.assign(size_t(m->ngeom), -1);
    for (Gripper g : {Gripper::Left, Gripper::Right}) {
        const QString hand = gripperName(g);
        Private::Hand &h = p.hands[size_t(g)];
        h.body = id(m, mjOBJ_BODY, hand + QStringLiteral(".gripper"));
        const int target = id(m, mjOBJ_BODY, hand + QStringLiteral(".target"));
        h.actuators[0] = id(m, mjOBJ_ACTUATOR, hand + QStringLiteral(".grip.left"));
        h.actuators[1] = id(m, mjOBJ_ACTUATOR, hand + QStringLiteral(".grip.right"));
        h.present = h.body >= 0 && target >= 0 && m->body_mocapid[target] >= 0 &&
                    h.actuators[0] >= 0 && h.actuators[1] >= 0;
        if (h.body >= 0 && !h.present) {
            *error = QStringLiteral("%1: gripper '%2' needs a mocap body %2.target and "
                                    "actuators %2.grip.left, %2.grip.right (see sim/README.md)")
                         .arg(nameOrPath, hand);
            return nullptr;
        }
        if (!h.present)
            continue;
        for (int finger = 0; finger < 2; ++finger) {
            const int a = h.actuators[finger];
            if (!isForceMotorOnJoint(m, a)) {
                *error = QStringLiteral("%1: actuator %2 must be a motor on its finger's "
                                        "joint, force in N closing (see sim/README.md): %3")
                             .arg(nameOrPath, name(m, mjOBJ_ACTUATOR, a), actuatorKind(m, a));
                return nullptr;
            }
            h.slides[finger] = m->actuator_trnid[2 * a];
        }
        h.mocap = m->body_mocapid[target];
        h.frame.gripper = g;
        for (int finger = 0; finger < 2; ++finger) {
            const QString prefix = hand + (finger == 0 ? QStringLiteral(".tip.left.")
                                                       : QStringLiteral(".tip.right."));
            const int tip = int(g) * 2 + finger;
            p.tips[size_t(tip)].gripperBody = h.body;
            for (int geom = 0; geom < m->ngeom; ++geom) {
                if (name(m, mjOBJ_GEOM, geom).startsWith(prefix))
                    p.tipOfGeom[size_t(geom)] = tip;
            }
        }
    }
    if (!p.hands[0].present && !p.hands[1].present) {
        *error = nameOrPath + QStringLiteral(": no gripper (a body left.gripper or "
                                             "right.gripper; see sim/README.md)");
        return nullptr;
    }
    for (Gripper g : {Gripper::Left, Gripper::Right}) {
        Private::Hand &h = p.hands[size_t(g)];
        if (!h.present)
            continue;
        const std::array<std::vector<int>, 2> pads{world->fingertipGeoms(g, 0),
                                                   world->fingertipGeoms(g, 1)};
        QString reason;
        // A gripper without fingertips touches nothing (a scene testing other things): no
        // geometry to measure.
        if (pads[0].empty() || pads[1].empty() ||
            h.geometry.measure(m, h.body, {h.slides[0], h.slides[1]}, pads, &reason)) {
            h.adapted = adapter != nullptr;
            h.padDamping = adapter ? adapter->damping : 0.0;
            continue;
        }
        *error = QStringLiteral("%1: gripper '%2': %3").arg(nameOrPath, gripperName(g), reason);
        return nullptr;
    }

    if (!p.sceneSignals.load(m, nameOrPath, {p.hands[0].present, p.hands[1].present}, error))
        return nullptr;
    const int task = id(m, mjOBJ_TEXT, QStringLiteral("semhap:task"));
    if (task >= 0)
        world->m_taskName = QString::fromUtf8(m->text_data + m->text_adr[task]);

    // Objects: free root bodies that are not grippers. Their names are the actors.
    p.objectOfBody.assign(size_t(m->nbody), -1);
    for (int body = 1; body < m->nbody; ++body) {
        const int joint = m->body_jntadr[body];
        if (m->body_parentid[body] != 0 || joint < 0 || m->jnt_type[joint] != mjJNT_FREE ||
            body == p.hands[0].body || body == p.hands[1].body)
            continue;
        SceneObject object;
        object.name = name(m, mjOBJ_BODY, body);
        object.body = body;
        object.actor = world->m_actors.intern(object.name);
        const int numeric = id(m, mjOBJ_NUMERIC, QStringLiteral("fragile:") + object.name);
        if (numeric >= 0)
            object.fragileForce = m->numeric_data[m->numeric_adr[numeric]];
        object.mass = m->body_subtreemass[body];
        // Its extent and grip, for operators and tasks that must know how big and how
        // slippery it is (boxes exactly, other shapes by their bounding sphere).
        bool first = true;
        for (int geom = 0; geom < m->ngeom; ++geom) {
            if (m->geom_bodyid[geom] != body)
                continue;
            object.friction = first ? m->geom_friction[3 * geom]
                                    : std::min(object.friction, m->geom_friction[3 * geom]);
            for (int axis = 0; axis < 3; ++axis) {
                const double half = m->geom_type[geom] == mjGEOM_BOX
                                        ? m->geom_size[3 * geom + axis]
                                        : m->geom_rbound[geom];
                const double centre = m->geom_pos[3 * geom + axis];
                const double low = centre - half;
                const double high = centre + half;
                object.lower[size_t(axis)] =
                    first ? low : std::min(object.lower[size_t(axis)], low);
                object.upper[size_t(axis)] =
                    first ? high : std::max(object.upper[size_t(axis)], high);
            }
            first = false;
        }
        p.objectOfBody[size_t(body)] = int(world->m_objects.size());
        world->m_objects.push_back(object);
    }
    p.gripOnObject.assign(world->m_objects.size(), 0.0);
    p.overForceSteps.assign(world->m_objects.size(), 0);

    // Sleeping: objects that are one free body (a joint further down would not stay put)
    // with collidable geoms; the grippers' collidable geoms are what wakes them.
    p.rests.resize(world->m_objects.size());
    p.blocked.assign(world->m_objects.size(), 0);
    for (size_t i = 0; i < world->m_objects.size(); ++i) {
        const int body = world->m_objects[i].body;
        Private::Rest &rest = p.rests[i];
        bool single = true;
        for (int b = 1; b < m->nbody; ++b)
            single = single && (b == body || m->body_rootid[b] != body);
        for (int geom = 0; geom < m->ngeom; ++geom) {
            if (m->geom_bodyid[geom] == body &&
                (m->geom_contype[geom] != 0 || m->geom_conaffinity[geom] != 0))
                rest.colliders.push_back({geom, m->geom_contype[geom], m->geom_conaffinity[geom]});
        }
        rest.canSleep = single && !rest.colliders.empty();
    }
    p.collides.resize(size_t(m->ngeom));
    for (int geom = 0; geom < m->ngeom; ++geom)
        p.collides[size_t(geom)] = m->geom_contype[geom] != 0 || m->geom_conaffinity[geom] != 0;
    // Whatever else can move and touch them wakes them: the grippers, and any other body
    // with a joint or a mocap root (a user's scene may have more).
    for (int geom = 0; geom < m->ngeom; ++geom) {
        const int body = m->geom_bodyid[geom];
        const int root = m->body_rootid[body];
        const int object = p.objectOfBody[size_t(root)];
        const bool sleeper = object >= 0 && p.rests[size_t(object)].canSleep;
        const bool moves = m->body_weldid[body] != 0 || m->body_mocapid[root] >= 0;
        if (!sleeper && moves && (m->geom_contype[geom] != 0 || m->geom_conaffinity[geom] != 0))
            p.moverGeoms.push_back(geom);
    }

    mj_forward(m, p.data.get());
    // Targets start where the grippers are, so nothing jumps at the first step.
    for (Gripper g : {Gripper::Left, Gripper::Right}) {
        if (world->hasGripper(g))
            world->setTarget(g, world->gripperPose(g));
    }
    return world;
}

double World::time() const
{
    return d->data->time;
}

double World::timestep() const
{
    return d->model->opt.timestep;
}

void World::step()
{
    const double t = d->data->time;
    d->wakeNearAwake(*this);
    for (const Private::Hand &h : d->hands) {
        for (int finger = 0; h.adapted && finger < 2; ++finger) {
            const int joint = h.slides[finger];
            const double q = d->data->qpos[d->model->jnt_qposadr[joint]];
            d->model->actuator_gear[6 * h.actuators[finger]] = h.geometry.arm(finger, q);
            const int dof = d->model->jnt_dofadr[joint];
            const double arm = h.geometry.arm(finger, q);
            d->data->qfrc_applied[dof] =
                -h.geometry.spring(finger, q) - h.padDamping * arm * arm * d->data->qvel[dof];
        }
    }
    const auto start = std::chrono::steady_clock::now();
    mj_step(d->model.get(), d->data.get());
    d->physics += std::chrono::steady_clock::now() - start;
    d->holdSleeping(*this);
    ++d->stepCount;
    m_fractures.clear();
    d->extract(*this, t);
    for (Gripper g : {Gripper::Left, Gripper::Right}) {
        if (hasGripper(g))
            d->sceneSignals.write(d->model.get(), d->data.get(), g, &d->hands[size_t(g)].frame);
    }
    d->checkFractures(*this, t);
    d->sleepResting(*this);
}

int World::sleepingObjects() const
{
    return d->sleeping;
}

double World::physicsSeconds() const
{
    return std::chrono::duration<double>(d->physics).count();
}

void World::Private::extract(World &world, double t)
{
    const mjModel *m = model.get();
    const mjData *dd = data.get();
    for (Tip &tip : tips) {
        tip.force = 0.0;
        tip.contacts = 0;
        tip.fworld = {};
        tip.touchedCount = 0;
    }
    std::fill(gripOnObject.begin(), gripOnObject.end(), 0.0);

    for (int c = 0; c < dd->ncon; ++c) {
        const mjContact &contact = dd->contact[c];
        const int tip1 = tipOfGeom[size_t(contact.geom1)];
        const int tip2 = tipOfGeom[size_t(contact.geom2)];
        if ((tip1 < 0) == (tip2 < 0))
            continue; // no fingertip, or two fingertips touching each other
        const bool tipIsFirst = tip1 >= 0;
        Tip &tip = tips[size_t(tipIsFirst ? tip1 : tip2)];
        const int taxel = tipIsFirst ? contact.geom1 : contact.geom2;
        const int other = tipIsFirst ? contact.geom2 : contact.geom1;
        const int root = m->body_rootid[m->geom_bodyid[other]];
        if (root == tip.gripperBody)
            continue; // the gripper's own parts
        const int object = objectOfBody[size_t(root)];
        const int actor = object >= 0 ? world.m_objects[size_t(object)].actor : -1;

        Touch *touch = nullptr;
        for (int i = 0; i < tip.touchedCount; ++i) {
            if (tip.touched[size_t(i)].actor == actor)
                touch = &tip.touched[size_t(i)];
        }
        if (!touch && tip.touchedCount < MaxTouched) {
            touch = &tip.touched[size_t(tip.touchedCount++)];
            *touch = Touch{actor, 0.0, 0, {}};
        }
        // A taxel counts once however many contact points it has. Contacts inside the
        // geoms' gap (efc_address < 0) count too: they keep n steady while an object slides.
        if (taxelStamp[size_t(taxel)] != stepCount) {
            taxelStamp[size_t(taxel)] = stepCount;
            ++tip.contacts;
            if (touch)
                ++touch->contacts;
        }
        if (contact.efc_address < 0)
            continue;
        mjtNum local[6];
        mj_contactForce(m, dd, c, local);
        const double magnitude =
            std::sqrt(local[0] * local[0] + local[1] * local[1] + local[2] * local[2]);
        tip.force += magnitude;
        if (touch)
            touch->force += magnitude;
        if (object >= 0)
            gripOnObject[size_t(object)] += magnitude;
        // The contact frame's rows are its axes in world coordinates; the force acts on
        // geom2 along them, so on geom1 it is the opposite.
        const double sign = tipIsFirst ? -1.0 : 1.0;
        for (int axis = 0; axis < 3; ++axis) {
            for (int k = 0; k < 3; ++k) {
                const double component = sign * local[axis] * contact.frame[3 * axis + k];
                tip.fworld[size_t(k)] += component;
                if (touch)
                    touch->fworld[size_t(k)] += component;
            }
        }
    }

    // Robust force: while an object slides, all of a fingertip's force contacts can drop
    // out for a step or two although its taxels still touch (n holds; sim/README.md). A
    // force sensor would not see such a gap; the detectors would (a grasp ending and
    // beginning again, a slip detector reset), so the last force is held over it.
    for (Tip &tip : tips) {
        if (tip.force == 0.0 && tip.contacts > 0 && tip.heldForce > 0.0 &&
            tip.heldSteps < MaxForceHoldSteps) {
            tip.force = tip.heldForce;
            tip.fworld = tip.heldFworld;
            ++tip.heldSteps;
        } else {
            tip.heldForce = tip.force;
            tip.heldFworld = tip.fworld;
            tip.heldSteps = 0;
        }
    }

    for (Gripper g : {Gripper::Left, Gripper::Right}) {
        Hand &hand = hands[size_t(g)];
        if (!hand.present)
            continue;
        // MuJoCo adds up its time step by step; frames carry it to the nanosecond, as the
        // player's instants do, so streams read 1.25 rather than 1.2499999999999.
        hand.frame.t = std::round(t * 1e9) / 1e9;
        const mjtNum *rotation = dd->xmat + 9 * hand.body;
        for (int finger = 0; finger < 2; ++finger) {
            const Tip &tip = tips[size_t(int(g) * 2 + finger)];
            Fingertip &out = finger == 0 ? hand.frame.left : hand.frame.right;
            out.f = tip.force;
            out.n = tip.contacts;
            // The touched body carrying the most force; without force, the most contacts.
            out.actor = -1;
            double bestForce = -1.0;
            int bestContacts = -1;
            for (int i = 0; i < tip.touchedCount; ++i) {
                const Touch &touch = tip.touched[size_t(i)];
                if (touch.force > bestForce ||
                    (touch.force == bestForce && touch.contacts > bestContacts)) {
                    bestForce = touch.force;
                    bestContacts = touch.contacts;
                    out.actor = touch.actor;
                }
            }
            // The touched object's friction: the objects' geoms have contact priority, so
            // theirs is the coefficient of the contact (sim/README.md).
            out.mu = 0.0;
            for (const SceneObject &object : world.m_objects) {
                if (object.actor == out.actor && out.actor >= 0)
                    out.mu = object.friction;
            }
            // Into the gripper frame: R^T · f (xmat is row-major, body to world).
            out.hasFxyz = true;
            for (int row = 0; row < 3; ++row) {
                out.fxyz[size_t(row)] = rotation[row] * tip.fworld[0] +
                                        rotation[3 + row] * tip.fworld[1] +
                                        rotation[6 + row] * tip.fworld[2];
            }
        }
    }
}

void World::Private::checkFractures(World &world, double t)
{
    for (size_t i = 0; i < world.m_objects.size(); ++i) {
        SceneObject &object = world.m_objects[i];
        if (object.broken) {
            // Gravity would pull a parked object down forever: put it back every step.
            world.placeObject(int(i), {0.0, 0.0, ParkingDepth});
            continue;
        }
        if (object.fragileForce <= 0)
            continue;
        overForceSteps[i] = gripOnObject[i] > object.fragileForce ? overForceSteps[i] + 1 : 0;
        if (overForceSteps[i] >= FractureSteps)
            fracture(world, i, t, gripOnObject[i]);
    }
}

void World::Private::fracture(World &world, size_t i, double t, double force)
{
    SceneObject &object = world.m_objects[i];
    wake(world, i);
    object.broken = true;
    world.m_fractures.push_back({t, int(i), force});
    mjModel *m = model.get();
    std::vector<float> &alphas = rests[i].alphas;
    alphas.clear();
    for (int geom = 0; geom < m->ngeom; ++geom) {
        if (m->geom_bodyid[geom] == object.body) {
            m->geom_contype[geom] = 0;
            m->geom_conaffinity[geom] = 0;
            alphas.push_back(m->geom_rgba[4 * geom + 3]);
            m->geom_rgba[4 * geom + 3] = 0.0f;
        }
    }
    world.placeObject(int(i), {0.0, 0.0, ParkingDepth});
}

void World::breakObject(int object, double force)
{
    if (!m_objects[size_t(object)].broken)
        d->fracture(*this, size_t(object), time(), force);
}

bool World::setControl(const QString &actuator, double value)
{
    const int index = id(d->model.get(), mjOBJ_ACTUATOR, actuator);
    if (index >= 0)
        d->data->ctrl[index] = value;
    return index >= 0;
}

int World::geomIndex(const QString &geomName) const
{
    return id(d->model.get(), mjOBJ_GEOM, geomName);
}

void World::setGeomAlpha(int geom, double alpha)
{
    d->model->geom_rgba[4 * geom + 3] = float(alpha);
}

Aabb World::Private::moverBox(size_t *k) const
{
    const int body = model->geom_bodyid[moverGeoms[*k]];
    Aabb box = geomBox(moverGeoms[*k]);
    for (; *k < moverGeoms.size() && model->geom_bodyid[moverGeoms[*k]] == body; ++*k)
        box.unite(geomBox(moverGeoms[*k]));
    return box;
}

Aabb World::Private::geomBox(int geom) const
{
    const mjModel *m = model.get();
    const mjData *dd = data.get();
    const mjtNum *centre = dd->geom_xpos + 3 * geom;
    const mjtNum *size = m->geom_size + 3 * geom;
    std::array<double, 3> half{};
    if (m->geom_type[geom] == mjGEOM_BOX) {
        // The rotated box's extent along each world axis (xmat is row-major, local to world).
        const mjtNum *r = dd->geom_xmat + 9 * geom;
        for (size_t i = 0; i < 3; ++i) {
            half[i] = std::abs(r[3 * i]) * size[0] + std::abs(r[3 * i + 1]) * size[1] +
                      std::abs(r[3 * i + 2]) * size[2];
        }
    } else {
        const double radius = m->geom_type[geom] == mjGEOM_SPHERE ? size[0] : m->geom_rbound[geom];
        half = {radius, radius, radius};
    }
    Aabb box;
    for (size_t i = 0; i < 3; ++i) {
        box.low[i] = centre[i] - half[i] - m->geom_margin[geom];
        box.high[i] = centre[i] + half[i] + m->geom_margin[geom];
    }
    return box;
}

double World::Private::speedAt(int body, const double *point) const
{
    // cvel is [angular; linear] at the subtree centre of mass of the body's root.
    const mjModel *m = model.get();
    const mjData *dd = data.get();
    const mjtNum *v = dd->cvel + 6 * body;
    const mjtNum *com = dd->subtree_com + 3 * m->body_rootid[body];
    double arm = 0.0;
    for (int i = 0; i < 3; ++i)
        arm += (point[i] - com[i]) * (point[i] - com[i]);
    return std::sqrt(v[3] * v[3] + v[4] * v[4] + v[5] * v[5]) +
           std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) * std::sqrt(arm);
}

Aabb World::Private::objectBox(const World &world, size_t object, bool moving) const
{
    const Rest &rest = rests[object];
    Aabb box = geomBox(rest.colliders.front().geom);
    for (const Collider &c : rest.colliders)
        box.unite(geomBox(c.geom));
    if (moving) {
        const int body = world.m_objects[object].body;
        const mjtNum *centre = data->xpos + 3 * body;
        box.grow(WakeMargin + 2 * model->opt.timestep * speedAt(body, centre));
    }
    return box;
}

void World::Private::collectAwake(const World &world, const std::vector<char> *moving)
{
    const double dt = model->opt.timestep;
    awake.clear();
    // One box per moving body.
    for (size_t k = 0; k < moverGeoms.size();) {
        const int body = model->geom_bodyid[moverGeoms[k]];
        const size_t first = k;
        Aabb box = moverBox(&k);
        double speed = 0.0;
        for (size_t g = first; g < k; ++g)
            speed = std::max(speed, speedAt(body, data->geom_xpos + 3 * moverGeoms[g]));
        box.grow(WakeMargin + 2 * dt * speed);
        awake.push_back(box);
    }
    for (size_t i = 0; i < rests.size(); ++i) {
        if (!rests[i].asleep && !world.m_objects[i].broken && rests[i].canSleep &&
            (!moving || (*moving)[i]))
            awake.push_back(objectBox(world, i, true));
    }
}

void World::Private::wake(const World &world, size_t object)
{
    Rest &rest = rests[object];
    rest.stillSteps = 0;
    if (!rest.asleep)
        return;
    rest.asleep = false;
    --sleeping;
    mjModel *m = model.get();
    if (world.m_objects[object].broken)
        return;
    for (const Collider &c : rest.colliders) {
        m->geom_contype[c.geom] = c.contype;
        m->geom_conaffinity[c.geom] = c.conaffinity;
    }
}

void World::Private::wakeNearAwake(const World &world)
{
    if (sleeping == 0)
        return;
    // Positions are those of the last step's start; the margins cover two steps' travel.
    collectAwake(world, nullptr);
    bool woke = true;
    while (woke && sleeping > 0) {
        woke = false;
        for (size_t i = 0; i < rests.size(); ++i) {
            if (!rests[i].asleep)
                continue;
            const Aabb &box = rests[i].box;
            for (const Aabb &other : awake) {
                if (box.overlaps(other)) {
                    wake(world, i);
                    // What it rests on or leans against wakes with it.
                    awake.push_back(objectBox(world, i, true));
                    woke = true;
                    break;
                }
            }
        }
    }
}

void World::Private::holdSleeping(const World &world)
{
    if (sleeping == 0)
        return;
    const mjModel *m = model.get();
    mjData *dd = data.get();
    for (size_t i = 0; i < rests.size(); ++i) {
        if (!rests[i].asleep)
            continue;
        const int joint = m->body_jntadr[world.m_objects[i].body];
        std::copy(rests[i].qpos.begin(), rests[i].qpos.end(), dd->qpos + m->jnt_qposadr[joint]);
        std::fill_n(dd->qvel + m->jnt_dofadr[joint], 6, 0.0);
    }
}

void World::Private::sleepResting(const World &world)
{
    mjModel *m = model.get();
    mjData *dd = data.get();
    bool candidates = false;
    for (size_t i = 0; i < rests.size(); ++i) {
        Rest &rest = rests[i];
        blocked[i] = 1;
        if (!rest.canSleep || rest.asleep || world.m_objects[i].broken)
            continue;
        const mjtNum *v = dd->qvel + m->jnt_dofadr[m->body_jntadr[world.m_objects[i].body]];
        const bool still =
            v[0] * v[0] + v[1] * v[1] + v[2] * v[2] < StillSpeed * StillSpeed &&
            v[3] * v[3] + v[4] * v[4] + v[5] * v[5] < StillAngularSpeed * StillAngularSpeed;
        rest.stillSteps = still ? rest.stillSteps + 1 : 0;
        if (rest.stillSteps >= SleepAfterSteps) {
            blocked[i] = 0;
            candidates = true;
        }
    }
    if (!candidates)
        return;
    // What is awake and moving keeps the resting objects near it awake, and those keep the
    // ones near them awake, and so on: objects that touch sleep and wake together.
    collectAwake(world, &blocked);
    bool more = true;
    while (more) {
        more = false;
        for (size_t i = 0; i < rests.size(); ++i) {
            if (blocked[i])
                continue;
            const Aabb box = objectBox(world, i, false);
            for (const Aabb &other : awake) {
                if (box.overlaps(other)) {
                    blocked[i] = 1;
                    awake.push_back(objectBox(world, i, true));
                    more = true;
                    break;
                }
            }
        }
    }
    for (size_t i = 0; i < rests.size(); ++i) {
        if (blocked[i])
            continue;
        Rest &rest = rests[i];
        rest.asleep = true;
        rest.box = objectBox(world, i, false);
        ++sleeping;
        const int joint = m->body_jntadr[world.m_objects[i].body];
        std::copy_n(dd->qpos + m->jnt_qposadr[joint], 7, rest.qpos.begin());
        std::fill_n(dd->qvel + m->jnt_dofadr[joint], 6, 0.0);
        for (const Collider &c : rest.colliders) {
            m->geom_contype[c.geom] = 0;
            m->geom_conaffinity[c.geom] = 0;
        }
    }
}

bool Region::contains(const std::array<double, 3> &p) const
{
    for (size_t i = 0; i < 3; ++i) {
        if (std::abs(p[i] - center[i]) > half[i])
            return false;
    }
    return true;
}

bool World::region(const QString &siteName, Region *region) const
{
    const mjModel *m = d->model.get();
    const int site = id(m, mjOBJ_SITE, siteName);
    if (site < 0)
        return false;
    std::copy_n(d->data->site_xpos + 3 * site, 3, region->center.begin());
    std::copy_n(m->site_size + 3 * site, 3, region->half.begin());
    return true;
}

QStringList World::signalNames(Gripper gripper) const
{
    return d->sceneSignals.names(gripper);
}

bool World::hasGripper(Gripper gripper) const
{
    return d->hands[size_t(gripper)].present;
}

void World::setTarget(Gripper gripper, const Pose &target)
{
    const Private::Hand &h = d->hands[size_t(gripper)];
    std::copy(target.pos.begin(), target.pos.end(), d->data->mocap_pos + 3 * h.mocap);
    std::copy(target.quat.begin(), target.quat.end(), d->data->mocap_quat + 4 * h.mocap);
}

Pose World::target(Gripper gripper) const
{
    const Private::Hand &h = d->hands[size_t(gripper)];
    Pose pose;
    std::copy_n(d->data->mocap_pos + 3 * h.mocap, 3, pose.pos.begin());
    std::copy_n(d->data->mocap_quat + 4 * h.mocap, 4, pose.quat.begin());
    return pose;
}

void World::setGrip(Gripper gripper, double force)
{
    // Each finger's pad pushes with its actuator's force: the total is twice that.
    const Private::Hand &h = d->hands[size_t(gripper)];
    for (int actuator : h.actuators)
        d->data->ctrl[actuator] = force / 2;
}

double World::grip(Gripper gripper) const
{
    const Private::Hand &h = d->hands[size_t(gripper)];
    return 2 * d->data->ctrl[h.actuators[0]];
}

double World::maxGrip(Gripper gripper) const
{
    const Private::Hand &h = d->hands[size_t(gripper)];
    return 2 * d->model->actuator_ctrlrange[2 * h.actuators[0] + 1];
}

double World::closingForce(Gripper gripper, double speed) const
{
    // Each finger's actuator pushes with half the total; a free finger moves at the speed
    // its damping takes all of that (through its moment arm: a pad at `speed` turns its
    // joint at speed / arm, and the joint's damping needs a pad force of damping * speed /
    // arm^2).
    const Private::Hand &h = d->hands[size_t(gripper)];
    const mjModel *m = d->model.get();
    double force = 0.0;
    for (int finger = 0; finger < 2; ++finger) {
        const double arm = d->arm(h, finger);
        force += m->dof_damping[m->jnt_dofadr[h.slides[finger]]] * speed / (arm * arm) +
                 h.padDamping * speed;
    }
    return force;
}

double World::fingerTravel(Gripper gripper) const
{
    const Private::Hand &h = d->hands[size_t(gripper)];
    const mjModel *m = d->model.get();
    double travel = 0.0;
    for (int finger = 0; finger < 2; ++finger) {
        const double q = d->data->qpos[m->jnt_qposadr[h.slides[finger]]];
        travel += (h.adapted ? h.geometry.travel(finger, q) : q) / 2;
    }
    return travel;
}

double World::padDrop(Gripper gripper, double gap) const
{
    return d->hands[size_t(gripper)].geometry.drop(gap);
}

double World::padReach(Gripper gripper, double gap) const
{
    return d->hands[size_t(gripper)].geometry.reach(gap);
}

std::vector<int> World::fingertipGeoms(Gripper gripper, int finger) const
{
    std::vector<int> geoms;
    const int tip = int(gripper) * 2 + finger;
    for (size_t geom = 0; geom < d->tipOfGeom.size(); ++geom) {
        if (d->tipOfGeom[geom] == tip)
            geoms.push_back(int(geom));
    }
    return geoms;
}

GripperTraits World::gripperTraits(Gripper gripper) const
{
    GripperTraits traits;
    traits.fullContacts =
        m_adapterFullContacts > 0 ? m_adapterFullContacts : fullContacts(gripper);
    traits.forceRipple = m_adapterForceRipple;
    return traits;
}

const GripperGeometry &World::gripperGeometry(Gripper gripper) const
{
    return d->hands[size_t(gripper)].geometry;
}

int World::fullContacts(Gripper gripper) const
{
    return d->hands[size_t(gripper)].geometry.fullContacts();
}

double World::supportForce(Gripper gripper) const
{
    double up = 0.0;
    for (int finger = 0; finger < 2; ++finger)
        up += d->tips[size_t(int(gripper) * 2 + finger)].fworld[2];
    return up;
}

std::optional<double> World::surfaceBelow(Gripper gripper,
                                          const std::array<double, 3> &point) const
{
    const mjModel *m = d->model.get();
    const Private::Hand &h = d->hands[size_t(gripper)];
    const int handRoot = m->body_rootid[h.body];
    auto held = [&](int root) {
        const int object = d->objectOfBody[size_t(root)];
        return object >= 0 && d->touches(*this, gripper, object);
    };
    // mj_ray stops at the first geom; the gripper and what it holds are looked through by
    // casting again just below them. A gripper has a few dozen geoms at most in a column.
    constexpr int MaxLayers = 64;
    mjtNum from[3] = {point[0], point[1], point[2]};
    const mjtNum down[3] = {0.0, 0.0, -1.0};
    for (int layer = 0; layer < MaxLayers; ++layer) {
        int geom = -1;
        const mjtNum distance = mj_ray(m, d->data.get(), from, down, nullptr, 1, -1, &geom);
        if (distance < 0 || geom < 0)
            return std::nullopt;
        const int root = m->body_rootid[m->geom_bodyid[geom]];
        const double z = from[2] - distance;
        if (root != handRoot && !held(root))
            return z;
        from[2] = z - 1e-4;
    }
    return std::nullopt;
}

std::optional<double> World::clearanceBelow(Gripper gripper) const
{
    const mjModel *m = d->model.get();
    const mjData *dd = d->data.get();
    const int handRoot = m->body_rootid[d->hands[size_t(gripper)].body];
    // What goes down with the hand: a box per finger (its pad of taxels), and the objects its
    // fingertips touch (a held cube lands before the pads do).
    std::vector<Aabb> moving;
    for (size_t k = 0; k < d->moverGeoms.size();) {
        const int body = m->geom_bodyid[d->moverGeoms[k]];
        const Aabb box = d->moverBox(&k);
        if (m->body_rootid[body] == handRoot)
            moving.push_back(box);
    }
    for (size_t i = 0; i < m_objects.size(); ++i) {
        if (!m_objects[i].broken && d->touches(*this, gripper, int(i)))
            moving.push_back(d->objectBox(*this, i, false));
    }
    std::optional<double> clearance;
    for (int geom = 0; geom < m->ngeom; ++geom) {
        const int root = m->body_rootid[m->geom_bodyid[geom]];
        const int object = d->objectOfBody[size_t(root)];
        if (root == handRoot || !d->collides[size_t(geom)] ||
            (object >= 0 &&
             (m_objects[size_t(object)].broken || d->touches(*this, gripper, object))))
            continue;
        // A plane (the floor) is taken as level and endless; anything else by its box.
        const bool plane = m->geom_type[geom] == mjGEOM_PLANE;
        const Aabb box = d->geomBox(geom);
        const double top = plane ? dd->geom_xpos[3 * geom + 2] : box.high[2];
        for (const Aabb &mover : moving) {
            const bool under =
                plane || (box.low[2] < mover.low[2] && box.low[0] <= mover.high[0] &&
                          mover.low[0] <= box.high[0] && box.low[1] <= mover.high[1] &&
                          mover.low[1] <= box.high[1]);
            if (under)
                clearance = std::min(clearance.value_or(1e9), std::max(0.0, mover.low[2] - top));
        }
    }
    return clearance;
}

bool World::Private::pushesApart(const World &world, Gripper gripper, int finger,
                                 const Touch &touch) const
{
    // The fingers close along the gripper frame's y axis, the left one towards -y: what is
    // between them pushes the left pad towards +y and the right one towards -y. Resting on
    // top of something (the closed fingertips lowered onto a cube) pushes both up instead.
    const double magnitude = std::hypot(touch.fworld[0], touch.fworld[1], touch.fworld[2]);
    if (magnitude < Fingertip::MinNormalForce)
        return false; // touching without force (inside the contact margin, or a dropout)
    const mjtNum *rotation = world.d->data->xmat + 9 * hands[size_t(gripper)].body;
    double across = 0.0;
    for (size_t k = 0; k < 3; ++k)
        across += rotation[3 * k + 1] * touch.fworld[k];
    return (finger == 0 ? across : -across) >= SqueezeShare * magnitude;
}

int World::objectBetween(Gripper gripper) const
{
    return hardestTouched(gripper, false);
}

int World::objectSqueezed(Gripper gripper) const
{
    return hardestTouched(gripper, true);
}

int World::hardestTouched(Gripper gripper, bool squeezed) const
{
    const Private::Tip &left = d->tips[size_t(int(gripper) * 2)];
    const Private::Tip &right = d->tips[size_t(int(gripper) * 2 + 1)];
    int actor = -1;
    double hardest = -1.0;
    for (int i = 0; i < left.touchedCount; ++i) {
        for (int j = 0; j < right.touchedCount; ++j) {
            const Private::Touch &a = left.touched[size_t(i)];
            const Private::Touch &b = right.touched[size_t(j)];
            if (a.actor >= 0 && a.actor == b.actor && a.force + b.force > hardest &&
                (!squeezed ||
                 (d->pushesApart(*this, gripper, 0, a) && d->pushesApart(*this, gripper, 1, b)))) {
                hardest = a.force + b.force;
                actor = a.actor;
            }
        }
    }
    for (size_t i = 0; i < m_objects.size() && actor >= 0; ++i) {
        if (m_objects[i].actor == actor)
            return int(i);
    }
    return -1;
}

bool World::isBetween(Gripper gripper, int object) const
{
    const int actor = m_objects[size_t(object)].actor;
    for (int finger = 0; finger < 2; ++finger) {
        const Private::Tip &tip = d->tips[size_t(int(gripper) * 2 + finger)];
        bool touched = false;
        for (int i = 0; i < tip.touchedCount; ++i)
            touched = touched || tip.touched[size_t(i)].actor == actor;
        if (!touched)
            return false;
    }
    return true;
}

bool World::Private::touches(const World &world, Gripper gripper, int object) const
{
    const int actor = world.m_objects[size_t(object)].actor;
    for (int finger = 0; finger < 2; ++finger) {
        const Tip &tip = tips[size_t(int(gripper) * 2 + finger)];
        for (int i = 0; i < tip.touchedCount; ++i) {
            if (tip.touched[size_t(i)].actor == actor)
                return true;
        }
    }
    return false;
}

Pose World::gripperPose(Gripper gripper) const
{
    const Private::Hand &h = d->hands[size_t(gripper)];
    Pose pose;
    std::copy_n(d->data->xpos + 3 * h.body, 3, pose.pos.begin());
    std::copy_n(d->data->xquat + 4 * h.body, 4, pose.quat.begin());
    return pose;
}

const ContactFrame &World::frame(Gripper gripper) const
{
    return d->hands[size_t(gripper)].frame;
}

int World::objectIndex(const QString &objectName) const
{
    for (size_t i = 0; i < m_objects.size(); ++i) {
        if (m_objects[i].name == objectName)
            return int(i);
    }
    return -1;
}

std::array<double, 3> World::objectPosition(int object) const
{
    std::array<double, 3> pos{};
    std::copy_n(d->data->xpos + 3 * m_objects[size_t(object)].body, 3, pos.begin());
    return pos;
}

Pose World::objectPose(int object) const
{
    const int body = m_objects[size_t(object)].body;
    Pose pose;
    std::copy_n(d->data->xpos + 3 * body, 3, pose.pos.begin());
    std::copy_n(d->data->xquat + 4 * body, 4, pose.quat.begin());
    return pose;
}

std::array<double, 3> World::objectVelocity(int object) const
{
    const mjModel *m = d->model.get();
    const int dof = m->jnt_dofadr[m->body_jntadr[m_objects[size_t(object)].body]];
    return {d->data->qvel[dof], d->data->qvel[dof + 1], d->data->qvel[dof + 2]};
}

void World::placeObject(int object, const std::array<double, 3> &pos)
{
    Pose upright;
    upright.pos = pos;
    setObjectPose(object, upright);
}

void World::setObjectPose(int object, const Pose &pose)
{
    const mjModel *m = d->model.get();
    const int joint = m->body_jntadr[m_objects[size_t(object)].body];
    mjtNum *qpos = d->data->qpos + m->jnt_qposadr[joint];
    mjtNum *qvel = d->data->qvel + m->jnt_dofadr[joint];
    std::copy(pose.pos.begin(), pose.pos.end(), qpos);
    std::copy(pose.quat.begin(), pose.quat.end(), qpos + 3);
    std::fill(qvel, qvel + 6, 0.0);
    d->wake(*this, size_t(object));
}

bool World::placeFixture(const QString &bodyName, const Pose &pose)
{
    const mjModel *m = d->model.get();
    const int body = id(m, mjOBJ_BODY, bodyName);
    const int mocap = body >= 0 ? m->body_mocapid[body] : -1;
    if (mocap < 0 || mocap == d->hands[0].mocap || mocap == d->hands[1].mocap)
        return false;
    std::copy(pose.pos.begin(), pose.pos.end(), d->data->mocap_pos + 3 * mocap);
    std::copy(pose.quat.begin(), pose.quat.end(), d->data->mocap_quat + 4 * mocap);
    // What is read before the next step (its sites, for the operator's eyes) follows now.
    mj_kinematics(m, d->data.get());
    return true;
}

std::optional<Pose> World::bodyPose(const QString &bodyName) const
{
    const int body = id(d->model.get(), mjOBJ_BODY, bodyName);
    if (body < 0)
        return std::nullopt;
    Pose pose;
    std::copy_n(d->data->xpos + 3 * body, 3, pose.pos.begin());
    std::copy_n(d->data->xquat + 4 * body, 4, pose.quat.begin());
    return pose;
}

std::optional<Pose> World::sitePose(const QString &siteName) const
{
    const mjModel *m = d->model.get();
    const int site = id(m, mjOBJ_SITE, siteName);
    if (site < 0)
        return std::nullopt;
    Pose pose;
    std::copy_n(d->data->site_xpos + 3 * site, 3, pose.pos.begin());
    mju_mat2Quat(pose.quat.data(), d->data->site_xmat + 9 * site);
    return pose;
}

std::array<double, 3> World::homePosition(int object) const
{
    const mjModel *m = d->model.get();
    const int joint = m->body_jntadr[m_objects[size_t(object)].body];
    const mjtNum *qpos = m->qpos0 + m->jnt_qposadr[joint];
    return {qpos[0], qpos[1], qpos[2]};
}

void World::restoreObject(int object, const std::array<double, 3> &pos)
{
    SceneObject &o = m_objects[size_t(object)];
    if (o.broken) {
        o.broken = false;
        d->overForceSteps[size_t(object)] = 0;
        mjModel *m = d->model.get();
        Private::Rest &rest = d->rests[size_t(object)];
        size_t k = 0;
        for (int geom = 0; geom < m->ngeom; ++geom) {
            if (m->geom_bodyid[geom] == o.body && k < rest.alphas.size())
                m->geom_rgba[4 * geom + 3] = rest.alphas[k++];
        }
        // A broken object is parked awake every step, so its bits are restored here.
        for (const Private::Collider &c : rest.colliders) {
            m->geom_contype[c.geom] = c.contype;
            m->geom_conaffinity[c.geom] = c.conaffinity;
        }
    }
    placeObject(object, pos);
}

int World::sceneStateSize() const
{
    const mjModel *m = d->model.get();
    return m->nq + 7 * m->nmocap;
}

std::vector<double> World::sceneState() const
{
    const mjModel *m = d->model.get();
    const mjData *data = d->data.get();
    std::vector<double> pose;
    pose.reserve(size_t(sceneStateSize()));
    pose.insert(pose.end(), data->qpos, data->qpos + m->nq);
    pose.insert(pose.end(), data->mocap_pos, data->mocap_pos + 3 * m->nmocap);
    pose.insert(pose.end(), data->mocap_quat, data->mocap_quat + 4 * m->nmocap);
    return pose;
}

bool World::setSceneState(const std::vector<double> &pose)
{
    if (int(pose.size()) != sceneStateSize())
        return false;
    const mjModel *m = d->model.get();
    mjData *data = d->data.get();
    const double *from = pose.data();
    std::copy_n(from, m->nq, data->qpos);
    std::copy_n(from + m->nq, 3 * m->nmocap, data->mocap_pos);
    std::copy_n(from + m->nq + 3 * m->nmocap, 4 * m->nmocap, data->mocap_quat);
    std::fill_n(data->qvel, m->nv, 0.0);
    mj_forward(m, data);
    return true;
}

const mjModel *World::model() const
{
    return d->model.get();
}

const mjData *World::data() const
{
    return d->data.get();
}

} // namespace semhap
