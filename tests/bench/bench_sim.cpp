// SPDX-License-Identifier: MIT
// The simulation's speed: `semhap run`'s realtime factor on both scenes, and what the whole
// pipeline (operator, contact extraction, detectors, router, player, task) costs over the
// raw mj_step calls of the same run. Targets: box_and_block >= 15x real time, the pipeline
// <= 10 % over raw physics.
#include "simrun.h"

#include <QCoreApplication>

#include <chrono>
#include <cstdio>

using namespace semhap;

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    const QStringList args = QCoreApplication::arguments();
    const double seconds = args.size() > 1 ? args[1].toDouble() : 60.0;
    std::printf("bench_sim: %g simulated s per scene, C3, scripted operator, seed 1\n", seconds);
    for (const char *scene : {"box_and_block", "bimanual_sorting"}) {
        RunOptions options;
        options.scene = QString::fromLatin1(scene);
        options.duration = seconds;
        QString error;
        std::unique_ptr<SimRun> run = SimRun::create(options, &error);
        if (!run) {
            std::fprintf(stderr, "%s\n", qPrintable(error));
            return 1;
        }
        RunSink sink;
        const auto start = std::chrono::steady_clock::now();
        while (run->step(sink)) {
        }
        const double wall =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const double physics = run->world().physicsSeconds();
        std::printf("  %-17s %6.1fx real time; mj_step alone %6.1fx; pipeline overhead %5.1f %%\n",
                    scene, run->time() / wall, run->time() / physics,
                    100.0 * (wall - physics) / physics);
    }
    return 0;
}
