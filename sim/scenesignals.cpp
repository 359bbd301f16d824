// SPDX-License-Identifier: MIT
#include "scenesignals.h"

#include "mujocohandles.h"
#include "nametable.h"

#include <QRegularExpression>

#include <algorithm>
#include <cmath>

namespace semhap {

namespace {

/** The quantities every frame has; a signal may not take their names (docs/streams.md). */
const QStringList &builtinQuantities()
{
    static const QStringList names{
        QStringLiteral("left.f"),        QStringLiteral("right.f"),
        QStringLiteral("left.n"),        QStringLiteral("right.n"),
        QStringLiteral("friction"),      QStringLiteral("left.friction"),
        QStringLiteral("right.friction")};
    return names;
}

/** 0, 1, 2 for `x`, `y`, `z`; -1 otherwise. */
int axisOf(const QString &word)
{
    static const QStringList axes{QStringLiteral("x"), QStringLiteral("y"), QStringLiteral("z")};
    return int(axes.indexOf(word));
}

/** Column `axis` of a row-major rotation (body to world): that axis in world coordinates. */
std::array<double, 3> column(const mjtNum *xmat, int axis)
{
    return {xmat[axis], xmat[3 + axis], xmat[6 + axis]};
}

double dot(const std::array<double, 3> &a, const std::array<double, 3> &b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

double norm(const std::array<double, 3> &a)
{
    return std::sqrt(dot(a, a));
}

} // namespace

bool SceneSignals::load(const mjModel *m, const QString &file, const std::array<bool, 2> &hasHand,
                        QString *error)
{
    const QLatin1String prefix("signal:");
    for (int text = 0; text < m->ntext; ++text) {
        const QString declared = QString::fromUtf8(m->names + m->name_textadr[text]);
        if (!declared.startsWith(prefix))
            continue;
        const auto fail = [&](const QString &reason) {
            *error = QStringLiteral("%1: %2: %3").arg(file, declared, reason);
            return false;
        };
        const QString rest = declared.mid(prefix.size());
        const int colon = int(rest.indexOf(QLatin1Char(':')));
        Gripper gripper = Gripper::Right;
        if (colon < 0 || !gripperFromName(rest.left(colon), &gripper))
            return fail(QStringLiteral("expected signal:left:NAME or signal:right:NAME"));
        if (!hasHand[size_t(gripper)])
            return fail(QStringLiteral("the scene has no %1 gripper").arg(gripperName(gripper)));
        Signal signal;
        signal.name = rest.mid(colon + 1);
        if (!isPlainName(signal.name))
            return fail(QStringLiteral("a signal name is 1 to %1 of a-z, 0-9, _ and .")
                            .arg(MaxPlainNameLength));
        if (builtinQuantities().contains(signal.name))
            return fail(
                QStringLiteral("'%1' is a built-in quantity of every frame").arg(signal.name));
        std::vector<Signal> &ofHand = m_signals[size_t(gripper)];
        if (int(ofHand.size()) >= FrameSignals::Capacity)
            return fail(QStringLiteral("more than %1 signals for the %2 gripper")
                            .arg(FrameSignals::Capacity)
                            .arg(gripperName(gripper)));
        QString reason;
        const QString data = QString::fromUtf8(m->text_data + m->text_adr[text]);
        if (!parse(m, data, &signal, &reason))
            return fail(reason);
        signal.id = signalNames().intern(signal.name);
        if (signal.id < 0)
            return fail(QStringLiteral("the table of signal names is full"));
        ofHand.push_back(signal);
    }
    return true;
}

bool SceneSignals::parse(const mjModel *m, const QString &data, Signal *signal, QString *reason)
{
    static const QRegularExpression space(QStringLiteral("\\s+"));
    const QStringList words = data.split(space, Qt::SkipEmptyParts);
    const QString kind = words.value(0);
    const auto place = [&](const QString &name, Place *out) {
        const QByteArray utf8 = name.toUtf8();
        out->site = true;
        out->id = mj_name2id(m, mjOBJ_SITE, utf8.constData());
        if (out->id < 0) {
            out->site = false;
            out->id = mj_name2id(m, mjOBJ_BODY, utf8.constData());
        }
        if (out->id < 0)
            *reason = QStringLiteral("no site or body '%1'").arg(name);
        return out->id >= 0;
    };
    const auto axis = [&](const QString &word, int *out) {
        *out = axisOf(word);
        if (*out < 0)
            *reason = QStringLiteral("axis '%1' is not x, y or z").arg(word);
        return *out >= 0;
    };
    const auto arguments = [&](int count, const char *usage) {
        if (words.size() != count + 1)
            *reason = QStringLiteral("expected '%1'").arg(QLatin1String(usage));
        return words.size() == count + 1;
    };
    if (kind == QLatin1String("sensor")) {
        if (words.size() != 2 && words.size() != 3) {
            *reason = QStringLiteral("expected 'sensor SENSOR [x|y|z|INDEX|norm]'");
            return false;
        }
        signal->kind = Kind::Sensor;
        signal->sensor = mj_name2id(m, mjOBJ_SENSOR, words[1].toUtf8().constData());
        if (signal->sensor < 0) {
            *reason = QStringLiteral("no sensor '%1'").arg(words[1]);
            return false;
        }
        const int dim = m->sensor_dim[signal->sensor];
        // One value is the value; a vector's default is its magnitude.
        signal->component = dim == 1 ? 0 : -1;
        if (words.size() == 3 && words[2] != QLatin1String("norm")) {
            bool number = false;
            const int index = words[2].toInt(&number);
            signal->component = number ? index : axisOf(words[2]);
            if (signal->component < 0 || signal->component >= dim) {
                *reason = QStringLiteral("sensor '%1' has %2 values: no component '%3'")
                              .arg(words[1])
                              .arg(dim)
                              .arg(words[2]);
                return false;
            }
        }
        return true;
    }
    if (kind == QLatin1String("along") || kind == QLatin1String("across")) {
        signal->kind = kind == QLatin1String("along") ? Kind::Along : Kind::Across;
        return arguments(3, "along|across A B x|y|z") && place(words[1], &signal->a) &&
               place(words[2], &signal->b) && axis(words[3], &signal->axisA);
    }
    if (kind == QLatin1String("distance") || kind == QLatin1String("speed")) {
        signal->kind = kind == QLatin1String("distance") ? Kind::Distance : Kind::Speed;
        return arguments(2, "distance|speed A B") && place(words[1], &signal->a) &&
               place(words[2], &signal->b);
    }
    if (kind == QLatin1String("angle")) {
        signal->kind = Kind::Angle;
        return arguments(4, "angle A x|y|z B x|y|z") && place(words[1], &signal->a) &&
               axis(words[2], &signal->axisA) && place(words[3], &signal->b) &&
               axis(words[4], &signal->axisB);
    }
    *reason = QStringLiteral("unknown kind '%1' (kinds: sensor, along, across, distance, angle, "
                             "speed)")
                  .arg(kind);
    return false;
}

QStringList SceneSignals::names(Gripper gripper) const
{
    QStringList names;
    for (const Signal &signal : m_signals[size_t(gripper)])
        names.append(signal.name);
    return names;
}

void SceneSignals::write(const mjModel *m, const mjData *d, Gripper gripper,
                         ContactFrame *frame) const
{
    for (const Signal &signal : m_signals[size_t(gripper)])
        frame->signalValues.set(signal.id, value(m, d, signal));
}

double SceneSignals::value(const mjModel *m, const mjData *d, const Signal &signal)
{
    if (signal.kind == Kind::Sensor) {
        const mjtNum *values = d->sensordata + m->sensor_adr[signal.sensor];
        if (signal.component >= 0)
            return values[signal.component];
        double sum = 0.0;
        for (int i = 0; i < m->sensor_dim[signal.sensor]; ++i)
            sum += values[i] * values[i];
        return std::sqrt(sum);
    }
    const auto position = [&](const Place &p) {
        const mjtNum *x = (p.site ? d->site_xpos : d->xpos) + 3 * p.id;
        return std::array<double, 3>{x[0], x[1], x[2]};
    };
    const auto rotation = [&](const Place &p) {
        return (p.site ? d->site_xmat : d->xmat) + 9 * p.id;
    };
    const std::array<double, 3> pa = position(signal.a);
    const std::array<double, 3> pb = position(signal.b);
    const std::array<double, 3> offset{pb[0] - pa[0], pb[1] - pa[1], pb[2] - pa[2]};
    switch (signal.kind) {
    case Kind::Along:
        return dot(offset, column(rotation(signal.a), signal.axisA));
    case Kind::Across: {
        const std::array<double, 3> axis = column(rotation(signal.a), signal.axisA);
        const double along = dot(offset, axis);
        return norm({offset[0] - along * axis[0], offset[1] - along * axis[1],
                     offset[2] - along * axis[2]});
    }
    case Kind::Distance:
        return norm(offset);
    case Kind::Angle: {
        const double c = dot(column(rotation(signal.a), signal.axisA),
                             column(rotation(signal.b), signal.axisB));
        return std::acos(std::clamp(c, -1.0, 1.0));
    }
    case Kind::Speed: {
        // Linear velocities at A's and B's origins, in world coordinates.
        mjtNum va[6];
        mjtNum vb[6];
        mj_objectVelocity(m, d, signal.a.site ? mjOBJ_SITE : mjOBJ_BODY, signal.a.id, va, 0);
        mj_objectVelocity(m, d, signal.b.site ? mjOBJ_SITE : mjOBJ_BODY, signal.b.id, vb, 0);
        return norm({vb[3] - va[3], vb[4] - va[4], vb[5] - va[5]});
    }
    case Kind::Sensor:
        break;
    }
    return 0.0;
}

} // namespace semhap
