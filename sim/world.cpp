// SPDX-License-Identifier: MIT
#include "world.h"

#include "gripperadapter.h"
#include "gripperlibrary.h"
#include "scenelibrary.h"
#include "worldprivate.h"

#include <QByteArray>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace semhap {

namespace {

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
