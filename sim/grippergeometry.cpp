// SPDX-License-Identifier: MIT
#include "grippergeometry.h"

#include "mujocohandles.h"

#include <algorithm>
#include <cmath>

namespace semhap {

namespace {

// Samples of the sweep from open to closed, and the most steps a linkage gets to settle at
// each (it stops earlier once the pads move less than SettledMotion in a step).
constexpr int Samples = 41;
constexpr int MaxSettleSteps = 200;
constexpr double SettledMotion = 1e-8; // m
// Less pad travel than this over the joint's range is a finger that does not close.
constexpr double LeastTravel = 1e-3; // m
// Pad geoms whose faces lie this close to the innermost one touch a flat object together.
constexpr double FacePlane = 1e-3; // m

using Vec = std::array<double, 3>;

double dot(const Vec &a, const Vec &b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

Vec normalized(Vec v)
{
    const double n = std::sqrt(dot(v, v));
    for (double &x : v)
        x /= n > 0 ? n : 1.0;
    return v;
}

/** Half the extent of geom `g` along world direction `u` (its support), from its centre. */
double halfExtent(const mjModel *m, const mjData *d, int g, const Vec &u)
{
    const double *R = d->geom_xmat + 9 * g;
    const double *size = m->geom_size + 3 * g;
    // u in the geom's frame.
    const Vec l{R[0] * u[0] + R[3] * u[1] + R[6] * u[2], R[1] * u[0] + R[4] * u[1] + R[7] * u[2],
                R[2] * u[0] + R[5] * u[1] + R[8] * u[2]};
    switch (m->geom_type[g]) {
    case mjGEOM_SPHERE:
        return size[0];
    case mjGEOM_CAPSULE:
        return size[0] + std::abs(l[2]) * size[1];
    case mjGEOM_CYLINDER:
        return std::abs(l[2]) * size[1] + std::sqrt(std::max(0.0, 1 - l[2] * l[2])) * size[0];
    case mjGEOM_ELLIPSOID:
        return std::sqrt(l[0] * l[0] * size[0] * size[0] + l[1] * l[1] * size[1] * size[1] +
                         l[2] * l[2] * size[2] * size[2]);
    case mjGEOM_BOX:
        return std::abs(l[0]) * size[0] + std::abs(l[1]) * size[1] + std::abs(l[2]) * size[2];
    case mjGEOM_MESH: {
        const int mesh = m->geom_dataid[g];
        double most = 0.0;
        for (int v = 0; v < m->mesh_vertnum[mesh]; ++v) {
            const float *p = m->mesh_vert + 3 * (m->mesh_vertadr[mesh] + v);
            most = std::max(most, p[0] * l[0] + p[1] * l[1] + p[2] * l[2]);
        }
        return most;
    }
    default:
        return m->geom_rbound[g];
    }
}

/** `p` (world) in the frame of body `b`. */
Vec inBody(const mjData *d, int b, const double *p)
{
    const double *R = d->xmat + 9 * b;
    const double *o = d->xpos + 3 * b;
    const Vec r{p[0] - o[0], p[1] - o[1], p[2] - o[2]};
    return {R[0] * r[0] + R[3] * r[1] + R[6] * r[2], R[1] * r[0] + R[4] * r[1] + R[7] * r[2],
            R[2] * r[0] + R[5] * r[1] + R[8] * r[2]};
}

/** `u` (the body's frame) in world coordinates. */
Vec toWorld(const mjData *d, int b, const Vec &u)
{
    const double *R = d->xmat + 9 * b;
    return {R[0] * u[0] + R[1] * u[1] + R[2] * u[2], R[3] * u[0] + R[4] * u[1] + R[5] * u[2],
            R[6] * u[0] + R[7] * u[1] + R[8] * u[2]};
}

/** The mean centre of `geoms` in the wrist's frame. */
Vec centre(const mjData *d, int wrist, const std::vector<int> &geoms)
{
    Vec sum{};
    for (int g : geoms) {
        const Vec p = inBody(d, wrist, d->geom_xpos + 3 * g);
        for (int k = 0; k < 3; ++k)
            sum[size_t(k)] += p[size_t(k)] / double(geoms.size());
    }
    return sum;
}

/**
 * The farthest any of `geoms` reaches along `u` (wrist frame; `sign` -1: the least), as a
 * coordinate along `u` from the wrist.
 */
double extreme(const mjModel *m, const mjData *d, int wrist, const std::vector<int> &geoms,
               const Vec &u, double sign)
{
    const Vec w = toWorld(d, wrist, u);
    double best = -sign * 1e9;
    for (int g : geoms) {
        const double c = dot(inBody(d, wrist, d->geom_xpos + 3 * g), u);
        const double e = c + sign * halfExtent(m, d, g, w);
        best = sign > 0 ? std::max(best, e) : std::min(best, e);
    }
    return best;
}

/**
 * How many of `geoms` have their face within FacePlane of the finger's innermost face along
 * `u` (`sign` as in extreme()): the geoms a flat object pressed between the pads touches.
 */
int facing(const mjModel *m, const mjData *d, int wrist, const std::vector<int> &geoms,
           const Vec &u, double sign)
{
    const double inner = extreme(m, d, wrist, geoms, u, sign);
    const Vec w = toWorld(d, wrist, u);
    int count = 0;
    for (int g : geoms) {
        const double face =
            dot(inBody(d, wrist, d->geom_xpos + 3 * g), u) + sign * halfExtent(m, d, g, w);
        count += std::abs(face - inner) <= FacePlane ? 1 : 0;
    }
    return count;
}

} // namespace

bool GripperGeometry::measure(const mjModel_ *model, int wrist, const std::array<int, 2> &joints,
                              const std::array<std::vector<int>, 2> &pads, QString *error)
{
    // The sweep runs on a copy: without contacts and gravity, the model's own untouched.
    MjModelPtr copy(mj_copyModel(nullptr, model));
    mjModel *m = copy.get();
    m->opt.disableflags |= mjDSBL_CONTACT | mjDSBL_GRAVITY | mjDSBL_ACTUATION;
    MjDataPtr data(mj_makeData(m));
    mjData *d = data.get();
    std::array<double, 2> open{}, closed{};
    for (int f = 0; f < 2; ++f) {
        const int j = joints[size_t(f)];
        const double lo = m->jnt_range[2 * j], hi = m->jnt_range[2 * j + 1];
        if (!m->jnt_limited[j] || !(hi > lo)) {
            *error = QStringLiteral("finger joint %1 has no range to close over")
                         .arg(QString::fromUtf8(mj_id2name(m, mjOBJ_JOINT, j)));
            return false;
        }
        // Which end is open: the one whose pads are farther apart, found below.
        open[size_t(f)] = lo;
        closed[size_t(f)] = hi;
    }
    std::vector<Sample> samples;
    std::vector<std::array<Vec, 2>> centres;
    auto settle = [&](const std::array<double, 2> &q) {
        Vec last{1e9, 0, 0};
        for (int step = 0; step < MaxSettleSteps; ++step) {
            for (int f = 0; f < 2; ++f) {
                const int j = joints[size_t(f)];
                d->qpos[m->jnt_qposadr[j]] = q[size_t(f)];
                d->qvel[m->jnt_dofadr[j]] = 0;
            }
            mj_step(m, d);
            for (int f = 0; f < 2; ++f) {
                const int j = joints[size_t(f)];
                d->qpos[m->jnt_qposadr[j]] = q[size_t(f)];
            }
            mj_kinematics(m, d);
            const Vec now = centre(d, wrist, pads[0]);
            const double moved = std::abs(now[0] - last[0]) + std::abs(now[1] - last[1]) +
                                 std::abs(now[2] - last[2]);
            last = now;
            if (moved < SettledMotion)
                break;
        }
    };
    mj_resetData(m, d);
    for (int k = 0; k < Samples; ++k) {
        const double s = double(k) / (Samples - 1);
        std::array<double, 2> q{};
        for (int f = 0; f < 2; ++f)
            q[size_t(f)] = open[size_t(f)] + s * (closed[size_t(f)] - open[size_t(f)]);
        settle(q);
        Sample sample;
        sample.q = q;
        samples.push_back(sample);
        centres.push_back({centre(d, wrist, pads[0]), centre(d, wrist, pads[1])});
        if (k == 0)
            m_closing = normalized({centres[0][0][0] - centres[0][1][0],
                                    centres[0][0][1] - centres[0][1][1],
                                    centres[0][0][2] - centres[0][1][2]});
        // The inner faces along the closing axis, measured in the wrist's frame.
        const double left = extreme(m, d, wrist, pads[0], m_closing, -1);
        const double right = extreme(m, d, wrist, pads[1], m_closing, 1);
        samples.back().gap = left - right;
        samples.back().travel = {left, right};
    }
    // Sweeping from the range's low end closed the fingers, or opened them: face the sweep
    // from open to closed, and the axis from right to left at the open end.
    if (samples.back().gap > samples.front().gap) {
        std::reverse(samples.begin(), samples.end());
        std::reverse(centres.begin(), centres.end());
    }
    const std::array<Vec, 2> &o = centres.front();
    m_closing = normalized({o[0][0] - o[1][0], o[0][1] - o[1][1], o[0][2] - o[1][2]});
    if (samples.front().gap <= 0) {
        *error = QStringLiteral("the two fingers' pads overlap when open");
        return false;
    }
    Vec mid{(o[0][0] + o[1][0]) / 2, (o[0][1] + o[1][1]) / 2, (o[0][2] + o[1][2]) / 2};
    const double along = dot(mid, m_closing);
    for (int k = 0; k < 3; ++k)
        mid[size_t(k)] -= along * m_closing[size_t(k)];
    m_approach = normalized(mid);
    m_openCentre = {(o[0][0] + o[1][0]) / 2, (o[0][1] + o[1][1]) / 2, (o[0][2] + o[1][2]) / 2};
    // Redo the faces against the final axis (the first sample's may have been the closed end).
    mj_resetData(m, d);
    std::vector<int> dofs; // the gripper's hinges and slides
    for (int dof = 0; dof < m->nv; ++dof) {
        const int joint = m->dof_jntid[dof];
        int body = m->jnt_bodyid[joint];
        while (body > 0 && body != wrist)
            body = m->body_parentid[body];
        if (body == wrist &&
            (m->jnt_type[joint] == mjJNT_HINGE || m->jnt_type[joint] == mjJNT_SLIDE))
            dofs.push_back(dof);
    }
    std::vector<std::vector<double>> positions(samples.size(), std::vector<double>(dofs.size()));
    std::vector<std::vector<double>> springs = positions;
    for (size_t k = 0; k < samples.size(); ++k) {
        Sample &sample = samples[k];
        settle(sample.q);
        const double left = extreme(m, d, wrist, pads[0], m_closing, -1);
        const double right = extreme(m, d, wrist, pads[1], m_closing, 1);
        sample.gap = left - right;
        sample.travel = {left, right};
        const Vec c = centre(d, wrist, [&] {
            std::vector<int> all = pads[0];
            all.insert(all.end(), pads[1].begin(), pads[1].end());
            return all;
        }());
        sample.drop = dot(c, m_approach);
        sample.reach = std::max(extreme(m, d, wrist, pads[0], m_approach, 1),
                                extreme(m, d, wrist, pads[1], m_approach, 1));
        if (k == 0)
            m_fullContacts = facing(m, d, wrist, pads[0], m_closing, -1) +
                             facing(m, d, wrist, pads[1], m_closing, 1);
        // The springs of the gripper's joints at rest here, and where its joints are.
        mju_zero(d->qvel, m->nv);
        mj_passive(m, d);
        for (size_t i = 0; i < dofs.size(); ++i) {
            positions[k][i] = d->qpos[m->jnt_qposadr[m->dof_jntid[dofs[i]]]];
            springs[k][i] = d->qfrc_passive[dofs[i]];
        }
    }
    // What the springs do as the fingers close (their work per sample), shared by the two
    // fingers' motors: a linkage's spring (the 2F-85's) pushes the pads with no command.
    for (size_t k = 0; k < samples.size(); ++k) {
        const size_t a = k == 0 ? 0 : k - 1, b = k == 0 ? 1 : k;
        double work = 0.0;
        for (size_t i = 0; i < dofs.size(); ++i)
            work += 0.5 * (springs[a][i] + springs[b][i]) * (positions[b][i] - positions[a][i]);
        for (int f = 0; f < 2; ++f) {
            const double dq = samples[b].q[size_t(f)] - samples[a].q[size_t(f)];
            samples[k].spring[size_t(f)] = dq != 0 ? work / (2 * dq) : 0.0;
        }
    }
    const std::array<double, 2> first = samples.front().travel;
    for (Sample &sample : samples) {
        sample.travel = {first[0] - sample.travel[0], sample.travel[1] - first[1]};
    }
    for (int f = 0; f < 2; ++f) {
        if (samples.back().travel[size_t(f)] < LeastTravel) {
            *error = QStringLiteral("finger joint %1 moves its pads %2 mm towards the other "
                                    "over its range: it does not close the gripper")
                         .arg(QString::fromUtf8(mj_id2name(m, mjOBJ_JOINT, joints[size_t(f)])))
                         .arg(samples.back().travel[size_t(f)] * 1000, 0, 'f', 1);
            return false;
        }
    }
    m_samples = std::move(samples);
    return true;
}

size_t GripperGeometry::segment(int finger, double q, double *fraction) const
{
    const size_t f = size_t(finger);
    const bool rising = m_samples.back().q[f] > m_samples.front().q[f];
    size_t k = 0;
    while (k + 2 < m_samples.size() &&
           (rising ? q > m_samples[k + 1].q[f] : q < m_samples[k + 1].q[f]))
        ++k;
    const double q0 = m_samples[k].q[f], q1 = m_samples[k + 1].q[f];
    *fraction = (q - q0) / (q1 - q0);
    return k;
}

size_t GripperGeometry::gapSegment(double gap, double *fraction) const
{
    size_t k = 0;
    while (k + 2 < m_samples.size() && gap < m_samples[k + 1].gap)
        ++k;
    const double g0 = m_samples[k].gap, g1 = m_samples[k + 1].gap;
    *fraction = std::clamp(g1 != g0 ? (gap - g0) / (g1 - g0) : 0.0, 0.0, 1.0);
    return k;
}

double GripperGeometry::atGap(double gap, double Sample::*field) const
{
    if (m_samples.empty())
        return 0.0;
    double s = 0;
    const size_t k = gapSegment(gap, &s);
    return m_samples[k].*field + s * (m_samples[k + 1].*field - m_samples[k].*field);
}

double GripperGeometry::atQ(int finger, double q, std::array<double, 2> Sample::*field) const
{
    double s = 0;
    const size_t k = segment(finger, q, &s);
    const double v0 = (m_samples[k].*field)[size_t(finger)];
    return v0 + s * ((m_samples[k + 1].*field)[size_t(finger)] - v0);
}

double GripperGeometry::drop(double gap) const
{
    return atGap(gap, &Sample::drop);
}

double GripperGeometry::reach(double gap) const
{
    return atGap(gap, &Sample::reach);
}

double GripperGeometry::travel(int finger, double q) const
{
    return m_samples.empty() ? q : atQ(finger, q, &Sample::travel);
}

double GripperGeometry::arm(int finger, double q) const
{
    if (m_samples.empty())
        return 1.0;
    double s = 0;
    const size_t k = segment(finger, q, &s);
    const Sample &a = m_samples[k], &b = m_samples[k + 1];
    return (b.travel[size_t(finger)] - a.travel[size_t(finger)]) /
           (b.q[size_t(finger)] - a.q[size_t(finger)]);
}

std::array<double, 2> GripperGeometry::armRange(int finger) const
{
    const size_t f = size_t(finger);
    std::array<double, 2> range{1e9, -1e9};
    if (m_samples.empty())
        return {1.0, 1.0};
    for (size_t k = 0; k + 1 < m_samples.size(); ++k) {
        const double arm = (m_samples[k + 1].travel[f] - m_samples[k].travel[f]) /
                           (m_samples[k + 1].q[f] - m_samples[k].q[f]);
        range = {std::min(range[0], arm), std::max(range[1], arm)};
    }
    return range;
}

double GripperGeometry::spring(int finger, double q) const
{
    return m_samples.empty() ? 0.0 : atQ(finger, q, &Sample::spring);
}

} // namespace semhap
