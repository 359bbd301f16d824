// SPDX-License-Identifier: MIT
// Warnings in time under stress: the share of failures whose warning was felt at least the
// reaction time before them, per router, on the two stress scripts — `fast_squeeze` (the
// operator closes fast and hard on fragile cubes: breaks) on box_and_block and
// `drifting_hold` (the holding hand relaxes: container drops) on bimanual_sorting.
// Target: C3p >= 95 % on both (reported beside the paper's C3).
// Then the holding hand's warnings judged as alarms (docs/metrics.md), bimanual_sorting with
// the reactive operator for 120 s: drops warned by onset (pooled over the seeds' drops),
// precision and duty (means over seeds). Targets for C3p: >= 90 %, >= 50 %, <= 15 %.
#include "simrun.h"
#include "task.h"

#include <QCoreApplication>
#include <QStringList>

#include <cstdio>

using namespace semhap;

namespace {

struct Totals
{
    int failures = 0;
    double warned = 0;
    double inTime = 0;
    double leadSum = 0;
    int leadRuns = 0;
};

/** Adds one run's failures and the shares weighted by them. */
void add(Totals &totals, const QJsonObject &metrics, const char *count, const char *warned,
         const char *inTime, const char *lead)
{
    const int n = metrics.value(QLatin1String(count)).toInt();
    totals.failures += n;
    totals.warned += n * metrics.value(QLatin1String(warned)).toDouble();
    totals.inTime += n * metrics.value(QLatin1String(inTime)).toDouble();
    if (metrics.value(QLatin1String(lead)).isDouble()) {
        totals.leadSum += metrics.value(QLatin1String(lead)).toDouble();
        ++totals.leadRuns;
    }
}

/** Runs `options` to its end; its metrics, or false after printing why it did not load. */
bool runToEnd(const RunOptions &options, QJsonObject *metrics)
{
    QString error;
    std::unique_ptr<SimRun> run = SimRun::create(options, &error);
    if (!run) {
        std::fprintf(stderr, "%s\n", qPrintable(error));
        return false;
    }
    RunSink sink;
    while (run->step(sink)) {
    }
    *metrics = run->metrics();
    return true;
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    const QStringList args = QCoreApplication::arguments();
    const int seeds = args.size() > 1 ? args[1].toInt() : 5;
    const QStringList routers = args.size() > 2
                                    ? args[2].split(QLatin1Char(','))
                                    : QStringList{QStringLiteral("C3"), QStringLiteral("C3p")};
    struct Stress
    {
        const char *scene;
        const char *op;
        double duration;
        const char *count, *warned, *inTime, *lead;
    };
    const Stress stresses[] = {
        {"box_and_block", "fast_squeeze", 60.0, "cubes_broken", "breaks_warned_share",
         "breaks_warned_in_time_share", "warning_lead_time"},
        {"bimanual_sorting", "drifting_hold", 90.0, "containers_dropped", "drops_warned_share",
         "drops_warned_in_time_share", "drop_warning_lead_time"},
    };
    std::printf("bench_warnings: seeds 1-%d, reaction time %.2f s\n", seeds, DefaultReactionTime);
    std::printf("  %-35s %-6s %9s %8s %9s %10s\n", "stress", "router", "failures", "warned",
                "in time", "mean lead");
    for (const Stress &stress : stresses) {
        for (const QString &router : routers) {
            Totals totals;
            for (int seed = 1; seed <= seeds; ++seed) {
                RunOptions options;
                options.scene = QString::fromLatin1(stress.scene);
                options.operatorName = QString::fromLatin1(stress.op);
                options.router = router;
                options.seed = std::uint64_t(seed);
                options.duration = stress.duration;
                QJsonObject metrics;
                if (!runToEnd(options, &metrics))
                    return 1;
                add(totals, metrics, stress.count, stress.warned, stress.inTime, stress.lead);
            }
            const double n = std::max(1, totals.failures);
            const QString label = QStringLiteral("%1 on %2")
                                      .arg(QLatin1String(stress.op), QLatin1String(stress.scene));
            std::printf("  %-35s %-6s %9d %7.0f%% %8.0f%% %9.3fs\n", qPrintable(label),
                        qPrintable(router), totals.failures, 100.0 * totals.warned / n,
                        100.0 * totals.inTime / n,
                        totals.leadRuns ? totals.leadSum / totals.leadRuns : 0.0);
        }
    }

    std::printf("\nthe left hand's warnings as alarms: bimanual_sorting, reactive, 120 s, seeds 1-%d, "
                "horizon %.0f s\n",
                seeds, DefaultHorizon);
    std::printf("  %-6s %6s %9s %9s %10s %6s\n", "router", "drops", "in time", "by onset",
                "precision", "duty");
    for (const QString &router : routers) {
        int drops = 0;
        double inTime = 0, byOnset = 0, precision = 0, duty = 0;
        int precisionRuns = 0, dutyRuns = 0;
        for (int seed = 1; seed <= seeds; ++seed) {
            RunOptions options;
            options.scene = QStringLiteral("bimanual_sorting");
            options.operatorName = QStringLiteral("reactive");
            options.router = router;
            options.seed = std::uint64_t(seed);
            options.duration = 120.0;
            QJsonObject m;
            if (!runToEnd(options, &m))
                return 1;
            const int n = m.value(QLatin1String("containers_dropped")).toInt();
            drops += n;
            inTime += n * m.value(QLatin1String("drops_warned_in_time_share")).toDouble();
            byOnset += n * m.value(QLatin1String("drops_warned_by_onset_share")).toDouble();
            if (m.value(QLatin1String("left_warning_precision")).isDouble()) {
                precision += m.value(QLatin1String("left_warning_precision")).toDouble();
                ++precisionRuns;
            }
            if (m.value(QLatin1String("left_warning_duty")).isDouble()) {
                duty += m.value(QLatin1String("left_warning_duty")).toDouble();
                ++dutyRuns;
            }
        }
        const double n = std::max(1, drops);
        std::printf("  %-6s %6d %8.0f%% %8.0f%% %9.0f%% %5.0f%%\n", qPrintable(router), drops,
                    100.0 * inTime / n, 100.0 * byOnset / n,
                    precisionRuns ? 100.0 * precision / precisionRuns : 0.0,
                    dutyRuns ? 100.0 * duty / dutyRuns : 0.0);
    }
    return 0;
}
