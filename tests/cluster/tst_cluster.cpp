// SPDX-License-Identifier: MIT
// The ready job scripts (scripts/slurm/, docs/cluster.md) on a real one-node Slurm cluster
// that the test starts and stops: a `compare` array and a `study simulate` array, each merged
// and checked against what one machine gives. Needs root (munged and slurmd), as CI has.
#include "compareruns.h"
#include "slurmcluster.h"
#include "studyexports.h"
#include "testfiles.h"

#include <QDir>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QThread>
#include <QtTest>

#include <memory>

namespace {

QString jobScript(const char *name)
{
    return QStringLiteral(SEMHAP_SOURCE_DIR "/scripts/slurm/") + QLatin1String(name);
}

// Every task gets one CPU, so that two run side by side on a two-core machine; the tasks
// run the semhap built here.
const QStringList TaskOptions{"--cpus-per-task=1", "--export=ALL,SEMHAP=" SEMHAP_CLI_BINARY};

} // namespace

class TestCluster : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void compareArrayMergesToTheOneMachineGrid();
    void studyArrayMergesToTheOneMachineStudy();
    void cleanupTestCase() { m_cluster.reset(); }

private:
    std::unique_ptr<SlurmCluster> m_cluster;
    QTemporaryDir m_dir;
};

void TestCluster::initTestCase()
{
    const QString why = SlurmCluster::unavailable();
    if (!why.isEmpty())
        QSKIP(qPrintable(why));
    QVERIFY(m_dir.isValid());
    m_cluster = std::make_unique<SlurmCluster>();
    QString error;
    QVERIFY2(m_cluster->start(QThread::idealThreadCount(), &error), qPrintable(error));
}

void TestCluster::compareArrayMergesToTheOneMachineGrid()
{
    // Three tasks numbered from 0, as some labs number them, for a grid of six runs.
    const QString results = m_dir.filePath(QStringLiteral("results"));
    const QStringList grid{"--scene",  "box_and_block", "--routers", "none,C3",    "--operator",
                           "scripted", "--seeds",       "3",         "--duration", "2"};
    QString error;
    QVERIFY2(m_cluster->runArray(QStringLiteral("0-2"), TaskOptions, jobScript("compare.sbatch"),
                                 QStringList{results} + grid, m_dir.path(), &error),
             qPrintable(error));
    QStringList parts;
    for (int task = 0; task < 3; ++task) {
        parts.append(QStringLiteral("%1/part-%2.csv").arg(results).arg(task));
        QVERIFY2(QFileInfo::exists(parts.last()), qPrintable(parts.last()));
        QVERIFY(!QFileInfo::exists(parts.last() + QStringLiteral(".partial")));
        // Each part says which slice it is and where it ran.
        const QJsonObject provenance =
            QJsonDocument::fromJson(readAll(parts.last() + QStringLiteral(".provenance.json")))
                .object();
        QCOMPARE(provenance.value("shard").toString(), QStringLiteral("%1/3").arg(task + 1));
        QVERIFY(provenance.contains("host") && provenance.contains("command"));
    }
    const QString merged = m_dir.filePath(QStringLiteral("merged.csv"));
    CliResult r = semhapRun(QStringList{"compare", "--merge", "--csv", merged} + parts);
    QVERIFY2(r.code == 0, r.err.constData());
    const QString one = m_dir.filePath(QStringLiteral("one.csv"));
    r = semhapRun(QStringList{"compare"} + grid + QStringList{"--csv", one});
    QVERIFY2(r.code == 0, r.err.constData());
    QCOMPARE(compareRuns(readAll(merged)), compareRuns(readAll(one)));
    QCOMPARE(compareRuns(readAll(one)).size(), 1 + 6);
}

void TestCluster::studyArrayMergesToTheOneMachineStudy()
{
    // Three participants in two tasks: P01 and P03 in the first, P02 in the second.
    const QString protocol = QStringLiteral(SEMHAP_RESOURCES "/studies/unimanual.json");
    const QString shards = m_dir.filePath(QStringLiteral("shards"));
    QString error;
    QVERIFY2(m_cluster->runArray(QStringLiteral("1-2"), TaskOptions, jobScript("study.sbatch"),
                                 {protocol, "3", shards, "--trial-seconds", "2"}, m_dir.path(),
                                 &error),
             qPrintable(error));
    const QString merged = m_dir.filePath(QStringLiteral("study.db"));
    CliResult r = semhapRun({"study", "merge", merged, shards + QStringLiteral("/shard-1.db"),
                             shards + QStringLiteral("/shard-2.db")});
    QVERIFY2(r.code == 0, r.err.constData());
    const QString one = m_dir.filePath(QStringLiteral("one.db"));
    r = semhapRun({"study", "simulate", protocol, "--participants", "3", "--trial-seconds", "2",
                   "--out", one});
    QVERIFY2(r.code == 0, r.err.constData());
    compareMergedStudy(merged, one, m_dir.path());
}

QTEST_GUILESS_MAIN(TestCluster)
#include "tst_cluster.moc"
