// SPDX-License-Identifier: MIT
#include "shard.h"

#include <QRegularExpression>
#include <QStringList>

#include <array>

namespace semhap {

namespace {

const char *const TaskId = "SLURM_ARRAY_TASK_ID";
const char *const TaskMin = "SLURM_ARRAY_TASK_MIN";
const char *const TaskMax = "SLURM_ARRAY_TASK_MAX";
const char *const TaskStep = "SLURM_ARRAY_TASK_STEP";
const char *const TaskCount = "SLURM_ARRAY_TASK_COUNT";

/** A variable's whole number (≥ 0); none when it is unset or not one. */
std::optional<long long> whole(const QProcessEnvironment &environment, const char *name)
{
    bool ok = false;
    const long long value = environment.value(QLatin1String(name)).trimmed().toLongLong(&ok);
    if (!ok || value < 0)
        return std::nullopt;
    return value;
}

} // namespace

QString Shard::text() const
{
    return QStringLiteral("%1/%2").arg(index).arg(count);
}

std::optional<Shard> Shard::parse(const QString &text, const QProcessEnvironment &environment,
                                  QString *error)
{
    if (text != QLatin1String("auto")) {
        const QRegularExpressionMatch m =
            QRegularExpression(QStringLiteral("^(\\d{1,9})/(\\d{1,9})$")).match(text);
        Shard shard{m.captured(1).toInt(), m.captured(2).toInt()};
        if (!m.hasMatch() || shard.count < 1 || shard.index < 1 || shard.index > shard.count) {
            *error = QStringLiteral("--shard expects I/N with 1 <= I <= N, e.g. 3/10, or auto "
                                    "in a Slurm job array");
            return std::nullopt;
        }
        return shard;
    }
    const QStringList names{QLatin1String(TaskId), QLatin1String(TaskMin), QLatin1String(TaskMax),
                            QLatin1String(TaskStep), QLatin1String(TaskCount)};
    if (!environment.contains(QLatin1String(TaskId))) {
        *error = QStringLiteral("--shard auto takes the slice from a Slurm job array (sbatch "
                                "--array), whose %1 are not set here; outside one, give I/N")
                     .arg(names.join(QStringLiteral(", ")));
        return std::nullopt;
    }
    const std::optional<long long> id = whole(environment, TaskId);
    const std::optional<long long> min = whole(environment, TaskMin);
    const std::optional<long long> max = whole(environment, TaskMax);
    const std::optional<long long> step = whole(environment, TaskStep);
    const std::optional<long long> count = whole(environment, TaskCount);
    for (int i = 0; i < names.size(); ++i) {
        const std::optional<long long> value = std::array{id, min, max, step, count}[size_t(i)];
        if (!value) {
            *error = QStringLiteral("--shard auto: %1 is '%2', not a whole number")
                         .arg(names[i], environment.value(names[i]));
            return std::nullopt;
        }
    }
    // Slice I of N is the task's place among the array's indices; an array with gaps
    // (--array=1,2,5) has indices no step reaches, so the slices would not cover the grid.
    if (*step < 1 || *count < 1 || *max < *min || *id < *min || *id > *max) {
        *error = QStringLiteral("--shard auto: the array's variables do not describe one "
                                "(%1=%2, %3=%4, %5=%6, %7=%8, %9=%10)")
                     .arg(names[0])
                     .arg(*id)
                     .arg(names[1])
                     .arg(*min)
                     .arg(names[2])
                     .arg(*max)
                     .arg(names[3])
                     .arg(*step)
                     .arg(names[4])
                     .arg(*count);
        return std::nullopt;
    }
    if ((*max - *min) % *step != 0 || (*max - *min) / *step + 1 != *count ||
        (*id - *min) % *step != 0) {
        *error = QStringLiteral("--shard auto: the job array has gaps (%1 tasks from %2 to %3 "
                                "by steps of %4), so its tasks are not the slices of one grid; "
                                "submit a range without gaps (--array=1-N) or give --shard I/N")
                     .arg(*count)
                     .arg(*min)
                     .arg(*max)
                     .arg(*step);
        return std::nullopt;
    }
    if (*count > 1000000000LL) {
        *error = QStringLiteral("--shard auto: %1 tasks are more than semhap splits a grid into")
                     .arg(*count);
        return std::nullopt;
    }
    return Shard{int((*id - *min) / *step + 1), int(*count)};
}

} // namespace semhap
