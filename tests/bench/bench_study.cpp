// SPDX-License-Identifier: MIT
// A study simulated and analysed (tests/bench/README.md): `semhap study simulate`'s
// throughput on a protocol, the disk its study and sessions take, and the analysis' time.
// bench_study [PROTOCOL] [PARTICIPANTS] [TRIAL_SECONDS]; TRIAL_SECONDS 0: the protocol's.
#include "studyanalysis.h"
#include "studydatabase.h"
#include "studysimulation.h"

#include <QCoreApplication>
#include <QDirIterator>
#include <QElapsedTimer>
#include <QTemporaryDir>

#include <cstdio>

using namespace semhap;

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    const QStringList args = app.arguments();
    const QString protocolPath =
        args.size() > 1 ? args[1] : QStringLiteral(SEMHAP_RESOURCES "/studies/bimanual.json");
    const int participants = args.size() > 2 ? args[2].toInt() : 4;
    const double trialSeconds = args.size() > 3 ? args[3].toDouble() : 30.0;
    StudyProtocol protocol;
    LoadError loadError;
    if (!StudyProtocol::read(protocolPath, &protocol, &loadError)) {
        std::fprintf(stderr, "%s\n", qPrintable(loadError.toString()));
        return 1;
    }
    QTemporaryDir dir;
    QString error;
    auto study = StudyDatabase::create(dir.filePath(QStringLiteral("bench.db")), protocol, &error);
    StudySimulation::Options options;
    options.participants = participants;
    options.maxSeconds = trialSeconds;
    QElapsedTimer wall;
    wall.start();
    if (!study || !StudySimulation::run(*study, options, &error)) {
        std::fprintf(stderr, "%s\n", qPrintable(error));
        return 1;
    }
    const double simulateSeconds = double(wall.elapsed()) / 1000.0;
    double simulated = 0;
    for (const StudyDatabase::Trial &trial : study->trials())
        simulated += trial.seconds;
    qint64 bytes = 0;
    QDirIterator files(dir.path(), QDir::Files, QDirIterator::Subdirectories);
    while (files.hasNext()) {
        files.next();
        bytes += files.fileInfo().size();
    }
    wall.restart();
    const StudyAnalysis analysis = StudyAnalysis::run(StudyTable::fromStudy(*study));
    const QByteArray report = analysis.markdown();
    const double analyseMs = double(wall.nsecsElapsed()) / 1e6;
    const size_t runs = study->trials().size();
    std::printf("bench_study: %s, %d participants, runs capped at %g s\n",
                qPrintable(protocol.name), participants, trialSeconds);
    std::printf("  simulate: %zu runs, %.0f simulated s in %.1f s wall (%.1fx real time, %.2f s "
                "per run)\n",
                runs, simulated, simulateSeconds, simulated / simulateSeconds,
                simulateSeconds / double(runs));
    std::printf("  disk: %.1f MB for the study and its sessions (%.2f MB per simulated minute)\n",
                double(bytes) / 1e6, double(bytes) / 1e6 / (simulated / 60.0));
    std::printf("  analyze: %zu measures in %.1f ms (report %lld bytes)\n",
                analysis.measures.size(), analyseMs, qlonglong(report.size()));
    return 0;
}
