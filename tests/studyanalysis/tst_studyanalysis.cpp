// SPDX-License-Identifier: MIT
// The study analysis (docs/studies.md, "Analysis") on textbook data with published results,
// through the same tidy table a study or a CSV gives; and the CSV's located errors.
#include "studyanalysis.h"
#include "studydatabase.h"

#include <QFile>
#include <QJsonArray>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

using namespace semhap;

namespace {

QString data(const char *name)
{
    return QStringLiteral(SEMHAP_TEST_DATA "/") + QLatin1String(name);
}

StudyTable readTable(const QString &path)
{
    StudyTable table;
    LoadError error;
    if (!StudyTable::readCsv(path, &table, &error))
        qFatal("%s", qPrintable(error.toString()));
    return table;
}

/** The table of a tidy CSV's text. */
StudyTable tableOf(const QByteArray &csv)
{
    StudyTable table;
    LoadError error;
    if (!StudyTable::parseCsv(csv, QStringLiteral("test.csv"), &table, &error))
        qFatal("%s", qPrintable(error.toString()));
    return table;
}

/** `actual` equals a published value to the digits it was printed with. */
bool published(double actual, double value, double halfUnit)
{
    return std::abs(actual - value) <= halfUnit;
}

} // namespace

class TestStudyAnalysis : public QObject
{
    Q_OBJECT

private slots:
    void oneWayAsField();
    void twoWayFromAFactorialStudy();
    void friedmanAsR();
    void nothingToTest();
    void aMeasureOfSomeConditions();
    void namesFromOtherTools();
    void aRankingTakesRankTests();
    void hugeValuesPlotInBoundedWork();
    void badCsvIsLocated_data();
    void badCsvIsLocated();
};

void TestStudyAnalysis::oneWayAsField()
{
    // Field, Miles & Field (2012), Discovering Statistics Using R, ch. 13: eight celebrities'
    // seconds to retch on four bushtucker foods, each value here the mean of two trials.
    // ezANOVA: F(3, 21) = 3.793806, p = .02557030; Mauchly W = 0.136248, p = .04684581; GG
    // epsilon 0.5328456, p = .06258412. The book reports the corrected test as F(1.60, 11.19)
    // = 3.79, p = .063.
    const StudyTable table = readTable(data("bushtucker.csv"));
    QCOMPARE(table.conditions().size(), 4);
    const StudyAnalysis analysis = StudyAnalysis::run(table);
    QCOMPARE(int(analysis.measures.size()), 1);
    const StudyAnalysis::Measure &m = analysis.measures.front();
    QCOMPARE(m.participants.size(), 8);
    QCOMPARE(m.conditions[0].summary.mean, 8.125); // stick insect: 65 / 8
    QVERIFY(published(m.anova.f, 3.793806, 5e-7));
    QVERIFY(published(m.anova.p, 0.02557030, 5e-9));
    QVERIFY(published(m.anova.sphericity.w, 0.136248, 5e-7));
    QVERIFY(published(m.anova.sphericity.p, 0.04684581, 5e-9));
    QVERIFY(published(m.anova.sphericity.greenhouseGeisser, 0.5328456, 5e-8));
    QVERIFY(published(m.anova.greenhouseGeisser.p, 0.06258412, 5e-9));
    QVERIFY(StudyAnalysis::Measure::sphericityViolated(m.anova));
    // The report gives the corrected test, as the book does.
    const QString report = QString::fromUtf8(analysis.markdown());
    QVERIFY2(report.contains(QStringLiteral("F(1.60, 11.19) = 3.79, p = .063, η²p = .351; "
                                            "Mauchly W = .136, p = .047, Greenhouse–Geisser ε = "
                                            ".533")),
             qPrintable(report));
    // Bonferroni-corrected paired t tests, as R's pairwise.t.test(paired = TRUE,
    // p.adjust.method = "bonferroni") prints them for these data: .0121 and .0056, the
    // other four pairs 1.
    QVERIFY(m.normal);
    QCOMPARE(m.pairedTest, PairedTest::T);
    QCOMPARE(int(m.pairwise.size()), 6);
    QVERIFY2(report.contains(QStringLiteral("stick_insect–kangaroo_testicle (p = .012), "
                                            "stick_insect–fish_eye (p = .006) |")),
             qPrintable(report));
    // JSON carries the same numbers.
    const QJsonObject json = analysis.toJson();
    const QJsonObject anova =
        json[QLatin1String("measures")][0][QLatin1String("anova")].toObject();
    QCOMPARE(anova[QLatin1String("f")].toDouble(), m.anova.f);
    QCOMPARE(anova[QLatin1String("greenhouse_geisser")][QLatin1String("epsilon")].toDouble(),
             m.anova.sphericity.greenhouseGeisser);
}

void TestStudyAnalysis::twoWayFromAFactorialStudy()
{
    // Field's 3 x 3 attitude data (drink x imagery, 20 participants) entered as the trials
    // of a study whose protocol declares the two factors, its conditions listed out of the
    // cells' order. ezANOVA: drink F = 5.105981 (GG epsilon .5771143), imagery F =
    // 122.564825, interaction F = 17.154922; the book: drink F(1.15, 21.93) = 5.11.
    QTemporaryDir dir;
    const QString protocolPath = dir.filePath(QStringLiteral("attitude.json"));
    const char *cells[][3] = {{"waterneut", "water", "neutral"}, {"beerpos", "beer", "positive"},
                              {"wineneg", "wine", "negative"},   {"beerneg", "beer", "negative"},
                              {"waterpos", "water", "positive"}, {"winepos", "wine", "positive"},
                              {"beerneut", "beer", "neutral"},   {"wineneut", "wine", "neutral"},
                              {"waterneg", "water", "negative"}};
    QString conditions;
    for (const auto &c : cells)
        conditions += QStringLiteral(R"({"id": "%1", "label": "%1", "router": "C1",
                                         "levels": {"drink": "%2", "imagery": "%3"}},)")
                          .arg(QLatin1String(c[0]), QLatin1String(c[1]), QLatin1String(c[2]));
    conditions.chop(1);
    QFile file(protocolPath);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(QStringLiteral(R"({"format": "semhap.study/1", "name": "Attitude",
        "scene": "box_and_block",
        "factors": [{"id": "drink", "levels": ["beer", "wine", "water"]},
                    {"id": "imagery", "levels": ["positive", "negative", "neutral"]}],
        "conditions": [%1], "trials": {"count": 1, "seconds": 60}})")
                   .arg(conditions)
                   .toUtf8());
    file.close();
    StudyProtocol protocol;
    LoadError loadError;
    QVERIFY2(StudyProtocol::read(protocolPath, &protocol, &loadError),
             qPrintable(loadError.toString()));
    QString error;
    auto study =
        StudyDatabase::create(dir.filePath(QStringLiteral("attitude.db")), protocol, &error);
    QVERIFY2(study, qPrintable(error));
    const StudyTable attitude = readTable(data("attitude.csv"));
    for (const StudyTable::Row &row : attitude.rows()) {
        if (!study->participants().contains(row.participant))
            QVERIFY(study->addParticipant(row.participant, &error));
        const StudyProtocol::Step step{StudyProtocol::Step::Kind::Trial,
                                       protocol.conditionIndex(row.condition), 1};
        const qint64 id = study->beginTrial(row.participant, step, dir.filePath("s.db"), &error);
        QVERIFY2(id > 0, qPrintable(error));
        QVERIFY(study->finishTrial(id, 60, {{QStringLiteral("attitude"), row.value}}, &error));
    }
    const StudyAnalysis analysis = StudyAnalysis::run(StudyTable::fromStudy(*study));
    const StudyAnalysis::Measure &m = analysis.measures.front();
    QCOMPARE(m.name, QStringLiteral("attitude"));
    QCOMPARE(m.participants.size(), 20);
    QVERIFY(m.twoWay);
    QVERIFY(published(m.twoWayAnova.a.f, 5.105981, 5e-7));
    QVERIFY(published(m.twoWayAnova.a.sphericity.greenhouseGeisser, 0.5771143, 5e-8));
    QVERIFY(published(m.twoWayAnova.b.f, 122.564825, 5e-7));
    QVERIFY(published(m.twoWayAnova.interaction.f, 17.154922, 5e-7));
    const QString report = QString::fromUtf8(analysis.markdown());
    QVERIFY2(report.contains(QLatin1String("drink: F(1.15, 21.93) = 5.11")), qPrintable(report));
    const QJsonObject twoWay =
        analysis.toJson()[QLatin1String("measures")][0][QLatin1String("two_way_anova")].toObject();
    QCOMPARE(twoWay.keys(), (QStringList{"drink", "drink:imagery", "imagery"}));
}

void TestStudyAnalysis::friedmanAsR()
{
    // R's friedman.test example (Hollander & Wolfe's rounding first base, 22 x 3, with ties):
    // chi-squared = 11.143, df = 2, p = 0.003805; Kendall's W = 11.143 / (22 x 2) = .2532.
    const StudyAnalysis analysis = StudyAnalysis::run(readTable(data("roundingtimes.csv")));
    const StudyAnalysis::Measure &m = analysis.measures.front();
    QCOMPARE(m.friedman.df, 2);
    QVERIFY(published(m.friedman.chiSquared, 11.143, 5e-4));
    QVERIFY(published(m.friedman.p, 0.003805, 5e-7));
    QVERIFY(published(m.friedman.kendallW, 0.2532, 5e-5));
    QVERIFY(QString::fromUtf8(analysis.markdown())
                .contains(QStringLiteral("χ²(2) = 11.14, p = .004, Kendall's W = .253")));
}

void TestStudyAnalysis::nothingToTest()
{
    // A measure with no variance, and one that each participant lacks in a condition.
    const StudyAnalysis analysis =
        StudyAnalysis::run(tableOf("participant,condition,trial,measure,value\n"
                                   "P1,A,1,zero,0\nP1,B,1,zero,0\nP2,A,1,zero,0\nP2,B,1,zero,0\n"
                                   "P3,A,1,zero,0\nP3,B,1,zero,0\nP3,A,1,one,1\nP2,B,1,one,1\n"));
    QCOMPARE(int(analysis.measures.size()), 2);
    QVERIFY(!analysis.measures[0].tested());
    QCOMPARE(analysis.measures[1].participants.size(), 0);
    // Everyone without every condition is named, even those without any value.
    QCOMPARE(analysis.measures[1].excluded, (QStringList{"P1", "P2", "P3"}));
    const QString report = QString::fromUtf8(analysis.markdown());
    QVERIFY(report.contains(QStringLiteral("| zero | 3 | — | not tested")));
    QVERIFY(report.contains(QLatin1String("left out for a missing condition: P1, P2, P3")));
    QVERIFY(report.contains(QStringLiteral("| B | – | – | – | – | not tested |")));
    QVERIFY(!report.contains(QLatin1String("nan")));
}

void TestStudyAnalysis::aMeasureOfSomeConditions()
{
    // Issue 33, D13: "the feedback was realistic" is asked after the conditions with feedback
    // only. It is compared over those three, not left out for everyone for lacking "none".
    QByteArray csv = "participant,condition,trial,measure,value\n";
    for (int p = 1; p <= 8; ++p) {
        for (const char *condition : {"none", "visual", "sensory", "semantic"})
            csv += QStringLiteral("P%1,%2,,tlx,%3\n").arg(p).arg(condition).arg(40 + p).toUtf8();
        csv += QStringLiteral("P%1,visual,,realistic,%2\nP%1,sensory,,realistic,%3\n"
                              "P%1,semantic,,realistic,%4\n")
                   .arg(p)
                   .arg(2 + p % 2)
                   .arg(4 + p % 3)
                   .arg(6 + p % 2)
                   .toUtf8();
    }
    const StudyAnalysis analysis = StudyAnalysis::run(tableOf(csv));
    QCOMPARE(analysis.conditions.size(), 4);
    const StudyAnalysis::Measure &realistic = analysis.measures[1];
    QCOMPARE(realistic.name, QStringLiteral("realistic"));
    QCOMPARE(realistic.participants.size(), 8);
    QVERIFY(realistic.excluded.isEmpty());
    QStringList ids;
    for (const StudyAnalysis::Condition &c : realistic.conditions)
        ids << c.id;
    QCOMPARE(ids, (QStringList{"visual", "sensory", "semantic"}));
    QCOMPARE(realistic.conditions[0].summary.mean, 2.5);
    QVERIFY(realistic.tested());
    QCOMPARE(int(realistic.pairwise.size()), 3);
    // The pairs name the measure's conditions, in JSON and in the report.
    const QJsonArray pairs =
        analysis.toJson()[QLatin1String("measures")][1][QLatin1String("pairwise")].toArray();
    QCOMPARE(pairs.size(), 3);
    for (const QJsonValue &pair : pairs) {
        QVERIFY(ids.contains(pair[QLatin1String("first")].toString()));
        QVERIFY(ids.contains(pair[QLatin1String("second")].toString()));
    }
    const QString report = QString::fromUtf8(analysis.markdown());
    QVERIFY2(report.contains(QStringLiteral("visual–semantic (p = ")), qPrintable(report));
    QCOMPARE(int(analysis.measures[0].conditions.size()), 4);
}

void TestStudyAnalysis::namesFromOtherTools()
{
    // R or a spreadsheet names conditions as people read them, even with a pipe; pandas
    // writes a trial column with empty cells as floats.
    QByteArray csv = "participant,condition,trial,measure,value\n";
    for (int p = 1; p <= 6; ++p)
        csv += QStringLiteral("P%1,No feedback,1.0,time on task,%2\nP%1,\"Haptic | visual\",1,"
                              "time on task,%3\n")
                   .arg(p)
                   .arg(10 + p)
                   .arg(8 + p * p % 5)
                   .toUtf8();
    const StudyAnalysis analysis = StudyAnalysis::run(tableOf(csv));
    QCOMPARE(analysis.conditions, (QStringList{"No feedback", "Haptic | visual"}));
    const QString report = QString::fromUtf8(analysis.markdown());
    QVERIFY(report.contains(QLatin1String("| Haptic \\| visual |")));
    const QString plot = StudyAnalysis::plotFile(QStringLiteral("time on task"));
    QVERIFY(plot.startsWith(QLatin1String("time_on_task-")));
    QVERIFY(plot != StudyAnalysis::plotFile(QStringLiteral("time_on task")));
    QCOMPARE(StudyAnalysis::plotFile(QStringLiteral("cubes_transferred")),
             QStringLiteral("cubes_transferred.svg"));
}

void TestStudyAnalysis::aRankingTakesRankTests()
{
    // Twelve participants rank three conditions; the ranks would pass Shapiro-Wilk in each
    // condition often enough, but ranks are for rank tests.
    QByteArray csv = "participant,condition,trial,measure,value\n";
    const int orders[6][3] = {{1, 2, 3}, {1, 3, 2}, {2, 1, 3}, {1, 2, 3}, {2, 3, 1}, {1, 2, 3}};
    for (int p = 0; p < 12; ++p) {
        for (int c = 0; c < 3; ++c)
            csv += QStringLiteral("P%1,%2,,rank,%3\n")
                       .arg(p)
                       .arg(QChar('A' + c))
                       .arg(orders[p % 6][c])
                       .toUtf8();
    }
    const StudyAnalysis analysis = StudyAnalysis::run(tableOf(csv));
    const StudyAnalysis::Measure &m = analysis.measures.front();
    QVERIFY(m.ranking);
    QVERIFY(!m.normal);
    QCOMPARE(m.pairedTest, PairedTest::SignedRank);
    QVERIFY(analysis.markdown().contains("| rank | 12 | Friedman | "));
}

void TestStudyAnalysis::hugeValuesPlotInBoundedWork()
{
    // Values two doubles apart at 1e17: no step of the axis fits between them.
    const StudyAnalysis analysis = StudyAnalysis::run(
        tableOf("participant,condition,trial,measure,value\n"
                "P1,A,1,big,1e17\nP1,B,1,big,100000000000000016\n"
                "P2,A,1,big,1e17\nP2,B,1,big,1e17\nP3,A,1,big,100000000000000016\n"
                "P3,B,1,big,1e17\n"));
    const QByteArray svg = analysis.boxPlotSvg(analysis.measures.front());
    QVERIFY(svg.size() < 20000);
    QVERIFY(svg.count("<line") < 40);
}

void TestStudyAnalysis::badCsvIsLocated_data()
{
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<QString>("error");
    const QByteArray header = "participant,condition,trial,measure,value\n";
    QTest::newRow("empty") << QByteArray() << ":1:1: empty";
    QTest::newRow("another header") << QByteArray("subject,condition,trial,measure,value\n")
                                    << ":1:1: the header must be exactly";
    QTest::newRow("four fields") << header + "P1,A,1,x\n"
                                 << ":2:1: expected 5 fields, got 4";
    QTest::newRow("a bad trial") << header + "P1,A,first,x,1\n"
                                 << ":2:6: trial must be a whole number";
    QTest::newRow("a bad value") << header + "P1,A,1,x,1\nP1,B,1,x,lots\n"
                                 << ":3:10: value must be a number, empty or NA, got 'lots'";
    QTest::newRow("a line break in a name") << header + "\"P\n1\",A,1,x,1\n"
                                            << ":2:1: participant must be 1 to 200 characters";
    QTest::newRow("a blank condition") << header + "P1,  ,1,x,1\n"
                                       << ":2:4: condition must be 1 to 200 characters";
    QTest::newRow("an open quote") << header + "P1,A,1,\"x,1\n"
                                   << ":3:1: a quoted field never ends";
    QTest::newRow("infinity") << header + "P1,A,1,x,inf\n"
                              << ":2:10: value must be a number";
}

void TestStudyAnalysis::badCsvIsLocated()
{
    QFETCH(QByteArray, text);
    QFETCH(QString, error);
    StudyTable table;
    LoadError loadError;
    QVERIFY(!StudyTable::parseCsv(text, QStringLiteral("bad.csv"), &table, &loadError));
    QVERIFY2(loadError.toString().startsWith(QStringLiteral("bad.csv") + error),
             qPrintable(loadError.toString()));
}

QTEST_GUILESS_MAIN(TestStudyAnalysis)
#include "tst_studyanalysis.moc"
