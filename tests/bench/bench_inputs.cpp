// SPDX-License-Identifier: MIT
// What large inputs cost: AHAP and `.haptic` import (events spread over time, the envelope
// combined and simplified) and router validation (parse and compile) at 10^4, 10^5 and
// 10^6 elements. The work must grow as n or n·log n: a tenfold input may take at most
// about twelve times as long. `bench_inputs [MAX]` stops at MAX elements (default 10^6).
#include "hapticconverter.h"
#include "largeinputs.h"
#include "router.h"
#include "routergraph.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <chrono>
#include <cstdio>
#include <cstdlib>

using namespace semhap;

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start)
{
    return std::chrono::duration<double>(Clock::now() - start).count();
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    const int max = argc > 1 ? std::atoi(argv[1]) : 1000000;
    std::printf("bench_inputs: time to import or validate, seconds (per element, µs)\n");
    std::printf("  %-34s %9s %10s %10s\n", "input", "elements", "seconds", "µs/elem");
    const auto row = [](const char *what, int n, double seconds) {
        std::printf("  %-34s %9d %10.3f %10.2f\n", what, n, seconds, seconds / n * 1e6);
        std::fflush(stdout);
    };
    const auto imports = [&](const char *what, QByteArray (*generate)(int), const QString &file) {
        ConvertOptions options;
        options.model = QStringLiteral("lra4");
        for (int n = 10000; n <= max; n *= 10) {
            const QByteArray bytes = generate(n);
            QJsonObject pattern;
            QStringList warnings;
            LoadError error;
            const Clock::time_point start = Clock::now();
            const bool ok =
                HapticConverter::parsePattern(bytes, file, options, &pattern, &warnings, &error);
            row(what, n, secondsSince(start));
            if (!ok)
                std::printf("    FAILED: %s\n", qPrintable(error.toString()));
        }
    };
    imports("AHAP import (events)", largeAhap, QStringLiteral("bench.ahap"));
    imports(".haptic import (points)", largeHaptic, QStringLiteral("bench.haptic"));
    for (int n = 10000; n <= max; n *= 10) {
        const QJsonObject json = largeRouter(n);
        const Clock::time_point start = Clock::now();
        RouterGraph graph;
        LoadError error;
        std::unique_ptr<Router> compiled;
        if (RouterGraph::fromJson(json, QStringLiteral("bench.json"), &graph, &error))
            compiled = Router::compile(graph, &error);
        row(compiled ? "router parse + compile (nodes)" : "router FAILED", int(graph.nodes.size()),
            secondsSince(start));
        if (!compiled)
            std::printf("    %s\n", qPrintable(error.toString()));
    }
    return 0;
}
