// SPDX-License-Identifier: MIT
// Per-tick cost of the whole core path: two grippers at 1 kHz through detectors, the C3
// router (and C3p, with the predictive nodes) and the player with all seven devices, and a
// task's router of ten generic detectors (threshold and compose nodes) on five frame
// signals. Prints median, p99 and max in microseconds and the heap allocations per tick (the
// targets: p99 <= 20 us with C3, <= 5 us with C3p and with the generic router
// (tests/bench/README.md); no allocation).
#include "allocationcounter.h"
#include "nametable.h"
#include "pipeline.h"

#include <QCoreApplication>
#include <QJsonDocument>
#include <QJsonObject>
#include <QStringList>

#include <algorithm>
#include <array>
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

/** The five task signals the generic router reads, as a plug insertion would give them. */
const char *const TaskSignals[] = {"plug.lateral", "plug.angle", "plug.depth", "plug.force",
                                   "wrist.fz"};

void addSignals(double t, ContactFrame *right)
{
    static const std::array<int, 5> ids = [] {
        std::array<int, 5> list{};
        for (size_t i = 0; i < list.size(); ++i)
            list[i] = signalNames().intern(QLatin1String(TaskSignals[i]));
        return list;
    }();
    const double phase = std::fmod(t, 5.0);
    right->signalValues.set(ids[0], 0.004 * std::cos(phase * 1.3));        // m
    right->signalValues.set(ids[1], 0.3 * std::exp(-phase) * std::sin(t)); // rad
    right->signalValues.set(ids[2], -0.02 + 0.01 * phase);                 // m
    right->signalValues.set(ids[3], phase > 2.5 ? 8 * (phase - 2.5) : 0);  // N
    right->signalValues.set(ids[4], 10 + 5 * std::sin(t * 3));             // N
}

/**
 * "generic10": the task router of the benchmark, built only from generic nodes: five signal
 * nodes, eight thresholds (every condition, hysteresis, intensity maps, a minDuration) and
 * two compose nodes, feeding the squeeze and the geiger on the right bands.
 */
QByteArray genericRouter()
{
    return R"({"format": "semhap.router/1", "name": "generic10", "nodes": [
      {"id": "lateral", "type": "signal", "params": {"gripper": "right", "quantity": "plug.lateral"}},
      {"id": "angle", "type": "signal", "params": {"gripper": "right", "quantity": "plug.angle"}},
      {"id": "depth", "type": "signal", "params": {"gripper": "right", "quantity": "plug.depth"}},
      {"id": "force", "type": "signal", "params": {"gripper": "right", "quantity": "plug.force"}},
      {"id": "fz", "type": "signal", "params": {"gripper": "right", "quantity": "wrist.fz"}},
      {"id": "aligned", "type": "threshold", "params": {"gripper": "right", "message": "aligned",
       "category": "confirmation", "condition": "inside", "begin": [-0.05, 0.05],
       "end": [-0.06, 0.06]}},
      {"id": "off", "type": "threshold", "params": {"gripper": "right", "message": "off",
       "category": "exception", "condition": "outside", "begin": [-0.003, 0.003],
       "end": [-0.002, 0.002], "intensity": [0.003, 0.006]}},
      {"id": "near", "type": "threshold", "params": {"gripper": "right", "message": "near",
       "category": "exception", "condition": "above", "begin": -0.005, "end": -0.006}},
      {"id": "seated", "type": "threshold", "params": {"gripper": "right", "message": "seated",
       "category": "confirmation", "begin": 0.012, "minDuration": 0.05}},
      {"id": "push", "type": "threshold", "params": {"gripper": "right", "message": "push",
       "category": "exception", "begin": 10, "end": 8, "intensity": [10, 20]}},
      {"id": "light", "type": "threshold", "params": {"gripper": "right", "message": "light",
       "category": "confirmation", "condition": "below", "begin": 1}},
      {"id": "engaged", "type": "threshold", "params": {"gripper": "right", "message": "engaged",
       "category": "confirmation", "begin": 8, "end": 7}},
      {"id": "hard", "type": "threshold", "params": {"gripper": "right", "message": "hard",
       "category": "exception", "begin": 14, "intensity": [14, 16]}},
      {"id": "collision", "type": "compose", "params": {"message": "collision",
       "category": "exception", "mode": "all"}},
      {"id": "ready", "type": "compose", "params": {"message": "ready",
       "category": "confirmation", "mode": "while"}},
      {"id": "warn", "type": "filter", "params": {"category": "exception"}},
      {"id": "confirm", "type": "filter", "params": {"category": "confirmation"}},
      {"id": "geiger", "type": "pattern", "params": {"pattern": "vib.geiger"}},
      {"id": "squeeze", "type": "pattern", "params": {"pattern": "air.squeeze"}},
      {"id": "right.vibro", "type": "device", "params": {"model": "lra4"}},
      {"id": "right.air", "type": "device", "params": {"model": "pneumatic6"}}
    ], "links": [
      {"from": "angle", "to": "aligned"}, {"from": "lateral", "to": "off"},
      {"from": "depth", "to": "near"}, {"from": "depth", "to": "seated"},
      {"from": "force", "to": "push"}, {"from": "force", "to": "light"},
      {"from": "fz", "to": "engaged"}, {"from": "fz", "to": "hard"},
      {"from": "near", "to": "collision:a"}, {"from": "off", "to": "collision:b"},
      {"from": "aligned", "to": "ready:a"}, {"from": "engaged", "to": "ready:b"},
      {"from": "collision", "to": "warn"}, {"from": "push", "to": "warn"},
      {"from": "hard", "to": "warn"}, {"from": "ready", "to": "confirm"},
      {"from": "seated", "to": "confirm"}, {"from": "light", "to": "confirm"},
      {"from": "warn", "to": "geiger"}, {"from": "confirm", "to": "squeeze"},
      {"from": "geiger", "to": "right.vibro"}, {"from": "squeeze", "to": "right.air"}
    ]})";
}

std::unique_ptr<Router> benchRouter(const QString &name, LoadError *error)
{
    if (name != QLatin1String("generic10"))
        return loadRouter(name, {}, error);
    RouterGraph graph;
    if (!RouterGraph::fromJson(QJsonDocument::fromJson(genericRouter()).object(), name, &graph,
                               error))
        return nullptr;
    return Router::compile(graph, error);
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
                                    : QStringList{QStringLiteral("C3"), QStringLiteral("C3p"),
                                                  QStringLiteral("generic10")};
    for (const QString &name : routers) {
        LoadError error;
        std::unique_ptr<Router> router = benchRouter(name, &error);
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
            addSignals(k * 0.001, &right);
            pipeline.process(left, sink);
            pipeline.process(right, sink);
            pipeline.flush(sink);
        }
        test::startCountingAllocations();
        for (int k = 0; k < ticks; ++k) {
            makeFrames(1.0 + k * 0.001, &left, &right);
            addSignals(1.0 + k * 0.001, &right);
            const auto start = std::chrono::steady_clock::now();
            pipeline.process(left, sink);
            pipeline.process(right, sink);
            pipeline.flush(sink);
            const auto stop = std::chrono::steady_clock::now();
            micros[size_t(k)] = std::chrono::duration<double, std::micro>(stop - start).count();
        }
        const long allocations = test::stopCountingAllocations();

        std::printf("bench_pipeline: %s, 2 grippers at 1 kHz, %d devices, %d ticks\n",
                    qPrintable(name), pipeline.router().player().deviceCount(), ticks);
        std::printf("  per tick: median %.2f us, p99 %.2f us, max %.2f us\n",
                    percentile(micros, 0.5), percentile(micros, 0.99), percentile(micros, 1.0));
        std::printf("  heap allocations per tick: %.3f (%ld in all)\n",
                    double(allocations) / ticks, allocations);
        std::printf("  output: %ld events, %ld device frames (checksum %.3f)\n", sink.events,
                    sink.frames, sink.checksum);
    }
    return 0;
}
