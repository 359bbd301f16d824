// SPDX-License-Identifier: MIT
// A simulated study in shards (docs/cluster.md): `study simulate --shard I/N|auto` slices the
// participants, `study merge` joins the slices into the study one machine makes, and refuses
// slices that are not of one study.
#include "studydatabase.h"
#include "studyexports.h"
#include "testfiles.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

using namespace semhap;

class TestStudyShards : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase() { QVERIFY(m_dir.isValid()); }
    void shardsMergeIntoTheOneMachineStudy();
    void mergeRefusesShardsOfNoOneStudy_data();
    void mergeRefusesShardsOfNoOneStudy();

private:
    QTemporaryDir m_dir; ///< the shards every refusal starts from, simulated once
};

namespace {

/** Sets the SLURM_ARRAY_TASK_* variables of a task of an array while it lives. */
struct ArrayTask
{
    ArrayTask(int id, int min, int max, int step, int count)
    {
        const int values[] = {id, min, max, step, count};
        for (int i = 0; i < 5; ++i)
            qputenv(Names[i], QByteArray::number(values[i]));
    }
    ~ArrayTask()
    {
        for (const char *name : Names)
            qunsetenv(name);
    }
    static constexpr const char *Names[] = {"SLURM_ARRAY_TASK_ID", "SLURM_ARRAY_TASK_MIN",
                                            "SLURM_ARRAY_TASK_MAX", "SLURM_ARRAY_TASK_STEP",
                                            "SLURM_ARRAY_TASK_COUNT"};
};

/** Copies a study and its sessions folder into `dir`, under the same names. */
bool copyStudy(const QString &study, const QString &dir)
{
    const QString sessions = StudyDatabase::sessionsFolder(study);
    const QString copied = QDir(dir).filePath(QFileInfo(sessions).fileName());
    if (!QFile::copy(study, QDir(dir).filePath(QFileInfo(study).fileName())) ||
        !QDir().mkpath(copied))
        return false;
    for (const QString &file : QDir(sessions).entryList(QDir::Files)) {
        if (!QFile::copy(QDir(sessions).filePath(file), QDir(copied).filePath(file)))
            return false;
    }
    return true;
}

} // namespace

void TestStudyShards::shardsMergeIntoTheOneMachineStudy()
{
    // Three participants on one machine, and as two shards: the first by I/N, the second as
    // task 8 of a Slurm array 7-8. Merged, the study exports and analyses as the one.
    QTemporaryDir dir;
    const auto path = [&](const char *name) { return dir.filePath(QLatin1String(name)); };
    const QStringList simulate{
        "study",           "simulate", example("unimanual.json"), "--participants", "3",
        "--trial-seconds", "2"};
    CliResult r = semhapRun(simulate + QStringList{"--out", path("one.db")});
    QVERIFY2(r.code == 0, r.err.constData());
    r = semhapRun(simulate + QStringList{"--out", path("s1.db"), "--shard", "1/2"});
    QVERIFY2(r.code == 0, r.err.constData());
    QVERIFY(r.out.contains("2 simulated participants, 24 runs"));
    {
        const ArrayTask task(8, 7, 8, 1, 2);
        r = semhapRun(simulate + QStringList{"--out", path("s2.db"), "--shard", "auto"});
    }
    QVERIFY2(r.code == 0, r.err.constData());
    QVERIFY(r.out.contains("1 simulated participant, 12 runs"));
    {
        // Each shard says which of the study it holds and where it came from.
        QString error;
        const auto shard = StudyDatabase::open(path("s2.db"), StudyDatabase::Access::Read, &error);
        QVERIFY2(shard, qPrintable(error));
        QCOMPARE(shard->participants(), QStringList{"P02"});
        const QJsonObject record =
            QJsonDocument::fromJson(shard->value("simulation").toUtf8()).object();
        QCOMPARE(record.value("shard").toString(), QString("2/2"));
        QCOMPARE(record.value("simulated").toArray(), QJsonArray{2});
        const QJsonObject provenance = record.value("provenance").toObject();
        for (const char *key : {"semhap", "command", "host", "started", "ended"})
            QVERIFY2(provenance.contains(key), key);
    }
    r = semhapRun({"study", "merge", path("all.db"), path("s2.db"), path("s1.db")});
    QVERIFY2(r.code == 0, r.err.constData());
    compareMergedStudy(path("all.db"), path("one.db"), dir.path());
    if (QTest::currentTestFailed())
        return;
    // The merged study's sessions are in its own folder, named as one machine names them.
    QVERIFY(readAll(path("export-1/trials.csv")).contains("all.sessions/P02-none-practice.db"));
    QVERIFY(QFileInfo(path("all.sessions/P02-none-practice.db")).isFile());
}

void TestStudyShards::mergeRefusesShardsOfNoOneStudy_data()
{
    QTest::addColumn<QString>("problem");
    QTest::addColumn<QString>("error");
    QTest::newRow("a participant twice") << "twice"
                                         << "copy.db: P01 is in s1.db too";
    QTest::newRow("a participant missing") << "missing"
                                           << "P02 is in none of the shards (of 2 participants)";
    QTest::newRow("another protocol") << "protocol"
                                      << "other.db: not of the protocol s1.db is of";
    QTest::newRow("another simulation")
        << "seconds"
        << "longer.db: simulated with another trial_seconds than s1.db";
    QTest::newRow("an unfinished participant")
        << "unfinished"
        << "s1.db: P01 is not finished (simulate that shard again with --resume)";
}

void TestStudyShards::mergeRefusesShardsOfNoOneStudy()
{
    QFETCH(QString, problem);
    QFETCH(QString, error);
    // A study of two participants as two shards, simulated once for every row.
    const QStringList simulate{
        "study",           "simulate", example("unimanual.json"), "--participants", "2",
        "--trial-seconds", "2"};
    const QString made = m_dir.filePath(QStringLiteral("shards"));
    if (!QFileInfo::exists(made + QStringLiteral("/s2.db"))) {
        QVERIFY(QDir().mkpath(made));
        for (const char *shard : {"1", "2"}) {
            const CliResult made1 = semhapRun(
                simulate + QStringList{"--out", made + QStringLiteral("/s%1.db").arg(shard),
                                       "--shard", QStringLiteral("%1/2").arg(shard)});
            QVERIFY2(made1.code == 0, made1.err.constData());
        }
    }
    QTemporaryDir dir;
    QVERIFY(copyStudy(made + QStringLiteral("/s1.db"), dir.path()));
    const QString before = QDir::currentPath();
    QVERIFY(QDir::setCurrent(dir.path())); // the messages name the shards as given
    CliResult r;
    QStringList shards{"s1.db"};
    if (problem == "twice") {
        QVERIFY(QFile::copy("s1.db", "copy.db"));
        shards.append("copy.db");
    } else if (problem == "protocol") {
        // The same study but for its name.
        QByteArray protocol = readAll(example("unimanual.json"));
        protocol.replace("\"name\": \"", "\"name\": \"Another ");
        QFile file("other.json");
        QVERIFY(file.open(QIODevice::WriteOnly) && file.write(protocol) == protocol.size());
        file.close();
        QStringList other = simulate;
        other[2] = dir.filePath("other.json");
        r = semhapRun(other + QStringList{"--out", "other.db", "--shard", "2/2"});
        QVERIFY2(r.code == 0, r.err.constData());
        shards.append("other.db");
    } else if (problem == "seconds") {
        QStringList longer = simulate;
        longer.last() = "3";
        r = semhapRun(longer + QStringList{"--out", "longer.db", "--shard", "2/2"});
        QVERIFY2(r.code == 0, r.err.constData());
        shards.append("longer.db");
    } else if (problem == "unfinished") {
        QVERIFY(copyStudy(made + QStringLiteral("/s2.db"), dir.path()));
        shards.append("s2.db");
        QString reason;
        auto study = StudyDatabase::open("s1.db", StudyDatabase::Access::Write, &reason);
        QVERIFY2(study, qPrintable(reason));
        QVERIFY(study->invalidateTrial(study->trials("P01").back().id, "redo", &reason));
    }
    r = semhapRun(QStringList{"study", "merge", "merged.db"} + shards);
    QVERIFY(QDir::setCurrent(before));
    QCOMPARE(r.code, 1);
    QCOMPARE(QString::fromUtf8(r.err).trimmed(), error);
    QVERIFY(!QFileInfo::exists(dir.filePath("merged.db")));
    QVERIFY(!QFileInfo::exists(dir.filePath("merged.sessions")));
}

QTEST_GUILESS_MAIN(TestStudyShards)
#include "tst_studyshards.moc"
