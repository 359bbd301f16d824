// SPDX-License-Identifier: MIT
// Per-tick cost of the whole core path: two grippers at 1 kHz through detectors, the C3
// router (and C3p, with the predictive nodes) and the player with all seven devices. Prints
// median, p99 and max in microseconds and the heap allocations per tick (the targets: p99
// <= 20 us with C3, <= 5 us with C3p (its own target, tests/bench/README.md); no allocation).
#include "allocationcounter.h"
#include "pipeline.h"

#include <QCoreApplication>
#include <QStringList>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

using namespace semhap;

namespace {

/** Counts what comes out, so the work is not optimised away. */
class CountingSink : public PipelineSink
{
public:
    void onEvent(const SemanticEvent &) override { ++events; }
    void onDeviceFrame(const DeviceFrame &frame) override
    {
        ++frames;
        checksum += frame.values[0];
    }
    long events = 0;
    long frames = 0;
    double checksum = 0;
};

/**
 * A busy workload: the right hand cycles through grasp, the break zone and release every
 * 4 s; the left hand holds the container while the contact count slides and recovers.
 */
void makeFrames(double t, ContactFrame *left, ContactFrame *right)
{
    const double phase = std::fmod(t, 4.0);
    const double force = phase < 0.5 ? 0.0 : 20 + 50 * (1 - std::cos(phase * 2.2));
    right->t = t;
    right->gripper = Gripper::Right;
    for (Fingertip *tip : {&right->left, &right->right}) {
        tip->f = force / 2;
        tip->n = force > 0 ? 16 : 0;
        tip->actor = force > 0 ? 1 : -1;
    }
    left->t = t;
    left->gripper = Gripper::Left;
    const int rows = int(std::fmod(t, 3.0) * 3); // 0..8 rows lost, a row at a time
    // The friction used swings between 0.5 and 1 of the cone every 3 s (mu 0.1).
    const double use = 0.75 + 0.25 * std::sin(t * 2.1);
    for (Fingertip *tip : {&left->left, &left->right}) {
        tip->f = 15;
        tip->n = std::max(0, 16 - 4 * (rows / 2));
        tip->actor = 0;
        tip->hasFxyz = true;
        tip->mu = 0.1;
        tip->fxyz = {0.0, 15.0, 15.0 * 0.1 * use};
    }
}

double percentile(std::vector<double> sorted, double p)
{
    std::sort(sorted.begin(), sorted.end());
    const auto index =
        size_t(std::clamp(p * double(sorted.size() - 1), 0.0, double(sorted.size() - 1)));
    return sorted[index];
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    const QStringList args = QCoreApplication::arguments();
    const int seconds = args.size() > 1 ? args[1].toInt() : 120;
    const int ticks = std::max(1, seconds) * 1000;

    const QStringList routers = args.size() > 2
                                    ? args[2].split(QLatin1Char(','))
                                    : QStringList{QStringLiteral("C3"), QStringLiteral("C3p")};
    for (const QString &name : routers) {
        LoadError error;
        std::unique_ptr<Router> router = loadRouter(name, {}, &error);
        if (!router) {
            std::fprintf(stderr, "%s\n", qPrintable(error.toString()));
            return 1;
        }
        Pipeline pipeline(std::move(router));
        CountingSink sink;
        ContactFrame left;
        ContactFrame right;
        std::vector<double> micros(size_t(ticks), 0.0);

        // One simulated second of warm-up: first-use allocations (static tables) happen here.
        for (int k = 0; k < 1000; ++k) {
            makeFrames(k * 0.001, &left, &right);
            pipeline.process(left, sink);
            pipeline.process(right, sink);
            pipeline.flush(sink);
        }
        test::startCountingAllocations();
        for (int k = 0; k < ticks; ++k) {
            makeFrames(1.0 + k * 0.001, &left, &right);
            const auto start = std::chrono::steady_clock::now();
            pipeline.process(left, sink);
            pipeline.process(right, sink);
            pipeline.flush(sink);
            const auto stop = std::chrono::steady_clock::now();
            micros[size_t(k)] = std::chrono::duration<double, std::micro>(stop - start).count();
        }
        const long allocations = test::stopCountingAllocations();

        std::printf("bench_pipeline: %s, 2 grippers at 1 kHz, 7 devices, %d ticks\n",
                    qPrintable(name), ticks);
        std::printf("  per tick: median %.2f us, p99 %.2f us, max %.2f us\n",
                    percentile(micros, 0.5), percentile(micros, 0.99), percentile(micros, 1.0));
        std::printf("  heap allocations per tick: %.3f (%ld in all)\n",
                    double(allocations) / ticks, allocations);
        std::printf("  output: %ld events, %ld device frames (checksum %.3f)\n", sink.events,
                    sink.frames, sink.checksum);
    }
    return 0;
}
