// SPDX-License-Identifier: MIT
// The simulation's speed: `semhap run`'s realtime factor on both scenes, and what the whole
// pipeline (operator, contact extraction, detectors, router, player, task) costs over the
// raw mj_step calls of the same run, and what the perceiving operator adds over the reactive
// one. Targets: box_and_block >= 15x real time, the pipeline <= 10 % over raw physics, the
// perceiving operator <= 10 % over the reactive one per tick.
#include "perceivingoperator.h"
#include "simrun.h"

#include <QCoreApplication>

#include <chrono>
#include <cstdio>
#include <cstdlib>

using namespace semhap;

namespace {

/** A run of `seconds` on `scene` with C3, seed 1; exits the benchmark when it cannot load. */
std::unique_ptr<SimRun> load(const char *scene, const QString &operatorName, double seconds)
{
    RunOptions options;
    options.scene = QString::fromLatin1(scene);
    options.operatorName = operatorName;
    options.duration = seconds;
    QString error;
    std::unique_ptr<SimRun> run = SimRun::create(options, &error);
    if (!run) {
        std::fprintf(stderr, "%s\n", qPrintable(error));
        std::exit(1);
    }
    return run;
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    const QStringList args = QCoreApplication::arguments();
    const double seconds = args.size() > 1 ? args[1].toDouble() : 60.0;
    std::printf("bench_sim: %g simulated s per scene, C3, scripted operator, seed 1\n", seconds);
    for (const char *scene : {"box_and_block", "bimanual_sorting"}) {
        std::unique_ptr<SimRun> run = load(scene, QStringLiteral("scripted"), seconds);
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
    // What the perceiving operator adds: its person (senses and gaze) timed on the reactive
    // operator's run, tick by tick, against the rest of the tick without physics (target:
    // <= 10 %). Timed on one run, so the two are of the same ticks.
    std::printf(
        "bench_sim: the perceiving operator's person per tick, C3, reactive run, seed 1\n");
    for (const char *scene : {"box_and_block", "bimanual_sorting"}) {
        std::unique_ptr<SimRun> run = load(scene, QStringLiteral("reactive"), seconds);
        struct Unjudged : Task
        {
            void observe(World &) override {}
            void feel(Gripper, const Feeling &, double) override {}
            QJsonObject metrics() const override { return {}; }
        } task;
        Person person({}, 1);
        std::array<double, 3> left = run->world().target(Gripper::Right).pos;
        RunSink sink;
        long ticks = 0;
        double personSeconds = 0.0;
        const auto start = std::chrono::steady_clock::now();
        while (run->step(sink)) {
            ++ticks;
            const auto before = std::chrono::steady_clock::now();
            person.look(PerceivingOperator::gaze(run->world(), left), run->time());
            if (run->world().hasGripper(Gripper::Left))
                left = run->world().target(Gripper::Left).pos;
            person.sense(run->perception(), task, run->time());
            personSeconds +=
                std::chrono::duration<double>(std::chrono::steady_clock::now() - before).count();
        }
        const double wall =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const double rest = wall - personSeconds - run->world().physicsSeconds();
        std::printf("  %-17s the rest of a tick %6.2f us, the person %5.2f us: %+5.1f %%\n", scene,
                    1e6 * rest / double(ticks), 1e6 * personSeconds / double(ticks),
                    100.0 * personSeconds / rest);
    }
    return 0;
}
