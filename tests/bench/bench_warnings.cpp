// SPDX-License-Identifier: MIT
// Warnings in time under stress: the share of failures whose warning was felt at least the
// reaction time before them, per router, on the two stress scripts — `fast_squeeze` (the
// operator closes fast and hard on fragile cubes: breaks) on box_and_block and
// `drifting_hold` (the holding hand relaxes: container drops) on bimanual_sorting.
// Target: C3p >= 95 % on both (reported beside the paper's C3).
#include "simrun.h"

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
                QString error;
                std::unique_ptr<SimRun> run = SimRun::create(options, &error);
                if (!run) {
                    std::fprintf(stderr, "%s\n", qPrintable(error));
                    return 1;
                }
                RunSink sink;
                while (run->step(sink)) {
                }
                add(totals, run->metrics(), stress.count, stress.warned, stress.inTime,
                    stress.lead);
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
    return 0;
}
