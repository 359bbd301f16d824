// SPDX-License-Identifier: MIT
// A design sweep scaled out (tests/bench/README.md, docs/cluster.md): the wall time of one
// `semhap compare` grid on one core, on two, and as a two-task job array (a real one-node
// Slurm cluster when this runs as root, else two processes given the variables Slurm gives
// its tasks), with the speed-ups; then what recording the grid's runs as sessions costs: MB
// per simulated minute and the share of a core it takes at real time.
// bench_cluster [SEEDS] [SECONDS] (default 30 seeds of 120 s, routers none, C1 and C3).
#include "compareruns.h"
#include "slurmcluster.h"

#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QTemporaryDir>
#include <QThread>

#include <sys/resource.h>

#include <algorithm>
#include <cstdio>
#include <vector>

namespace {

const QString Semhap = QStringLiteral(SEMHAP_CLI_BINARY);

/** The CPU seconds (user and system) of every child this process has waited for. */
double childrenCpuSeconds()
{
    rusage usage{};
    getrusage(RUSAGE_CHILDREN, &usage);
    return double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
           double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec) / 1e6;
}

/** Runs semhap with `args` (and `environment`) to its end; false with its errors if it failed. */
bool semhap(const QStringList &args,
            const QProcessEnvironment &environment = QProcessEnvironment::systemEnvironment())
{
    QProcess process;
    process.setProcessEnvironment(environment);
    process.setStandardOutputFile(QProcess::nullDevice());
    process.start(Semhap, args);
    if (process.waitForFinished(-1) && process.exitStatus() == QProcess::NormalExit &&
        process.exitCode() == 0)
        return true;
    std::fprintf(stderr, "semhap %s: %s\n", qPrintable(args.join(QLatin1Char(' '))),
                 process.readAllStandardError().constData());
    return false;
}

/** A compare CSV's runs, as compareRuns() reads them. */
QStringList runs(const QString &path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? compareRuns(file.readAll()) : QStringList();
}

/** The two-task array without Slurm: two processes with the variables Slurm gives task 1 and 2. */
bool arrayByHand(const QStringList &grid, const QString &results)
{
    std::vector<std::unique_ptr<QProcess>> tasks;
    for (int task = 1; task <= 2; ++task) {
        QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
        const int values[] = {task, 1, 2, 1, 2};
        const char *const names[] = {"SLURM_ARRAY_TASK_ID", "SLURM_ARRAY_TASK_MIN",
                                     "SLURM_ARRAY_TASK_MAX", "SLURM_ARRAY_TASK_STEP",
                                     "SLURM_ARRAY_TASK_COUNT"};
        for (int i = 0; i < 5; ++i)
            environment.insert(QLatin1String(names[i]), QString::number(values[i]));
        tasks.push_back(std::make_unique<QProcess>());
        tasks.back()->setProcessEnvironment(environment);
        tasks.back()->setStandardOutputFile(QProcess::nullDevice());
        tasks.back()->start(
            Semhap, QStringList{"compare"} + grid +
                        QStringList{"--jobs", "1", "--shard", "auto", "--csv",
                                    QStringLiteral("%1/part-%2.csv").arg(results).arg(task)});
    }
    bool ok = true;
    for (auto &task : tasks)
        ok = task->waitForFinished(-1) && task->exitCode() == 0 && ok;
    return ok;
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    const QStringList args = app.arguments();
    const int seeds = args.size() > 1 ? args[1].toInt() : 30;
    const double seconds = args.size() > 2 ? args[2].toDouble() : 120.0;
    if (seeds < 1 || seconds <= 0) {
        std::fprintf(stderr, "usage: bench_cluster [SEEDS] [SECONDS]\n");
        return 2;
    }
    QTemporaryDir dir;
    const auto path = [&](const QString &name) { return dir.filePath(name); };
    const QStringList grid{"--scene",    "bimanual_sorting",
                           "--routers",  "none,C1,C3",
                           "--operator", "reactive",
                           "--seeds",    QString::number(seeds),
                           "--duration", QString::number(seconds)};
    const double simulated = 3.0 * seeds * seconds;
    std::printf("bench_cluster: bimanual_sorting, 3 routers x %d seeds x %g s (%.0f simulated "
                "s), reactive operator, %d cores\n",
                seeds, seconds, simulated, QThread::idealThreadCount());
    std::fflush(stdout);

    QElapsedTimer wall;
    double oneCore = 0;
    for (int jobs : {1, 2}) {
        wall.start();
        if (!semhap(QStringList{"compare"} + grid +
                    QStringList{"--jobs", QString::number(jobs), "--csv",
                                path(QStringLiteral("jobs%1.csv").arg(jobs))}))
            return 1;
        const double elapsed = double(wall.elapsed()) / 1000.0;
        if (jobs == 1)
            oneCore = elapsed;
        std::printf("  %s: %.1f s wall (%.1fx real time), speed-up %.2f\n",
                    jobs == 1 ? "one core (--jobs 1)" : "two cores (--jobs 2)", elapsed,
                    simulated / elapsed, oneCore / elapsed);
        std::fflush(stdout);
    }

    // The two-task array: submission to the last task's end, then the merge.
    const QString results = path(QStringLiteral("results"));
    QDir().mkpath(results);
    const QString why = SlurmCluster::unavailable();
    SlurmCluster cluster;
    QString error;
    if (why.isEmpty() && !cluster.start(QThread::idealThreadCount(), &error)) {
        std::fprintf(stderr, "%s\n", qPrintable(error));
        return 1;
    }
    wall.start();
    if (why.isEmpty()) {
        if (!cluster.runArray(QStringLiteral("1-2"),
                              {"--cpus-per-task=1", "--export=ALL,SEMHAP=" + Semhap},
                              QStringLiteral(SEMHAP_SOURCE_DIR "/scripts/slurm/compare.sbatch"),
                              QStringList{results} + grid, dir.path(), &error)) {
            std::fprintf(stderr, "%s\n", qPrintable(error));
            return 1;
        }
    } else if (!arrayByHand(grid, results)) {
        return 1;
    }
    const double array = double(wall.elapsed()) / 1000.0;
    if (!semhap({"compare", "--merge", results + QStringLiteral("/part-1.csv"),
                 results + QStringLiteral("/part-2.csv"), "--csv",
                 path(QStringLiteral("merged.csv"))}))
        return 1;
    std::printf("  two-task array (%s): %.1f s wall from submission to the last task's end "
                "(%.1fx real time), speed-up %.2f; merged runs %s the one-core grid's\n",
                why.isEmpty() ? "a one-node Slurm cluster, 1 CPU a task"
                              : qPrintable(QStringLiteral("two processes as Slurm's tasks; no "
                                                          "cluster: ") +
                                           why),
                array, simulated / array, oneCore / array,
                runs(path(QStringLiteral("merged.csv"))) == runs(path(QStringLiteral("jobs1.csv")))
                    ? "equal"
                    : "DIFFER FROM");
    std::fflush(stdout);

    // Sessions: one run of the grid with and without recording, three times each,
    // interleaved; the least CPU of each, so that a busy moment counts against neither.
    const QStringList run{"run",
                          "--scene",
                          "bimanual_sorting",
                          "--router",
                          "C3",
                          "--operator",
                          "reactive",
                          "--seed",
                          "1",
                          "--duration",
                          QString::number(seconds)};
    double cpu[2] = {1e300, 1e300};
    qint64 bytes = 0;
    for (int repeat = 0; repeat < 3; ++repeat) {
        for (int recorded = 0; recorded < 2; ++recorded) {
            const QString session = path(QStringLiteral("session%1.db").arg(repeat));
            const double before = childrenCpuSeconds();
            if (!semhap(recorded ? run + QStringList{"--session", session} : run))
                return 1;
            cpu[recorded] = std::min(cpu[recorded], childrenCpuSeconds() - before);
            if (recorded)
                bytes = QFileInfo(session).size();
        }
    }
    std::printf("  sessions: %.2f MB per simulated minute (%.1f MB for %g s, C3, seed 1); "
                "recording takes %.2f CPU s of %.2f, %.1f %% of a core at real time\n",
                double(bytes) / 1e6 / (seconds / 60.0), double(bytes) / 1e6, seconds,
                cpu[1] - cpu[0], cpu[1], 100.0 * (cpu[1] - cpu[0]) / seconds);
    return 0;
}
