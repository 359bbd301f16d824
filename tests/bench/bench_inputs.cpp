// SPDX-License-Identifier: MIT
// What large inputs cost: AHAP and `.haptic` import (events spread over time, the envelope
// combined and simplified) and router validation (parse and compile) at 10^4, 10^5 and
// 10^6 elements. The work must grow as n or n·log n: a tenfold input may take at most
// about twelve times as long. `bench_inputs [MAX]` stops at MAX elements (default 10^6).
#include "hapticconverter.h"
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

/**
 * An AHAP file of `events` events, alternating transients and short continuous ones 20 ms
 * apart with intensities that vary, and an intensity curve every 100 events.
 */
QByteArray ahap(int events)
{
    QJsonArray pattern;
    for (int i = 0; i < events; ++i) {
        const double t = 0.02 * i;
        const double intensity = 0.3 + 0.6 * ((i * 37) % 100) / 100.0;
        const bool transient = i % 2 == 0;
        QJsonObject event{
            {"Time", t},
            {"EventType", transient ? "HapticTransient" : "HapticContinuous"},
            {"EventParameters",
             QJsonArray{QJsonObject{{"ParameterID", "HapticIntensity"},
                                    {"ParameterValue", intensity}},
                        QJsonObject{{"ParameterID", "HapticSharpness"},
                                    {"ParameterValue", 0.5}}}}};
        if (!transient)
            event.insert("EventDuration", 0.015);
        pattern.append(QJsonObject{{"Event", event}});
        if (i % 100 == 50) {
            pattern.append(QJsonObject{
                {"ParameterCurve",
                 QJsonObject{{"ParameterID", "HapticIntensityControl"},
                             {"Time", t},
                             {"ParameterCurveControlPoints",
                              QJsonArray{QJsonObject{{"Time", 0.0}, {"ParameterValue", 1.0}},
                                         QJsonObject{{"Time", 0.5}, {"ParameterValue", 0.6}},
                                         QJsonObject{{"Time", 1.0}, {"ParameterValue", 1.0}}}}}}});
        }
    }
    return QJsonDocument(QJsonObject{{"Version", 1.0}, {"Pattern", pattern}})
        .toJson(QJsonDocument::Compact);
}

/** A `.haptic` file of `points` amplitude breakpoints, one emphasis every tenth. */
QByteArray haptic(int points)
{
    QJsonArray amplitude;
    for (int i = 0; i < points; ++i) {
        QJsonObject point{{"time", 0.01 * i}, {"amplitude", 0.2 + 0.7 * ((i * 13) % 50) / 50.0}};
        if (i % 10 == 5)
            point.insert("emphasis", QJsonObject{{"amplitude", 1.0}, {"frequency", 0.5}});
        amplitude.append(point);
    }
    return QJsonDocument(
               QJsonObject{{"version", QJsonObject{{"major", 1}, {"minor", 0}, {"patch", 0}}},
                           {"signals",
                            QJsonObject{{"continuous",
                                         QJsonObject{{"envelopes",
                                                      QJsonObject{{"amplitude", amplitude}}}}}}}})
        .toJson(QJsonDocument::Compact);
}

/**
 * A router of about `nodes` nodes: force detectors, each behind it a chain of eight
 * filters and a pattern node, all driving one of eight vibrotactile bands.
 */
QJsonObject router(int nodes)
{
    QJsonArray list;
    QJsonArray links;
    for (int d = 0; d < 8; ++d)
        list.append(QJsonObject{{"id", QString("band%1").arg(d)},
                                {"type", "device"},
                                {"params", QJsonObject{{"model", "lra4"}}}});
    const int chains = std::max(1, (nodes - 8) / 10);
    for (int c = 0; c < chains; ++c) {
        const QString id = QString("c%1").arg(c);
        list.append(QJsonObject{
            {"id", QString(id + ".force")},
            {"type", "force"},
            {"params", QJsonObject{{"gripper", QString(c % 2 ? "left" : "right")}, {"grasp", 20}}}});
        QString previous = id + ".force";
        for (int f = 0; f < 8; ++f) {
            const QString filter = QString("%1.f%2").arg(id).arg(f);
            list.append(QJsonObject{{"id", filter},
                                    {"type", "filter"},
                                    {"params", QJsonObject{{"category", "confirmation"}}}});
            links.append(QJsonObject{{"from", previous}, {"to", filter}});
            previous = filter;
        }
        list.append(QJsonObject{{"id", QString(id + ".pattern")},
                                {"type", "pattern"},
                                {"params", QJsonObject{{"pattern", "vib.geiger"}}}});
        links.append(QJsonObject{{"from", previous}, {"to", QString(id + ".pattern")}});
        links.append(QJsonObject{{"from", QString(id + ".pattern")},
                                 {"to", QString("band%1").arg(c % 8)}});
    }
    return QJsonObject{{"format", "semhap.router/1"}, {"nodes", list}, {"links", links}};
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
    ConvertOptions options;
    options.model = QStringLiteral("lra4");
    for (int n = 10000; n <= max; n *= 10) {
        const QByteArray bytes = ahap(n);
        QJsonObject pattern;
        QStringList warnings;
        LoadError error;
        const Clock::time_point start = Clock::now();
        const bool ok = HapticConverter::parsePattern(bytes, QStringLiteral("bench.ahap"),
                                                      options, &pattern, &warnings, &error);
        row(ok ? "AHAP import (events)" : "AHAP import FAILED", n, secondsSince(start));
        if (!ok)
            std::printf("    %s\n", qPrintable(error.toString()));
    }
    for (int n = 10000; n <= max; n *= 10) {
        const QByteArray bytes = haptic(n);
        QJsonObject pattern;
        QStringList warnings;
        LoadError error;
        const Clock::time_point start = Clock::now();
        const bool ok = HapticConverter::parsePattern(bytes, QStringLiteral("bench.haptic"),
                                                      options, &pattern, &warnings, &error);
        row(ok ? ".haptic import (points)" : ".haptic import FAILED", n, secondsSince(start));
        if (!ok)
            std::printf("    %s\n", qPrintable(error.toString()));
    }
    for (int n = 10000; n <= max; n *= 10) {
        const QJsonObject json = router(n);
        const Clock::time_point start = Clock::now();
        RouterGraph graph;
        LoadError error;
        std::unique_ptr<Router> compiled;
        if (RouterGraph::fromJson(json, QStringLiteral("bench.json"), &graph, &error))
            compiled = Router::compile(graph, &error);
        row(compiled ? "router parse + compile (nodes)" : "router FAILED",
            int(graph.nodes.size()), secondsSince(start));
        if (!compiled)
            std::printf("    %s\n", qPrintable(error.toString()));
    }
    return 0;
}
