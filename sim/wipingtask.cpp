// SPDX-License-Identifier: MIT
#include "wipingtask.h"

#include "perception.h"

#include <mujoco/mujoco.h>

#include <cmath>

namespace semhap {

namespace {

// A plate breaks once pressed above its limit for this many steps in a row, as World's
// fracture rule does for fingertips: a one-step contact spike is physics noise.
constexpr int BreakSteps = 3;
// The task's draws are its own: the operator's generator starts from the same seed.
constexpr std::uint64_t SeedMix = 0xD1B54A32D192ED03ULL;
// A broken plate is replaced once the sponge is this far above where the plate goes (m).
constexpr double SpongeClear = 0.01;

const QString &stainPrefix()
{
    static const QString prefix = QStringLiteral("plate.stain.");
    return prefix;
}

/** `p` (world) in the frame of a MuJoCo position and row-major rotation matrix. */
std::array<double, 3> inFrame(const mjtNum *pos, const mjtNum *mat, const mjtNum *p)
{
    const mjtNum d[3] = {p[0] - pos[0], p[1] - pos[1], p[2] - pos[2]};
    std::array<double, 3> out{};
    for (int i = 0; i < 3; ++i)
        out[size_t(i)] = mat[i] * d[0] + mat[3 + i] * d[1] + mat[6 + i] * d[2];
    return out;
}

} // namespace

WipingTask::WipingTask(const World &world, std::uint64_t seed)
    : m_plate(world.objectIndex(QStringLiteral("plate"))),
      m_sponge(world.geomIndex(QStringLiteral("right.sponge")))
{
    Random random(seed ^ SeedMix);
    m_stiffenAt = random.uniform(StiffenEarliest, StiffenLatest);
    if (m_plate < 0 || m_sponge < 0)
        return;
    m_breakForce = world.objects()[size_t(m_plate)].fragileForce;
    const mjModel *m = world.model();
    for (int geom = 0; geom < m->ngeom; ++geom) {
        const char *name = mj_id2name(m, mjOBJ_GEOM, geom);
        if (!name || !QString::fromUtf8(name).startsWith(stainPrefix()))
            continue;
        Cell cell;
        cell.geom = geom;
        cell.center = {m->geom_pos[3 * geom], m->geom_pos[3 * geom + 1]};
        m_stainAlpha = m->geom_rgba[4 * geom + 3];
        m_cells.push_back(cell);
    }
}

std::unique_ptr<WipingTask> WipingTask::create(const World &world, std::uint64_t seed,
                                               QString *error)
{
    std::unique_ptr<WipingTask> task(new WipingTask(world, seed));
    if (task->m_plate < 0 || task->m_sponge < 0 || task->m_cells.empty()) {
        *error = QStringLiteral("%1: the %2 task needs a free body 'plate' with stains "
                                "'plate.stain.*' and a geom 'right.sponge' (sim/README.md)")
                     .arg(world.sceneName(), QLatin1String(Name));
        return nullptr;
    }
    return task;
}

double WipingTask::press(const World &world) const
{
    const mjModel *m = world.model();
    const mjData *d = world.data();
    const int plateBody = world.objects()[size_t(m_plate)].body;
    const int spongeBody = m->geom_bodyid[m_sponge];
    double force = 0.0;
    for (int c = 0; c < d->ncon; ++c) {
        const mjContact &contact = d->contact[c];
        const int body1 = m->geom_bodyid[contact.geom1];
        const int body2 = m->geom_bodyid[contact.geom2];
        const bool between = (body1 == spongeBody && body2 == plateBody) ||
                             (body2 == spongeBody && body1 == plateBody);
        if (!between || contact.efc_address < 0)
            continue;
        mjtNum local[6];
        mj_contactForce(m, d, c, local);
        force += local[0]; // the normal force, along the contact frame's first axis
    }
    return force;
}

std::array<double, 2> WipingTask::spongeOnPlate(const World &world) const
{
    const mjData *d = world.data();
    const int body = world.objects()[size_t(m_plate)].body;
    const auto p = inFrame(d->xpos + 3 * body, d->xmat + 9 * body, d->geom_xpos + 3 * m_sponge);
    return {p[0], p[1]};
}

void WipingTask::observe(World &world)
{
    const double t = world.time();
    if (!m_stiffened && t >= m_stiffenAt) {
        // Once: a scene without the actuator simply keeps its sponge as it is.
        world.setControl(QStringLiteral("right.sponge.stiffen"), 1.0);
        m_stiffened = true;
    }
    for (const Fracture &fracture : world.fractures()) {
        if (fracture.object == m_plate) {
            ++m_broken;
            m_brokenAt = t;
        }
    }
    if (m_brokenAt >= 0) {
        replaceBroken(world);
        m_press = 0.0;
        m_hasLast = false;
        return;
    }
    const double dt = world.timestep();
    m_press = press(world);
    m_peak = std::max(m_peak, m_press);
    if (m_press > SafeForce)
        m_aboveSafe += dt;
    if (m_press > 0) {
        m_pressSum += m_press;
        ++m_pressSteps;
    }
    m_overSteps = m_breakForce > 0 && m_press > m_breakForce ? m_overSteps + 1 : 0;
    if (m_overSteps >= BreakSteps) {
        world.breakObject(m_plate, m_press);
        ++m_broken;
        m_brokenAt = t;
        m_overSteps = 0;
        m_hasLast = false;
        return;
    }
    wipe(world, m_press);
}

void WipingTask::wipe(World &world, double force)
{
    // A cell is wiped by the distance the sponge slides over the plate while the cell's centre
    // is under the sponge and the sponge presses with at least CleanForce.
    const std::array<double, 2> now = spongeOnPlate(world);
    const double moved = m_hasLast ? std::hypot(now[0] - m_last[0], now[1] - m_last[1]) : 0.0;
    m_last = now;
    m_hasLast = true;
    if (force < CleanForce || moved <= 0)
        return;
    const mjModel *m = world.model();
    const mjData *d = world.data();
    const int body = world.objects()[size_t(m_plate)].body;
    const mjtNum *half = m->geom_size + 3 * m_sponge;
    int clean = 0;
    for (Cell &cell : m_cells) {
        const mjtNum local[3] = {cell.center[0], cell.center[1], 0.0};
        mjtNum p[3];
        mju_rotVecMat(p, local, d->xmat + 9 * body);
        mju_addTo3(p, d->xpos + 3 * body);
        const auto s = inFrame(d->geom_xpos + 3 * m_sponge, d->geom_xmat + 9 * m_sponge, p);
        const bool under = std::abs(s[0]) <= half[0] && std::abs(s[1]) <= half[1];
        if (under && cell.wiped < CleanDistance) {
            cell.wiped += moved;
            if (cell.wiped >= CleanDistance)
                ++m_cleaned;
            // The stain fades as it is wiped.
            world.setGeomAlpha(cell.geom,
                               m_stainAlpha * std::max(0.0, 1.0 - cell.wiped / CleanDistance));
        }
        clean += cell.wiped >= CleanDistance ? 1 : 0;
    }
    if (clean == int(m_cells.size()) && !m_cells.empty()) {
        ++m_platesCleaned;
        if (m_cleanAt < 0)
            m_cleanAt = world.time();
        restain(world);
    }
}

void WipingTask::restain(World &world)
{
    for (Cell &cell : m_cells) {
        cell.wiped = 0.0;
        world.setGeomAlpha(cell.geom, m_stainAlpha);
    }
}

void WipingTask::replaceBroken(World &world)
{
    // The next plate goes where the first stood once the penalty is over, the left hand has
    // let go and the sponge is clear of it.
    const double t = world.time();
    if (t - m_brokenAt < ReplacePenalty || world.grip(Gripper::Left) > 0)
        return;
    const auto home = world.homePosition(m_plate);
    const SceneObject &plate = world.objects()[size_t(m_plate)];
    const mjModel *m = world.model();
    const double spongeBottom =
        world.data()->geom_xpos[3 * m_sponge + 2] - m->geom_size[3 * m_sponge + 2];
    if (spongeBottom < home[2] + plate.upper[2] + SpongeClear)
        return;
    world.restoreObject(m_plate, home);
    restain(world);
    m_brokenAt = -1.0;
}

void WipingTask::feel(Gripper hand, const Feeling &feeling, double t)
{
    // Warnings felt on the wiping hand: a pulsed warning is one while its pulses keep coming.
    if (hand != Gripper::Right ||
        std::max(feeling.warning, feeling.shownWarning) < Perception::Noticeable)
        return;
    if (t - m_lastWarned > Perception::PulseGap)
        ++m_warnings;
    m_lastWarned = t;
}

QJsonObject WipingTask::metrics() const
{
    const double cells = double(std::max<size_t>(1, m_cells.size()));
    return {
        {QStringLiteral("area_cleaned"), m_cleaned / cells},
        {QStringLiteral("plates_cleaned"), m_platesCleaned},
        {QStringLiteral("time_to_clean"),
         m_cleanAt >= 0 ? QJsonValue(m_cleanAt) : QJsonValue(QJsonValue::Null)},
        {QStringLiteral("peak_force"), m_peak},
        {QStringLiteral("time_above_safe_force"), m_aboveSafe},
        {QStringLiteral("plates_broken"), m_broken},
        {QStringLiteral("average_press_force"), m_pressSteps > 0
                                                    ? QJsonValue(m_pressSum / double(m_pressSteps))
                                                    : QJsonValue(QJsonValue::Null)},
        {QStringLiteral("warnings_felt"), m_warnings},
        {QStringLiteral("stiffened_at"), m_stiffenAt},
    };
}

const std::vector<MetricSpec> &WipingTask::metricSpecs()
{
    static const std::vector<MetricSpec> specs = {
        {"area_cleaned", MetricUnit::Ratio, MetricBetter::Higher,
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Area cleaned (plates)"),
         QT_TRANSLATE_NOOP("semhap::MetricSpec",
                           "Cells cleaned, in plates' worth: above 1 when more than a plate was "
                           "cleaned.")},
        {"time_to_clean", MetricUnit::Seconds, MetricBetter::Lower,
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Time to clean"),
         QT_TRANSLATE_NOOP("semhap::MetricSpec",
                           "When every cell of the first plate was first clean.")},
        {"plates_cleaned", MetricUnit::Count, MetricBetter::Higher,
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Plates cleaned"),
         QT_TRANSLATE_NOOP("semhap::MetricSpec",
                           "Times every cell of a plate was clean at once.")},
        {"plates_broken", MetricUnit::Count, MetricBetter::Lower,
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Plates broken"),
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Plates broken by pressing above 40 N.")},
        {"peak_force", MetricUnit::Newtons, MetricBetter::Lower,
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Peak force"),
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "The highest press of the sponge on the plate.")},
        {"time_above_safe_force", MetricUnit::Seconds, MetricBetter::Lower,
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Time above the safe force"),
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "The time the press was above the safe 25 N.")},
        {"average_press_force", MetricUnit::Newtons, MetricBetter::Neither,
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Average press force"),
         QT_TRANSLATE_NOOP("semhap::MetricSpec",
                           "The mean press while the sponge pressed on the plate.")},
        {"warnings_felt", MetricUnit::Count, MetricBetter::Neither,
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Warnings felt"),
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Warnings felt on the wiping hand.")},
        {"stiffened_at", MetricUnit::Seconds, MetricBetter::Neither,
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Sponge stiffened at"),
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "When the sponge's holder stiffened.")},
    };
    return specs;
}

} // namespace semhap
