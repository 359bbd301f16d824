// SPDX-License-Identifier: MIT
#include "insertiontask.h"

#include "nametable.h"

#include <QJsonValue>

#include <algorithm>

namespace semhap {

namespace {

// A collision begins when the port pushes on a plug that is laterally off by more than the
// clearance, at the face (not yet inside), and ends once the push has gone.
constexpr double CollisionForce = 0.5; // N
constexpr double CollisionEnd = 0.1;   // N
constexpr double AtTheFace = 0.001;    // m of depth: deeper, the plug is in the opening
constexpr double CollisionQuiet = 0.2; // s
// A plug counts as picked up once held this far above where it rested (m).
constexpr double Lifted = 0.01;
// Out of both fingertips this long, a held plug was let go or dropped (s).
constexpr double LostAfter = 0.05;
// After an insertion the task lays out again once the hand has let go and risen this far
// above the port's face (m): it never moves the plug out of a hand.
constexpr double HandClear = 0.08;
const QStringList &requiredSignals()
{
    static const QStringList names{QStringLiteral("plug.lateral"), QStringLiteral("plug.angle"),
                                   QStringLiteral("plug.depth"), QStringLiteral("plug.force")};
    return names;
}

QJsonValue mean(double sum, int count)
{
    return count > 0 ? QJsonValue(sum / count) : QJsonValue();
}

} // namespace

std::unique_ptr<InsertionTask> InsertionTask::create(World &world, std::uint64_t seed,
                                                     QString *error)
{
    const QStringList declared = world.signalNames(Gripper::Right);
    for (const QString &name : requiredSignals()) {
        if (!declared.contains(name)) {
            *error = QStringLiteral("%1: the %2 task needs the right gripper's signal '%3' "
                                    "(sim/README.md, \"Signals\")")
                         .arg(world.sceneName(), QLatin1String(Name), name);
            return nullptr;
        }
    }
    const std::optional<Pose> port = world.bodyPose(QStringLiteral("port"));
    if (world.objectIndex(QStringLiteral("plug")) < 0 ||
        !world.sitePose(QStringLiteral("port.mouth")) || !port ||
        !world.placeFixture(QStringLiteral("port"), *port)) {
        *error = QStringLiteral("%1: the %2 task needs a free body 'plug', a mocap body 'port' "
                                "and a site 'port.mouth'")
                     .arg(world.sceneName(), QLatin1String(Name));
        return nullptr;
    }
    return std::unique_ptr<InsertionTask>(new InsertionTask(world, seed, port->pos));
}

InsertionTask::InsertionTask(World &world, std::uint64_t seed,
                             const std::array<double, 3> &portHome)
    : m_random(seed ^ 0x75736221ULL), m_plug(world.objectIndex(QStringLiteral("plug"))),
      m_portHome(portHome), m_plugHome(world.homePosition(m_plug)),
      m_lateral(signalNames().find(QStringLiteral("plug.lateral"))),
      m_depth(signalNames().find(QStringLiteral("plug.depth"))),
      m_force(signalNames().find(QStringLiteral("plug.force")))
{
    layOut(world);
}

void InsertionTask::layOut(World &world)
{
    Pose port;
    port.pos = {m_portHome[0] + m_random.uniform(-Scatter, Scatter),
                m_portHome[1] + m_random.uniform(-Scatter, Scatter), m_portHome[2]};
    port.quat = yawQuaternion(m_random.uniform(-MaxYaw, MaxYaw));
    Pose plug;
    plug.pos = {m_plugHome[0] + m_random.uniform(-Scatter, Scatter),
                m_plugHome[1] + m_random.uniform(-Scatter, Scatter), m_plugHome[2]};
    plug.quat = yawQuaternion(m_random.uniform(-MaxYaw, MaxYaw));
    world.setObjectPose(m_plug, plug);
    world.placeFixture(QStringLiteral("port"), port);
    m_face = world.sitePose(QStringLiteral("port.mouth"))->pos[2];
    m_pickedAt = -1.0;
    m_seated = false;
    m_droppedAt = -1.0;
    m_colliding = false;
}

double InsertionTask::signal(const World &world, int id) const
{
    const double *value = world.frame(Gripper::Right).signalValues.find(id);
    return value ? *value : 0.0;
}

void InsertionTask::observe(World &world)
{
    const double t = world.time();
    const double depth = signal(world, m_depth);
    const double force = signal(world, m_force);
    const double lateral = signal(world, m_lateral);
    m_peakForce = std::max(m_peakForce, force);

    // Held: both fingertips on the plug; let go once out of them for LostAfter.
    if (world.isBetween(Gripper::Right, m_plug)) {
        m_held = true;
        m_lostAt = -1.0;
    } else if (m_held) {
        if (m_lostAt < 0)
            m_lostAt = t;
        if (t - m_lostAt >= LostAfter) {
            m_held = false;
            if (m_pickedAt >= 0 && !m_seated && m_droppedAt < 0) {
                ++m_drops;
                m_droppedAt = t;
            }
        }
    }
    if (m_held && m_pickedAt < 0 && world.objectPosition(m_plug)[2] > m_plugHome[2] + Lifted) {
        m_pickedAt = t;
        ++m_pickups;
    }

    // Box on box, the contact flickers from step to step: an episode ends only once the push
    // has stayed away for CollisionQuiet, or the plug has gone in.
    if (!m_colliding && force > CollisionForce && lateral > Clearance && depth < AtTheFace) {
        m_colliding = true;
        ++m_collisions;
        m_quietSince = -1.0;
    } else if (m_colliding) {
        if (force >= CollisionEnd)
            m_quietSince = -1.0;
        else if (m_quietSince < 0)
            m_quietSince = t;
        if (depth >= AtTheFace || (m_quietSince >= 0 && t - m_quietSince >= CollisionQuiet))
            m_colliding = false;
    }

    if (!m_seated && isSeated(depth, lateral) && m_pickedAt >= 0) {
        m_seated = true;
        ++m_insertions;
        m_insertTimeSum += t - m_pickedAt;
    }
    const bool handClear = world.gripperPose(Gripper::Right).pos[2] > m_face + HandClear;
    const bool touched =
        world.frame(Gripper::Right).left.actor == world.objects()[size_t(m_plug)].actor ||
        world.frame(Gripper::Right).right.actor == world.objects()[size_t(m_plug)].actor;
    if ((m_seated && !m_held && !touched && handClear) ||
        (m_droppedAt >= 0 && !m_held && t - m_droppedAt >= DropPenalty))
        layOut(world);
}

void InsertionTask::feel(Gripper, const Feeling &, double) {}

QJsonObject InsertionTask::metrics() const
{
    return {{QStringLiteral("insertions"), m_insertions},
            {QStringLiteral("time_to_insert"), mean(m_insertTimeSum, m_insertions)},
            {QStringLiteral("collisions"), m_collisions},
            {QStringLiteral("peak_insertion_force"), m_peakForce},
            {QStringLiteral("plug_pickups"), m_pickups},
            {QStringLiteral("plugs_dropped"), m_drops}};
}

const std::vector<MetricSpec> &InsertionTask::metricSpecs()
{
    static const std::vector<MetricSpec> specs = {
        {"insertions", MetricUnit::Count, MetricBetter::Higher,
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Plugs inserted"),
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Plugs seated in the port.")},
        {"time_to_insert", MetricUnit::Seconds, MetricBetter::Lower,
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Time to insert"),
         QT_TRANSLATE_NOOP("semhap::MetricSpec",
                           "The mean time from picking a plug up to seating it.")},
        {"collisions", MetricUnit::Count, MetricBetter::Lower,
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Collisions with the port"),
         QT_TRANSLATE_NOOP("semhap::MetricSpec",
                           "Times the plug pushed on the port's face beside the opening.")},
        {"peak_insertion_force", MetricUnit::Newtons, MetricBetter::Lower,
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Peak insertion force"),
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "The highest force on the port during the run.")},
        {"plug_pickups", MetricUnit::Count, MetricBetter::Neither,
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Plug pick-ups"),
         QT_TRANSLATE_NOOP("semhap::MetricSpec",
                           "Times a plug was lifted from where it was laid out.")},
        {"plugs_dropped", MetricUnit::Count, MetricBetter::Lower,
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Plugs dropped"),
         QT_TRANSLATE_NOOP("semhap::MetricSpec",
                           "Plugs let go of after a pick-up without being seated.")},
    };
    return specs;
}

} // namespace semhap
