// SPDX-License-Identifier: MIT
// The study database (docs/studies.md): participants and their orders, the steps, trials
// done, aborted, invalid and interrupted, answers within their scales, one writer at a time.
#include "sessioninfo.h"
#include "studydatabase.h"

#include <QDir>
#include <QFile>
#include <QSqlDatabase>
#include <QSqlQuery>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

using namespace semhap;
using Step = StudyProtocol::Step;
using Kind = StudyProtocol::Step::Kind;

namespace {

QString examples()
{
    return QStringLiteral(SEMHAP_RESOURCES "/studies/");
}

StudyProtocol readProtocol(const QString &path)
{
    StudyProtocol protocol;
    LoadError error;
    if (!StudyProtocol::read(path, &protocol, &error))
        qFatal("%s", qPrintable(error.toString()));
    return protocol;
}

} // namespace

class TestStudyDatabase : public QObject
{
    Q_OBJECT

private slots:
    void participantsTakeTheSchemesOrders();
    void anExistingFileIsNeverOverwritten();
    void aSecondWriterIsRefused();
    void stepsFollowTheProtocol();
    void aCrashLeavesTheTrialInterrupted();
    void anInvalidTrialIsRedone();
    void answersStayWithinTheirScale_data();
    void answersStayWithinTheirScale();
    void theNewestAnswerCounts();
    void theStudyKeepsItsProtocol();
    void sessionsAreTagged();
    void resultsOutliveTheProtocolsFolder();
    void whatAnotherStudyLeftIsRefused();
    void aDamagedStudyReadsWithAnError();

private:
    QTemporaryDir m_dir;
    std::unique_ptr<StudyDatabase>
    create(const QString &name, const QString &protocol = QStringLiteral("bimanual.json"))
    {
        QString error;
        auto study = StudyDatabase::create(m_dir.filePath(name),
                                           readProtocol(examples() + protocol), &error);
        if (!study)
            qFatal("%s", qPrintable(error));
        return study;
    }
    /** Runs `step` to its end, done. */
    static void complete(StudyDatabase &study, const QString &participant, const Step &step)
    {
        QString error;
        const QString session = study.newSessionPath(participant, step, &error);
        const qint64 id = study.beginTrial(participant, step, session, &error);
        QVERIFY2(id > 0, qPrintable(error));
        QVERIFY2(study.finishTrial(id, 60.0, {{QStringLiteral("cubes_transferred"), 7}}, &error),
                 qPrintable(error));
    }
};

void TestStudyDatabase::participantsTakeTheSchemesOrders()
{
    auto study = create(QStringLiteral("orders.db"));
    const ConditionOrder scheme = study->protocol().order();
    QString error;
    for (const QString &id : {QStringLiteral("P01"), QStringLiteral("P02"), QStringLiteral("P03"),
                              QStringLiteral("P04"), QStringLiteral("P05")})
        QVERIFY2(study->addParticipant(id, &error), qPrintable(error));
    QVERIFY(!study->addParticipant(QStringLiteral("P01"), &error));
    QVERIFY(error.contains(QLatin1String("already a participant")));
    QVERIFY(!study->addParticipant(QStringLiteral("Jane Doe"), &error));
    const QStringList ids = study->participants();
    QCOMPARE(ids.size(), 5);
    study.reset();
    auto reopened = StudyDatabase::open(m_dir.filePath(QStringLiteral("orders.db")),
                                        StudyDatabase::Access::Read, &error);
    QVERIFY2(reopened, qPrintable(error));
    QCOMPARE(reopened->participants(), ids);
    for (int p = 0; p < 5; ++p)
        QCOMPARE(reopened->order(ids[p]), scheme.order(p));
    // The fifth takes the first row again: four rows for four conditions.
    QCOMPARE(reopened->order(ids[4]), reopened->order(ids[0]));
}

void TestStudyDatabase::anExistingFileIsNeverOverwritten()
{
    const QString path = m_dir.filePath(QStringLiteral("taken.db"));
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("precious");
    file.close();
    QString error;
    QVERIFY(!StudyDatabase::create(path, readProtocol(examples() + "bimanual.json"), &error));
    QVERIFY2(error.startsWith(path + QStringLiteral(": already exists")), qPrintable(error));
    QVERIFY(file.open(QIODevice::ReadOnly));
    QCOMPARE(file.readAll(), QByteArray("precious"));
    QVERIFY(!StudyDatabase::open(m_dir.filePath("none.db"), StudyDatabase::Access::Read, &error));
    QVERIFY(!StudyDatabase::open(path, StudyDatabase::Access::Read, &error));
    QVERIFY2(error.contains(QLatin1String("not a semhap study")), qPrintable(error));
}

void TestStudyDatabase::aSecondWriterIsRefused()
{
    auto first = create(QStringLiteral("locked.db"));
    QString error;
    QVERIFY(!StudyDatabase::open(first->path(), StudyDatabase::Access::Write, &error));
    QVERIFY2(error.contains(QLatin1String("already open in")), qPrintable(error));
    QVERIFY2(error.contains(QString::number(QCoreApplication::applicationPid())),
             qPrintable(error));
    // Readers (export, analysis) may look while the experimenter works.
    QVERIFY2(StudyDatabase::open(first->path(), StudyDatabase::Access::Read, &error),
             qPrintable(error));
    first.reset();
    QVERIFY2(
        StudyDatabase::open(m_dir.filePath("locked.db"), StudyDatabase::Access::Write, &error),
        qPrintable(error));
}

void TestStudyDatabase::stepsFollowTheProtocol()
{
    auto study = create(QStringLiteral("steps.db"));
    QString error;
    QVERIFY(study->addParticipant(QStringLiteral("P01"), &error));
    const std::vector<int> order = study->order(QStringLiteral("P01"));
    const std::vector<Step> steps = study->protocol().steps(order);
    // Per condition: practice, 2 trials, the questionnaire; then the final one.
    QCOMPARE(int(steps.size()), 4 * 4 + 1);
    QCOMPARE(steps[0], (Step{Kind::Practice, order[0], 0}));
    QCOMPARE(steps[2], (Step{Kind::Trial, order[0], 2}));
    QCOMPARE(steps[4], (Step{Kind::Practice, order[1], 0}));
    QCOMPARE(steps.back().kind, Kind::Final);

    const QString p = QStringLiteral("P01");
    complete(*study, p, steps[0]);
    complete(*study, p, steps[1]);
    QCOMPARE(study->nextStep(p), steps[2]);
    complete(*study, p, steps[2]);
    QCOMPARE(study->nextStep(p), steps[3]);
    // The questionnaire is done once each of its measures has an answer.
    const StudyProtocol &protocol = study->protocol();
    for (const StudyProtocol::Question &q : protocol.questionsAfter(order[0])) {
        for (const QString &measure : q.measures()) {
            QCOMPARE(study->nextStep(p), steps[3]);
            QVERIFY2(study->answer({p, order[0], measure, q.lowest(), {}, {}}, &error),
                     qPrintable(error));
        }
    }
    QCOMPARE(study->nextStep(p), steps[4]);
    for (size_t i = 4; i + 1 < steps.size(); ++i) {
        if (steps[i].kind == Kind::Questionnaire) {
            for (const StudyProtocol::Question &q : protocol.questionsAfter(steps[i].condition))
                for (const QString &measure : q.measures())
                    QVERIFY(study->answer({p, steps[i].condition, measure, 1, {}, {}}, &error));
        } else {
            complete(*study, p, steps[i]);
        }
    }
    QCOMPARE(study->nextStep(p), steps.back());
    for (int c = 0; c < 4; ++c)
        QVERIFY2(study->answer({p, c, QStringLiteral("rank"), double(c + 1), {}, {}}, &error),
                 qPrintable(error));
    QCOMPARE(study->nextStep(p), steps.back());
    QVERIFY2(study->answer({p, -1, QStringLiteral("interview"), 0, QStringLiteral("liked C"), {}},
                           &error),
             qPrintable(error));
    QCOMPARE(study->nextStep(p).kind, Kind::Done);
}

void TestStudyDatabase::aCrashLeavesTheTrialInterrupted()
{
    const QString path = m_dir.filePath(QStringLiteral("crash.db"));
    const QString p = QStringLiteral("P01");
    QString error;
    {
        auto study = create(QStringLiteral("crash.db"));
        QVERIFY(study->addParticipant(p, &error));
        const Step practice = study->nextStep(p);
        complete(*study, p, practice);
        const Step trial = study->nextStep(p);
        QVERIFY(study->beginTrial(p, trial, study->newSessionPath(p, trial, &error), &error));
        // Closed without finishing: what a kill leaves (tests/studycli kills a real process).
    }
    auto study = StudyDatabase::open(path, StudyDatabase::Access::Write, &error);
    QVERIFY2(study, qPrintable(error));
    const std::vector<StudyDatabase::Trial> trials = study->trials(p);
    QCOMPARE(int(trials.size()), 2);
    QCOMPARE(trials[0].status, StudyDatabase::Status::Done);
    QCOMPARE(trials[1].status, StudyDatabase::Status::Interrupted);
    QVERIFY(!trials[1].reason.isEmpty());
    QCOMPARE(study->nextStep(p), (Step{Kind::Trial, trials[1].condition, 1}));
}

void TestStudyDatabase::anInvalidTrialIsRedone()
{
    auto study = create(QStringLiteral("redo.db"));
    const QString p = QStringLiteral("P01");
    QString error;
    QVERIFY(study->addParticipant(p, &error));
    complete(*study, p, study->nextStep(p));
    const Step trial = study->nextStep(p);
    const QString first = study->newSessionPath(p, trial, &error);
    QFile(first).open(QIODevice::WriteOnly); // the recording's file
    const qint64 id = study->beginTrial(p, trial, first, &error);
    QVERIFY(study->finishTrial(id, 60, {}, &error));
    QVERIFY(!study->finishTrial(id, 60, {}, &error)); // once
    QVERIFY(!study->invalidateTrial(id, QStringLiteral("  "), &error));
    QVERIFY(error.contains(QLatin1String("say why")));
    QVERIFY2(study->invalidateTrial(id, QStringLiteral("the band came loose"), &error),
             qPrintable(error));
    QCOMPARE(study->nextStep(p), trial);
    // The redo records into a file of its own; the first stays.
    const QString second = study->newSessionPath(p, trial, &error);
    QVERIFY(second != first);
    QVERIFY(second.endsWith(QLatin1String("-2.db")));
    const qint64 redo = study->beginTrial(p, trial, second, &error);
    QVERIFY(study->abortTrial(redo, 12.5, QStringLiteral("fire alarm"), &error));
    QCOMPARE(study->nextStep(p), trial);
    const std::vector<StudyDatabase::Trial> trials = study->trials(p);
    QCOMPARE(int(trials.size()), 3);
    QCOMPARE(trials[1].status, StudyDatabase::Status::Invalid);
    QCOMPARE(trials[1].reason, QStringLiteral("the band came loose"));
    QCOMPARE(trials[2].status, StudyDatabase::Status::Aborted);
    QCOMPARE(trials[2].seconds, 12.5);
    QVERIFY(!trials[1].session.startsWith(QLatin1Char('/'))); // relative to the study
}

void TestStudyDatabase::answersStayWithinTheirScale_data()
{
    QTest::addColumn<int>("condition");
    QTest::addColumn<QString>("measure");
    QTest::addColumn<double>("value");
    QTest::addColumn<bool>("accepted");
    // Condition 0 is `none`: "the feedback was realistic" is asked after the others only.
    QTest::addRow("likert 1") << 1 << "realistic" << 1.0 << true;
    QTest::addRow("likert 7") << 1 << "realistic" << 7.0 << true;
    QTest::addRow("likert 0") << 1 << "realistic" << 0.0 << false;
    QTest::addRow("likert 8 of 7") << 1 << "realistic" << 8.0 << false;
    QTest::addRow("likert 3.5") << 1 << "realistic" << 3.5 << false;
    QTest::addRow("likert NaN") << 1 << "realistic" << std::nan("") << false;
    QTest::addRow("likert not asked after none") << 0 << "realistic" << 4.0 << false;
    QTest::addRow("likert asked after each") << 0 << "dexterity" << 4.0 << true;
    QTest::addRow("tlx 0") << 1 << "tlx.mental" << 0.0 << true;
    QTest::addRow("tlx 100") << 1 << "tlx.frustration" << 100.0 << true;
    QTest::addRow("tlx 105") << 1 << "tlx.effort" << 105.0 << false;
    QTest::addRow("tlx -5") << 1 << "tlx.effort" << -5.0 << false;
    QTest::addRow("rank 4 of 4") << 2 << "rank" << 4.0 << true;
    QTest::addRow("rank 5 of 4") << 2 << "rank" << 5.0 << false;
    QTest::addRow("rank of no condition") << -1 << "rank" << 1.0 << false;
    QTest::addRow("likert without a condition") << -1 << "realistic" << 1.0 << false;
    QTest::addRow("unknown measure") << 0 << "comfort" << 1.0 << false;
    QTest::addRow("no such condition") << 4 << "realistic" << 1.0 << false;
}

void TestStudyDatabase::answersStayWithinTheirScale()
{
    QFETCH(int, condition);
    QFETCH(QString, measure);
    QFETCH(double, value);
    QFETCH(bool, accepted);
    auto study = create(QStringLiteral("scale-%1.db")
                            .arg(QTest::currentDataTag())
                            .replace(QLatin1Char(' '), QLatin1Char('_')));
    QString error;
    QVERIFY(study->addParticipant(QStringLiteral("P01"), &error));
    QCOMPARE(study->answer({QStringLiteral("P01"), condition, measure, value, {}, {}}, &error),
             accepted);
    QCOMPARE(int(study->answers(QStringLiteral("P01")).size()), accepted ? 1 : 0);
    if (!accepted)
        QVERIFY(!error.isEmpty());
    QVERIFY(!study->answer({QStringLiteral("P02"), 0, QStringLiteral("realistic"), 1, {}, {}},
                           &error));
}

void TestStudyDatabase::theNewestAnswerCounts()
{
    auto study = create(QStringLiteral("newest.db"));
    QString error;
    QVERIFY(study->addParticipant(QStringLiteral("P01"), &error));
    QVERIFY(study->addParticipant(QStringLiteral("P02"), &error));
    for (double v : {3.0, 5.0, 4.0})
        QVERIFY(study->answer({QStringLiteral("P01"), 0, QStringLiteral("dexterity"), v, {}, {}},
                              &error));
    QVERIFY(
        study->answer({QStringLiteral("P02"), 0, QStringLiteral("dexterity"), 6, {}, {}}, &error));
    const std::vector<StudyDatabase::Answer> mine = study->answers(QStringLiteral("P01"));
    QCOMPARE(int(mine.size()), 1);
    QCOMPARE(mine[0].value, 4.0);
    QVERIFY(mine[0].answered.isValid());
    QCOMPARE(int(study->answers().size()), 2);
}

void TestStudyDatabase::theStudyKeepsItsProtocol()
{
    // Copy an example beside the study, start, then edit the file: the study goes on with
    // the protocol it began with.
    const QString protocol = m_dir.filePath(QStringLiteral("mine.json"));
    QVERIFY(QFile::copy(examples() + QStringLiteral("unimanual.json"), protocol));
    QFile::setPermissions(protocol, QFile::ReadOwner | QFile::WriteOwner);
    QString error;
    const QString path = m_dir.filePath(QStringLiteral("kept.db"));
    {
        auto study = StudyDatabase::create(path, readProtocol(protocol), &error);
        QVERIFY2(study, qPrintable(error));
    }
    QFile file(protocol);
    QVERIFY(file.open(QIODevice::ReadOnly));
    QByteArray text = file.readAll();
    file.close();
    text.replace("\"seconds\": 60", "\"seconds\": 90");
    QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
    file.write(text);
    file.close();
    auto study = StudyDatabase::open(path, StudyDatabase::Access::Read, &error);
    QVERIFY2(study, qPrintable(error));
    QCOMPARE(study->protocol().trialSeconds, 60.0);
    QCOMPARE(study->protocol().file, QFileInfo(protocol).absoluteFilePath());
}

void TestStudyDatabase::sessionsAreTagged()
{
    auto study = create(QStringLiteral("tags.db"));
    QString error;
    QVERIFY(study->addParticipant(QStringLiteral("P07"), &error));
    const Step step = study->nextStep(QStringLiteral("P07"));
    SessionInfo info;
    study->tagSession(QStringLiteral("P07"), step, &info);
    QCOMPARE(info.extra.value("participant"), QStringLiteral("P07"));
    QCOMPARE(info.extra.value("phase"), QStringLiteral("practice"));
    QCOMPARE(info.extra.value("condition"),
             study->protocol().conditions[size_t(step.condition)].id);
    QCOMPARE(info.extra.value("study"), study->protocol().name);
    const QString session = study->newSessionPath(QStringLiteral("P07"), step, &error);
    QCOMPARE(QFileInfo(session).absolutePath(), m_dir.filePath(QStringLiteral("tags.sessions")));
}

void TestStudyDatabase::resultsOutliveTheProtocolsFolder()
{
    // A protocol with a router file of its own; the study is copied to another machine
    // where neither is: its results still read, running it says why it cannot.
    QTemporaryDir protocolDir;
    QVERIFY(QFile::copy(QStringLiteral(SEMHAP_RESOURCES "/routers/C3.json"),
                        protocolDir.filePath(QStringLiteral("mine.json"))));
    QFile file(protocolDir.filePath(QStringLiteral("protocol.json")));
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(R"({"format": "semhap.study/1", "name": "Own router", "scene": "box_and_block",
        "conditions": [{"id": "A", "label": "A", "router": "mine.json"},
                       {"id": "B", "label": "B", "router": "C1"}],
        "trials": {"count": 1, "seconds": 10}})");
    file.close();
    const QString path = m_dir.filePath(QStringLiteral("moved.db"));
    QString error;
    {
        auto study = StudyDatabase::create(path, readProtocol(file.fileName()), &error);
        QVERIFY2(study, qPrintable(error));
        QVERIFY(study->addParticipant(QStringLiteral("P01"), &error));
    }
    QVERIFY(protocolDir.remove());
    auto reader = StudyDatabase::open(path, StudyDatabase::Access::Read, &error);
    QVERIFY2(reader, qPrintable(error));
    QCOMPARE(reader->participants(), QStringList{"P01"});
    QCOMPARE(reader->protocol().conditions.size(), size_t(2));
    reader.reset();
    QVERIFY(!StudyDatabase::open(path, StudyDatabase::Access::Write, &error));
    QVERIFY2(error.startsWith(path + QStringLiteral(": its protocol no longer loads: ")) &&
                 error.contains(QLatin1String("/conditions/0/router")),
             qPrintable(error));
}

void TestStudyDatabase::whatAnotherStudyLeftIsRefused()
{
    // A study deleted without its sessions: a new one of the same name would mix them in.
    const QString path = m_dir.filePath(QStringLiteral("again.db"));
    QVERIFY(QDir().mkpath(StudyDatabase::sessionsFolder(path)));
    QString error;
    const StudyProtocol protocol = readProtocol(examples() + QStringLiteral("unimanual.json"));
    QVERIFY2(StudyDatabase::create(path, protocol, &error), qPrintable(error)); // empty: fine
    QVERIFY(QFile::remove(path));
    QFile session(StudyDatabase::sessionsFolder(path) + QStringLiteral("/P01-none-trial1.db"));
    QVERIFY(session.open(QIODevice::WriteOnly));
    session.close();
    QVERIFY(!StudyDatabase::create(path, protocol, &error));
    QVERIFY2(error.contains(QLatin1String("again.sessions is left from another study")),
             qPrintable(error));
    QVERIFY(!QFileInfo::exists(path));
}

void TestStudyDatabase::aDamagedStudyReadsWithAnError()
{
    const QString path = m_dir.filePath(QStringLiteral("damaged.db"));
    {
        auto study = create(QStringLiteral("damaged.db"));
        QString error;
        QVERIFY(study->addParticipant(QStringLiteral("P01"), &error));
        complete(*study, QStringLiteral("P01"), study->nextStep(QStringLiteral("P01")));
    }
    {
        QSqlDatabase db = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), "damage");
        db.setDatabaseName(path);
        QVERIFY(db.open());
        QSqlQuery(db).exec(QStringLiteral("ALTER TABLE trials RENAME TO lost"));
        db.close();
    }
    QSqlDatabase::removeDatabase(QStringLiteral("damage"));
    QString error;
    auto study = StudyDatabase::open(path, StudyDatabase::Access::Read, &error);
    QVERIFY2(study, qPrintable(error));
    QVERIFY(study->readError().isEmpty());
    QVERIFY(study->trials().empty());
    QVERIFY2(study->readError().startsWith(path + QStringLiteral(": cannot read: ")),
             qPrintable(study->readError()));
}

QTEST_GUILESS_MAIN(TestStudyDatabase)
#include "tst_studydatabase.moc"
