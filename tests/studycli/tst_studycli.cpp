// SPDX-License-Identifier: MIT
// `semhap study` (docs/studies.md): a protocol simulated with 20 participants into a study,
// its tidy export, a kill in the middle, and the refusals.
#include "clirun.h"
#include "repeatedmeasures.h"
#include "sessionreader.h"
#include "statistics.h"
#include "studydatabase.h"
#include "studysimulation.h"
#include "studytable.h"
#include "testfiles.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QSqlDatabase>
#include <QSqlQuery>
#include <QTemporaryDir>
#include <QtTest>

#include <csignal>
#include <set>
#include <utility>

using namespace semhap;

namespace {

/** The trial seconds CI can afford: 20 participants x 4 conditions x 3 runs. */
constexpr double TrialSeconds = 6.0;

} // namespace

class TestStudyCli : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void simulatedStudyFollowsTheProtocol();
    void exportIsTidy();
    void analysisOfTheStudyAndOfItsExportAgree();
    void reportHasAPlotPerMeasure();
    void aKillLosesAtMostTheRunningTrial();
    void aDamagedStudyIsNeitherExportedNorAnalysed();
    void badCallsAreRefused_data();
    void badCallsAreRefused();
    void perceivingParticipants();

private:
    /**
     * Whether the study of 20 simulated participants is there: simulated by the first test
     * that reads it (a test run on its own, the kill test, waits for none).
     */
    bool simulated();
    QTemporaryDir m_dir;
    QString m_study;
    CliResult m_simulated;
    bool m_simulatedOnce = false;
};

void TestStudyCli::initTestCase()
{
    QVERIFY(m_dir.isValid());
    m_study = m_dir.filePath(QStringLiteral("unimanual.db"));
}

bool TestStudyCli::simulated()
{
    if (!std::exchange(m_simulatedOnce, true)) {
        m_simulated = semhapRun({QStringLiteral("study"), QStringLiteral("simulate"),
                                 example("unimanual.json"), QStringLiteral("--participants"),
                                 QStringLiteral("20"), QStringLiteral("--out"), m_study,
                                 QStringLiteral("--trial-seconds"), QString::number(TrialSeconds)});
        if (m_simulated.code != 0)
            qWarning("%s", m_simulated.err.constData());
    }
    return m_simulated.code == 0;
}

void TestStudyCli::simulatedStudyFollowsTheProtocol()
{
    QVERIFY(simulated());
    QString error;
    auto study = StudyDatabase::open(m_study, StudyDatabase::Access::Read, &error);
    QVERIFY2(study, qPrintable(error));
    const StudyProtocol &protocol = study->protocol();
    const QStringList participants = study->participants();
    QCOMPARE(participants.size(), 20);
    QCOMPARE(participants.first(), QStringLiteral("P01"));
    QCOMPARE(participants.last(), QStringLiteral("P20"));
    const std::vector<StudyDatabase::Trial> trials = study->trials();
    // Each participant: per condition a practice round and two trials, all done.
    QCOMPARE(int(trials.size()), 20 * 4 * 3);
    QVERIFY(m_simulated.out.contains("20 simulated participants, 240 runs"));
    for (int p = 0; p < 20; ++p) {
        const QString id = participants[p];
        QCOMPARE(study->order(id), protocol.order().order(p));
        std::vector<int> met; // the conditions in the order the trials ran
        for (const StudyDatabase::Trial &t : study->trials(id)) {
            QCOMPARE(t.status, StudyDatabase::Status::Done);
            QVERIFY(t.seconds <= TrialSeconds + 1e-6);
            QVERIFY(t.metrics.contains(QLatin1String("cubes_transferred")));
            if (met.empty() || met.back() != t.condition)
                met.push_back(t.condition);
        }
        QCOMPARE(met, study->order(id));
        // The questionnaires are left for people: that is the step each stops at.
        QCOMPARE(study->nextStep(id).kind, StudyProtocol::Step::Kind::Questionnaire);
    }
    // A trial's session is tagged with its place in the study and ran the condition's
    // router with the participant's seed.
    const StudyDatabase::Trial &trial = trials[4]; // P01's second condition, trial 1
    QVERIFY(!trial.practice);
    std::unique_ptr<SessionReader> session =
        SessionReader::open(QFileInfo(m_study).absoluteDir().filePath(trial.session), &error);
    QVERIFY2(session, qPrintable(error));
    const SessionInfo &info = session->info();
    QCOMPARE(info.extra.value("participant"), QStringLiteral("P01"));
    QCOMPARE(info.extra.value("condition"), protocol.conditions[size_t(trial.condition)].id);
    QCOMPARE(info.extra.value("phase"), QStringLiteral("trial"));
    QCOMPARE(info.extra.value("trial"), QStringLiteral("1"));
    QCOMPARE(info.routerSource, protocol.conditions[size_t(trial.condition)].router);
    QCOMPARE(info.operatorName, QStringLiteral("reactive"));
    QCOMPARE(info.seed, QString::number(StudySimulation::seed(1, 1)));
    // Participants differ from one another; conditions of one participant share the seeds.
    QVERIFY(StudySimulation::seed(1, 1) != StudySimulation::seed(2, 1));
}

void TestStudyCli::exportIsTidy()
{
    QVERIFY(simulated());
    const QString dir = m_dir.filePath(QStringLiteral("export"));
    const CliResult r = semhapRun({QStringLiteral("study"), QStringLiteral("export"), m_study,
                                   QStringLiteral("--csv"), dir});
    QVERIFY2(r.code == 0, r.err.constData());
    const QList<QByteArray> lines = readAll(dir + QStringLiteral("/measures.csv")).split('\n');
    QCOMPARE(lines.first(), QByteArray("participant,condition,trial,measure,value"));
    // Every timed trial's numeric metrics, no practice round.
    QString error;
    auto study = StudyDatabase::open(m_study, StudyDatabase::Access::Read, &error);
    int expected = 0;
    std::set<QString> seen;
    for (const StudyDatabase::Trial &t : study->trials()) {
        if (t.practice)
            continue;
        for (auto it = t.metrics.begin(); it != t.metrics.end(); ++it) {
            if (!it.value().isDouble())
                continue;
            ++expected;
            const QString row =
                QStringLiteral("%1,%2,%3,%4,")
                    .arg(t.participant, study->protocol().conditions[size_t(t.condition)].id)
                    .arg(t.number)
                    .arg(it.key());
            seen.insert(row + QString::number(it.value().toDouble(), 'g', 17));
        }
    }
    QCOMPARE(lines.size() - 2, expected); // the header, and the empty end after the last \n
    for (int i = 1; i < lines.size() - 1; ++i) {
        const QList<QByteArray> f = lines[i].split(',');
        QCOMPARE(f.size(), 5);
        const QString key = QStringLiteral("%1,%2,%3,%4,%5")
                                .arg(QString::fromUtf8(f[0]), QString::fromUtf8(f[1]),
                                     QString::fromUtf8(f[2]), QString::fromUtf8(f[3]))
                                .arg(QString::number(f[4].toDouble(), 'g', 17));
        QVERIFY2(seen.count(key), qPrintable(key));
    }
    // The export reads back as it was written.
    StudyTable table;
    LoadError loadError;
    QVERIFY2(StudyTable::readCsv(dir + QStringLiteral("/measures.csv"), &table, &loadError),
             qPrintable(loadError.toString()));
    QCOMPARE(int(table.rows().size()), expected);
    QCOMPARE(table.toCsv(), StudyTable::fromStudy(*study).toCsv());
    const QList<QByteArray> trials = readAll(dir + QStringLiteral("/trials.csv")).split('\n');
    QCOMPARE(trials.size() - 2, 240);
    QVERIFY(trials[1].startsWith("P01,"));
    QVERIFY(trials[1].contains(",practice,,done,"));
}

void TestStudyCli::analysisOfTheStudyAndOfItsExportAgree()
{
    QVERIFY(simulated());
    const CliResult fromStudy = semhapRun(
        {QStringLiteral("study"), QStringLiteral("analyze"), m_study, QStringLiteral("--json")});
    QVERIFY2(fromStudy.code == 0, fromStudy.err.constData());
    const QJsonObject json = QJsonDocument::fromJson(fromStudy.out).object();
    QCOMPARE(json[QLatin1String("conditions")].toArray().size(), 4);
    QJsonObject transferred;
    for (const QJsonValue &m : json[QLatin1String("measures")].toArray()) {
        if (m[QLatin1String("measure")].toString() == QLatin1String("cubes_transferred"))
            transferred = m.toObject();
    }
    QCOMPARE(transferred[QLatin1String("participants")].toInt(), 20);
    QCOMPARE(transferred[QLatin1String("pairwise")].toArray().size(), 6);
    // The statistics are those of the participants' means computed here from the study's
    // trials, by the tested functions (tests/statistics checks them on textbook data).
    QString error;
    auto study = StudyDatabase::open(m_study, StudyDatabase::Access::Read, &error);
    QVERIFY2(study, qPrintable(error));
    const QStringList ids = study->participants();
    std::vector<std::vector<double>> means(20, std::vector<double>(4, 0.0));
    for (const StudyDatabase::Trial &t : study->trials()) {
        if (!t.practice)
            means[size_t(ids.indexOf(t.participant))][size_t(t.condition)] +=
                t.metrics[QLatin1String("cubes_transferred")].toDouble() / 2.0;
    }
    const WithinEffect anova = repeatedMeasuresAnova(means);
    const FriedmanTest friedman = friedmanTest(means);
    const QJsonObject anovaJson = transferred[QLatin1String("anova")].toObject();
    QCOMPARE(anovaJson[QLatin1String("tested")].toBool(), anova.tested);
    if (anova.tested) {
        QCOMPARE(anovaJson[QLatin1String("f")].toDouble(), anova.f);
        QCOMPARE(anovaJson[QLatin1String("p")].toDouble(), anova.p);
    }
    QCOMPARE(transferred[QLatin1String("friedman")][QLatin1String("chi_squared")].toDouble(),
             friedman.chiSquared);
    std::vector<double> first; // the protocol's first condition
    for (const std::vector<double> &row : means)
        first.push_back(row[0]);
    QCOMPARE(transferred[QLatin1String("conditions")][0][QLatin1String("mean")].toDouble(),
             summarise(first).mean);
    const QString primary = transferred[QLatin1String("primary")].toString();
    QVERIFY(primary == QLatin1String("anova") || primary == QLatin1String("friedman"));
    // The same analysis from the tidy export (collected elsewhere, say): the same numbers.
    const QString dir = m_dir.filePath(QStringLiteral("export-for-analysis"));
    QCOMPARE(semhapRun({QStringLiteral("study"), QStringLiteral("export"), m_study,
                        QStringLiteral("--csv"), dir})
                 .code,
             0);
    const CliResult fromCsv =
        semhapRun({QStringLiteral("study"), QStringLiteral("analyze"),
                   dir + QStringLiteral("/measures.csv"), QStringLiteral("--json")});
    QVERIFY2(fromCsv.code == 0, fromCsv.err.constData());
    // A CSV's conditions come in the order first seen (P01's order here), so compare what
    // does not depend on the order: the tests' statistics and each condition's mean.
    const auto invariant = [](const QJsonObject &analysis) {
        QMap<QString, QString> out;
        for (const QJsonValue &m : analysis[QLatin1String("measures")].toArray()) {
            const QString name = m[QLatin1String("measure")].toString();
            out[name] =
                QStringLiteral("n %1 F %2 p %3 chi2 %4")
                    .arg(m[QLatin1String("participants")].toInt())
                    .arg(m[QLatin1String("anova")][QLatin1String("f")].toDouble(), 0, 'g', 10)
                    .arg(m[QLatin1String("anova")][QLatin1String("p")].toDouble(), 0, 'g', 10)
                    .arg(m[QLatin1String("friedman")][QLatin1String("chi_squared")].toDouble(), 0,
                         'g', 10);
            for (const QJsonValue &c : m[QLatin1String("conditions")].toArray())
                out[name + QLatin1Char('/') + c[QLatin1String("condition")].toString()] =
                    QString::number(c[QLatin1String("mean")].toDouble(), 'g', 12);
        }
        return out;
    };
    QCOMPARE(invariant(QJsonDocument::fromJson(fromCsv.out).object()), invariant(json));
    // One measure on its own; an unknown one is refused with the ones there are.
    const CliResult one =
        semhapRun({QStringLiteral("study"), QStringLiteral("analyze"), m_study,
                   QStringLiteral("--measure"), QStringLiteral("cubes_transferred")});
    QCOMPARE(one.code, 0);
    QVERIFY(one.out.contains("| cubes_transferred | 20 |"));
    QVERIFY(!one.out.contains("## cubes_broken"));
    const CliResult unknown =
        semhapRun({QStringLiteral("study"), QStringLiteral("analyze"), m_study,
                   QStringLiteral("--measure"), QStringLiteral("happiness")});
    QCOMPARE(unknown.code, 1);
    QVERIFY(unknown.err.contains("no measure 'happiness' (measures: "));
}

void TestStudyCli::reportHasAPlotPerMeasure()
{
    QVERIFY(simulated());
    const QString dir = m_dir.filePath(QStringLiteral("report"));
    const CliResult r = semhapRun({QStringLiteral("study"), QStringLiteral("analyze"), m_study,
                                   QStringLiteral("--report"), dir});
    QVERIFY2(r.code == 0, r.err.constData());
    const QString report = QString::fromUtf8(readAll(dir + QStringLiteral("/report.md")));
    QVERIFY(report.startsWith(QLatin1String("# Analysis: Unimanual evaluation")));
    QVERIFY(report.contains(QLatin1String("## Summary")));
    int plots = 0;
    for (const QString &line : report.split(QLatin1Char('\n'))) {
        if (!line.startsWith(QLatin1String("![")))
            continue;
        const QString file = line.mid(line.indexOf(QLatin1String("](")) + 2).chopped(1);
        const QByteArray svg = readAll(dir + QLatin1Char('/') + file);
        QVERIFY2(svg.startsWith("<svg xmlns=\"http://www.w3.org/2000/svg\""), qPrintable(file));
        QVERIFY(svg.trimmed().endsWith("</svg>"));
        ++plots;
    }
    QVERIFY(plots >= 10);
}

void TestStudyCli::aKillLosesAtMostTheRunningTrial()
{
    const QString path = m_dir.filePath(QStringLiteral("killed.db"));
    QProcess process;
    process.start(QStringLiteral(SEMHAP_CLI_BINARY),
                  {QStringLiteral("study"), QStringLiteral("simulate"), example("unimanual.json"),
                   QStringLiteral("--participants"), QStringLiteral("1"), QStringLiteral("--out"),
                   path, QStringLiteral("--trial-seconds"), QStringLiteral("20")});
    QVERIFY(process.waitForStarted());
    // Three runs done and the fourth begun, as the study itself says: kill it there, as a
    // power cut would. The study is read as export reads it, beside its writer.
    const auto fourthRunning = [&] {
        QString ignored;
        const auto reader = StudyDatabase::open(path, StudyDatabase::Access::Read, &ignored);
        if (!reader)
            return false;
        const std::vector<StudyDatabase::Trial> trials = reader->trials();
        return trials.size() == 4 && trials.back().status == StudyDatabase::Status::Running;
    };
    QTRY_VERIFY_WITH_TIMEOUT(fourthRunning() || process.state() != QProcess::Running, 240000);
    QCOMPARE(process.state(), QProcess::Running);
    QVERIFY(process.processId() > 0); // never kill(0): that is this test's own group
    ::kill(pid_t(process.processId()), SIGKILL);
    QVERIFY(process.waitForFinished());
    QString error;
    auto study = StudyDatabase::open(path, StudyDatabase::Access::Write, &error);
    QVERIFY2(study, qPrintable(error)); // the dead process's lock is taken over
    const std::vector<StudyDatabase::Trial> trials = study->trials();
    QCOMPARE(int(trials.size()), 4);
    for (int k = 0; k < 3; ++k)
        QCOMPARE(trials[size_t(k)].status, StudyDatabase::Status::Done);
    const StudyDatabase::Trial &killed = trials.back();
    QCOMPARE(killed.status, StudyDatabase::Status::Interrupted);
    // It is due again: the participant's first run not done is the one that was running.
    // (The simulation answers no questionnaire, so the first condition's is still open.)
    StudyProtocol::Step due;
    for (const StudyProtocol::Step &step :
         study->protocol().steps(study->order(killed.participant))) {
        const bool run = step.kind == StudyProtocol::Step::Kind::Practice ||
                         step.kind == StudyProtocol::Step::Kind::Trial;
        if (run && !study->isDone(killed.participant, step)) {
            due = step;
            break;
        }
    }
    QCOMPARE(due.kind, killed.practice ? StudyProtocol::Step::Kind::Practice
                                       : StudyProtocol::Step::Kind::Trial);
    QCOMPARE(due.condition, killed.condition);
    QCOMPARE(due.trial, killed.number);
    QSqlDatabase db =
        QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), QStringLiteral("check"));
    db.setDatabaseName(path);
    QVERIFY(db.open());
    QSqlQuery check(db);
    QVERIFY(check.exec(QStringLiteral("PRAGMA integrity_check")) && check.next());
    QCOMPARE(check.value(0).toString(), QStringLiteral("ok"));
    check = QSqlQuery();
    db.close();
    db = QSqlDatabase();
    QSqlDatabase::removeDatabase(QStringLiteral("check"));
    study.reset();

    // Resumed, the runs done stay and the rest run, the one cut off again: the measures are
    // those of a simulation never killed, and the cut-off attempt stays, as interrupted.
    const QStringList simulate{
        "study",           "simulate", example("unimanual.json"), "--participants", "1",
        "--trial-seconds", "20"};
    CliResult r = semhapRun(simulate + QStringList{"--out", path, "--resume"});
    QVERIFY2(r.code == 0, r.err.constData());
    QVERIFY(r.out.contains("1 simulated participant, 13 runs"));
    const QString whole = m_dir.filePath(QStringLiteral("unkilled.db"));
    r = semhapRun(simulate + QStringList{"--out", whole});
    QVERIFY2(r.code == 0, r.err.constData());
    for (const QString &made : {path, whole}) {
        r = semhapRun({"study", "export", made, "--csv", made + QStringLiteral("-csv")});
        QVERIFY2(r.code == 0, r.err.constData());
    }
    QCOMPARE(readAll(path + QStringLiteral("-csv/measures.csv")),
             readAll(whole + QStringLiteral("-csv/measures.csv")));
    auto resumed = StudyDatabase::open(path, StudyDatabase::Access::Read, &error);
    QVERIFY2(resumed, qPrintable(error));
    QCOMPARE(resumed->trials()[3].status, StudyDatabase::Status::Interrupted);
    QCOMPARE(QJsonDocument::fromJson(resumed->value("simulation").toUtf8())
                 .object()
                 .value("attempt")
                 .toInt(),
             2);
    // Resumed with another slice of the study, it is refused.
    r = semhapRun(simulate + QStringList{"--out", path, "--resume", "--shard", "1/2"});
    QCOMPARE(r.code, 1);
    QVERIFY2(r.err.contains("was simulated with another shard; resume it with the options it "
                            "was begun with"),
             r.err.constData());
}

void TestStudyCli::aDamagedStudyIsNeitherExportedNorAnalysed()
{
    QVERIFY(simulated());
    const QString copy = m_dir.filePath(QStringLiteral("damaged.db"));
    QVERIFY(QFile::copy(m_study, copy));
    {
        QSqlDatabase db = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), "damage");
        db.setDatabaseName(copy);
        QVERIFY(db.open());
        QVERIFY(QSqlQuery(db).exec(QStringLiteral("ALTER TABLE answers RENAME TO lost")));
        db.close();
    }
    QSqlDatabase::removeDatabase(QStringLiteral("damage"));
    const QString dir = m_dir.filePath(QStringLiteral("damaged-export"));
    const CliResult exported = semhapRun(
        {QStringLiteral("study"), QStringLiteral("export"), copy, QStringLiteral("--csv"), dir});
    QCOMPARE(exported.code, 1);
    QVERIFY2(exported.err.startsWith((copy + QStringLiteral(": cannot read: ")).toUtf8()),
             exported.err.constData());
    QVERIFY(!QFileInfo::exists(dir + QStringLiteral("/measures.csv"))); // nothing half
    const CliResult analysed =
        semhapRun({QStringLiteral("study"), QStringLiteral("analyze"), copy});
    QCOMPARE(analysed.code, 1);
    QVERIFY(analysed.out.isEmpty());
}

void TestStudyCli::badCallsAreRefused_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<int>("code");
    QTest::addColumn<QString>("error");
    const QString out = QStringLiteral("OUT/new.db");
    QTest::newRow("no action") << QStringList{} << 2 << "an action is required";
    QTest::newRow("unknown action") << QStringList{"analyse", "x.db"} << 2 << "unknown action";
    QTest::newRow("no --out") << QStringList{"simulate", example("unimanual.json"),
                                             "--participants", "2"}
                              << 2 << "simulate needs --out";
    QTest::newRow("no participants")
        << QStringList{"simulate", example("unimanual.json"), "--participants", "0", "--out", out}
        << 2 << "--participants must be a whole number from 1 to 1000";
    QTest::newRow("trial seconds 0") << QStringList{"simulate",        example("unimanual.json"),
                                                    "--participants",  "2",
                                                    "--out",           out,
                                                    "--trial-seconds", "0"}
                                     << 2 << "--trial-seconds must be more than 0";
    QTest::newRow("the study exists")
        << QStringList{"simulate", example("unimanual.json"), "--participants", "2", "--out",
                       "STUDY"}
        << 1 << "already exists";
    QTest::newRow("the protocol as the output")
        << QStringList{"simulate", example("unimanual.json"), "--participants", "2",
                       "--out",    example("unimanual.json")}
        << 1 << "cannot write: it is the same file as the input";
    QTest::newRow("a bad protocol")
        << QStringList{"simulate",       QStringLiteral(SEMHAP_TEST_DATA "/bad.json"),
                       "--participants", "2",
                       "--out",          out}
        << 1 << "bad.json: /conditions/0/router: C9: no such router preset";
    QTest::newRow("an operator that ignores feedback")
        << QStringList{"simulate",       example("unimanual.json"),
                       "--participants", "2",
                       "--out",          out,
                       "--operator",     "scripted"}
        << 2 << "--operator must be one of reactive, perceiving";
    QTest::newRow("a person out of range")
        << QStringList{"simulate",       example("unimanual.json"),
                       "--participants", "2",
                       "--out",          out,
                       "--operator",     "perceiving",
                       "--person",       "first_reliance=0.2"}
        << 2 << "--person first_reliance=0.2: expected a number from 0.5 to 1 (default 1)";
    QTest::newRow("a shard out of range")
        << QStringList{"simulate",       example("unimanual.json"),
                       "--participants", "2",
                       "--out",          out,
                       "--shard",        "3/2"}
        << 2 << "--shard expects I/N with 1 <= I <= N";
    QTest::newRow("a shard of no job array")
        << QStringList{"simulate",       example("unimanual.json"),
                       "--participants", "2",
                       "--out",          out,
                       "--shard",        "auto"}
        << 2
        << "--shard auto takes the slice from a Slurm job array (sbatch --array), whose "
           "SLURM_ARRAY_TASK_ID, SLURM_ARRAY_TASK_MIN, SLURM_ARRAY_TASK_MAX, "
           "SLURM_ARRAY_TASK_STEP, SLURM_ARRAY_TASK_COUNT are not set here";
    QTest::newRow("merge of nothing") << QStringList{"merge", out} << 2 << "merge needs";
    QTest::newRow("merge over a shard") << QStringList{"merge", "STUDY", "STUDY"} << 1
                                        << "cannot write: it is the same file as the input";
    QTest::newRow("export of no study")
        << QStringList{"export", example("unimanual.json"), "--csv", "OUT"} << 1
        << "not a semhap study";
    QTest::newRow("export without --csv")
        << QStringList{"export", "STUDY"} << 2 << "export needs --csv DIR or --r DIR";
    QTest::newRow("analyze a bad CSV")
        << QStringList{"analyze", QStringLiteral(SEMHAP_TEST_DATA "/bad.csv")} << 1
        << "bad.csv:3:19: value must be a number, empty or NA, got 'many'";
}

void TestStudyCli::badCallsAreRefused()
{
    QVERIFY(simulated());
    QFETCH(QStringList, args);
    QFETCH(int, code);
    QFETCH(QString, error);
    const QString out = m_dir.filePath(QStringLiteral("refused"));
    QDir().mkpath(out);
    for (QString &arg : args) {
        arg.replace(QLatin1String("OUT"), out);
        if (arg == QLatin1String("STUDY"))
            arg = m_study;
    }
    const QByteArray before = readAll(m_study);
    const CliResult r = semhapRun(QStringList{QStringLiteral("study")} + args);
    QCOMPARE(r.code, code);
    QVERIFY2(QString::fromUtf8(r.err).contains(error), r.err.constData());
    QCOMPARE(readAll(m_study), before); // nothing written over
    QVERIFY(!QFileInfo::exists(out + QStringLiteral("/new.db")));
}

void TestStudyCli::perceivingParticipants()
{
    // The perceiving operator's participants, with a parameter of their person set: each
    // session says who drove and with what senses.
    const QString study = m_dir.filePath(QStringLiteral("perceiving.db"));
    const CliResult r = semhapRun({"study", "simulate", example("unimanual.json"),
                                   "--participants", "2", "--out", study, "--trial-seconds", "2",
                                   "--operator", "perceiving", "--person", "saccade=0.15"});
    QVERIFY2(r.code == 0, r.err.constData());
    QVERIFY(r.out.contains("2 simulated participants, 24 runs"));
    QString error;
    auto opened = StudyDatabase::open(study, StudyDatabase::Access::Read, &error);
    QVERIFY2(opened, qPrintable(error));
    const StudyDatabase::Trial trial = opened->trials().front();
    auto session = SessionReader::open(QFileInfo(study).dir().filePath(trial.session), &error);
    QVERIFY2(session, qPrintable(error));
    QCOMPARE(session->info().operatorName, QStringLiteral("perceiving"));
    QCOMPARE(session->info().extra.value("person"), QStringLiteral("{\"saccade\":0.15}"));
}

QTEST_GUILESS_MAIN(TestStudyCli)
#include "tst_studycli.moc"
