// SPDX-License-Identifier: MIT
// Study protocols (docs/studies.md): reading and refusing them, and the orders of conditions.
#include "studyprotocol.h"

#include <QDir>
#include <QFile>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

#include <map>
#include <set>

using namespace semhap;

class TestStudy : public QObject
{
    Q_OBJECT

private slots:
    void williamsIsBalanced_data();
    void williamsIsBalanced();
    void williamsFirstRowIsTheTextbooks();
    void randomOrdersAreSeeded();
    void exampleProtocolsRead_data();
    void exampleProtocolsRead();
    void badProtocolsAreRefused_data();
    void badProtocolsAreRefused();
    void factorsMayBeNamedInAnyLanguage();
    void practiceEndsAtItsGoal_data();
    void practiceEndsAtItsGoal();
};

void TestStudy::williamsIsBalanced_data()
{
    QTest::addColumn<int>("scheme");
    QTest::addColumn<int>("conditions");
    QTest::addColumn<int>("rows");
    QTest::addColumn<int>("follows"); // how often each condition follows each other
    for (int n : {2, 4, 6, 8})
        QTest::addRow("williams %d", n) << int(ConditionOrder::Scheme::Williams) << n << n << 1;
    for (int n : {3, 5, 7})
        QTest::addRow("latin %d (odd: with its mirror)", n)
            << int(ConditionOrder::Scheme::Latin) << n << 2 * n << 2;
    QTest::addRow("latin 4 (even: Williams)") << int(ConditionOrder::Scheme::Latin) << 4 << 4 << 1;
}

void TestStudy::williamsIsBalanced()
{
    QFETCH(int, scheme);
    QFETCH(int, conditions);
    QFETCH(int, rows);
    QFETCH(int, follows);
    const ConditionOrder order(ConditionOrder::Scheme(scheme), conditions);
    QCOMPARE(int(order.rows().size()), rows);
    std::map<std::pair<int, int>, int> pairs;
    const size_t n = size_t(conditions);
    std::vector<std::vector<int>> atPosition(n, std::vector<int>(n, 0));
    for (int p = 0; p < rows; ++p) {
        const std::vector<int> row = order.order(p);
        QCOMPARE(std::set<int>(row.begin(), row.end()).size(), size_t(conditions));
        for (int i = 0; i < conditions; ++i) {
            ++atPosition[size_t(i)][size_t(row[size_t(i)])];
            if (i + 1 < conditions)
                ++pairs[{row[size_t(i)], row[size_t(i) + 1]}];
        }
        QCOMPARE(order.order(p + rows), row); // participants cycle through the rows
    }
    // Each condition at each position equally often, and after each other one equally often.
    for (const std::vector<int> &position : atPosition)
        for (int count : position)
            QCOMPARE(count, rows / conditions);
    QCOMPARE(int(pairs.size()), conditions * (conditions - 1));
    for (const auto &[pair, count] : pairs)
        QCOMPARE(count, follows);
}

void TestStudy::williamsFirstRowIsTheTextbooks()
{
    // Williams (1949) for four treatments: A B D C, B C A D, C D B A, D A C B.
    const ConditionOrder order(ConditionOrder::Scheme::Williams, 4);
    const std::vector<std::vector<int>> expected{
        {0, 1, 3, 2}, {1, 2, 0, 3}, {2, 3, 1, 0}, {3, 0, 2, 1}};
    QCOMPARE(order.rows(), expected);
    QVERIFY(!ConditionOrder::accepts(ConditionOrder::Scheme::Williams, 3));
    QVERIFY(ConditionOrder::accepts(ConditionOrder::Scheme::Latin, 3));
}

void TestStudy::randomOrdersAreSeeded()
{
    const ConditionOrder a(ConditionOrder::Scheme::Random, 4, 7);
    const ConditionOrder b(ConditionOrder::Scheme::Random, 4, 7);
    const ConditionOrder c(ConditionOrder::Scheme::Random, 4, 8);
    std::set<std::vector<int>> seen;
    bool differs = false;
    for (int p = 0; p < 24; ++p) {
        const std::vector<int> order = a.order(p);
        QCOMPARE(std::set<int>(order.begin(), order.end()), (std::set<int>{0, 1, 2, 3}));
        QCOMPARE(b.order(p), order);
        differs = differs || c.order(p) != order;
        seen.insert(order);
    }
    QVERIFY(differs);
    QVERIFY(seen.size() > 8); // 24 participants meet many of the 24 orders
}

void TestStudy::exampleProtocolsRead_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<QString>("scene");
    QTest::addColumn<int>("scheme");
    QTest::addColumn<double>("trialSeconds");
    QTest::addColumn<int>("factors");
    // The paper's trials: one minute in box_and_block, two in the bimanual task; its first
    // study crossed grasp and break modality.
    QTest::newRow("comparison") << "comparison.json"
                                << "box_and_block" << int(ConditionOrder::Scheme::Williams) << 60.0
                                << 2;
    QTest::newRow("unimanual") << "unimanual.json"
                               << "box_and_block" << int(ConditionOrder::Scheme::Williams) << 60.0
                               << 0;
    QTest::newRow("bimanual") << "bimanual.json"
                              << "bimanual_sorting" << int(ConditionOrder::Scheme::Latin) << 120.0
                              << 0;
}

void TestStudy::exampleProtocolsRead()
{
    QFETCH(QString, file);
    QFETCH(QString, scene);
    QFETCH(int, scheme);
    QFETCH(double, trialSeconds);
    QFETCH(int, factors);
    StudyProtocol protocol;
    LoadError error;
    QVERIFY2(StudyProtocol::read(QString(SEMHAP_RESOURCES "/studies/") + file, &protocol, &error),
             qPrintable(error.toString()));
    QCOMPARE(protocol.scene, scene);
    QCOMPARE(int(protocol.scheme), scheme);
    QCOMPARE(int(protocol.conditions.size()), 4);
    // The paper's procedure: practice until 10 transfers, two trials.
    QCOMPARE(protocol.practiceTransfers, 10);
    QCOMPARE(protocol.trials, 2);
    QCOMPARE(protocol.trialSeconds, trialSeconds);
    QCOMPARE(int(protocol.factors.size()), factors);
    for (const StudyProtocol::Condition &condition : protocol.conditions)
        QCOMPARE(int(condition.levels.size()), factors);
    QCOMPARE(protocol.afterCondition.front().kind, StudyProtocol::Question::Kind::NasaTlx);
    QCOMPARE(protocol.atTheEnd.front().kind, StudyProtocol::Question::Kind::Ranking);
    QCOMPARE(protocol.atTheEnd.front().conditions.size(), 4);
    // Questions about the feedback are not asked after a condition without any (issue 33,
    // D13); every condition still has its questionnaire.
    for (int c = 0; c < int(protocol.conditions.size()); ++c) {
        QStringList asked;
        for (const StudyProtocol::Question &q : protocol.questionsAfter(c))
            asked << q.id;
        QVERIFY(asked.contains("tlx"));
        QCOMPARE(asked.contains("realistic"), protocol.conditions[size_t(c)].router != "none");
        const std::vector<StudyProtocol::Step> steps = protocol.steps({c});
        QCOMPARE(steps.back().kind, StudyProtocol::Step::Kind::Final);
        QCOMPARE(steps[steps.size() - 2].kind, StudyProtocol::Step::Kind::Questionnaire);
    }
}

void TestStudy::badProtocolsAreRefused_data()
{
    // A protocol written here, edited by replacing text, and the error it must give.
    QTest::addColumn<QString>("from");
    QTest::addColumn<QString>("to");
    QTest::addColumn<QString>("error");
    QTest::newRow("unknown router") << "\"router\": \"C3\""
                                    << "\"router\": \"C9\""
                                    << "/conditions/2/router: C9: no such router preset";
    QTest::newRow("odd Williams")
        << ", {\"id\": \"D\", \"label\": \"D\", \"router\": \"C4\"}"
        << ""
        << "/order/scheme: a Williams design needs an even number of conditions, the protocol "
           "has 3: use 'latin'";
    QTest::newRow("ranking leaves one out")
        << "{\"type\": \"ranking\"}"
        << "{\"type\": \"ranking\", \"conditions\": [\"A\", \"B\", \"D\"]}"
        << "/questionnaires/atTheEnd/0/conditions: leaves out condition 'C'";
    QTest::newRow("ranking twice")
        << "{\"type\": \"ranking\"}"
        << "{\"type\": \"ranking\", \"conditions\": [\"A\", \"B\", \"C\", \"D\", \"D\"]}"
        << "/questionnaires/atTheEnd/0/conditions: names condition 'D' twice";
    QTest::newRow("a trial longer than a day") << "\"seconds\": 60"
                                               << "\"seconds\": 90000"
                                               << "/trials/seconds: must be from 1 to 86400";
    QTest::newRow("no such scene") << "\"box_and_block\""
                                   << "\"box_and_blocks\""
                                   << "/scene: no bundled scene 'box_and_blocks'";
    QTest::newRow("same condition twice") << "\"id\": \"B\""
                                          << "\"id\": \"A\""
                                          << "/conditions/1/id: 'A' is already a condition";
    QTest::newRow("likert without anchors")
        << "\"anchors\": [\"no\", \"yes\"], "
        << ""
        << "/questionnaires/afterCondition/1/anchors: must name "
           "the scale's two ends, got 0";
    QTest::newRow("likert scale of 1") << "\"points\": 7"
                                       << "\"points\": 1"
                                       << "/questionnaires/afterCondition/1/points: must be a "
                                          "whole number from 2 to 11, got 1";
    QTest::newRow("unknown item") << "\"nasa_tlx\""
                                  << "\"sus\""
                                  << "/questionnaires/afterCondition/0/type: must be nasa_tlx, "
                                     "likert, ranking or notes, got 'sus'";
    QTest::newRow("unknown scheme") << "\"williams\""
                                    << "\"balanced\""
                                    << "/order/scheme: must be williams, latin or random";
    QTest::newRow("ranking after a condition")
        << "{\"type\": \"nasa_tlx\"}"
        << "{\"type\": \"ranking\"}"
        << "/questionnaires/afterCondition/0/type: a ranking of the conditions belongs in "
           "atTheEnd";
    QTest::newRow("one measure, two items")
        << "\"id\": \"real\""
        << "\"id\": \"tlx.effort\""
        << "/questionnaires/afterCondition/1: 'tlx.effort' is already a measure";
    QTest::newRow("levels without factors")
        << "\"router\": \"C1\"}"
        << "\"router\": \"C1\", \"levels\": {\"grasp\": \"vib\"}}"
        << "/conditions/0/levels: the protocol declares no factors";
    // In the 2 x 2 factorial version of the protocol (badProtocolsAreRefused's `factorial`).
    QTest::newRow("factorial: a condition outside the factors")
        << ", \"levels\": {\"grasp\": \"vib\", \"break\": \"vib\"}"
        << ""
        << "/conditions/0: missing key 'levels'";
    QTest::newRow("factorial: three factors")
        << "\"factors\": ["
        << "\"factors\": [{\"id\": \"c\", \"levels\": [\"1\", \"2\"]}, "
        << "/factors: at most 2 factors (a two-way design), got 3";
    QTest::newRow("factorial: no such level")
        << "{\"grasp\": \"vib\", \"break\": \"vib\"}"
        << "{\"grasp\": \"heat\", \"break\": \"vib\"}"
        << "/conditions/0/levels/grasp: 'heat' is not a level of 'grasp' (vib, air)";
    QTest::newRow("factorial: one cell twice")
        << "{\"grasp\": \"vib\", \"break\": \"air\"}"
        << "{\"grasp\": \"vib\", \"break\": \"vib\"}"
        << "/conditions/1/levels: the same cell as condition 'A'";
    QTest::newRow("factorial: a cell left empty")
        << "{\"id\": \"break\", \"levels\": [\"vib\", \"air\"]}"
        << "{\"id\": \"break\", \"levels\": [\"vib\", \"air\", \"heat\"]}"
        << "/conditions: the factors cross into 6 cells, the protocol has 4 conditions";
    QTest::newRow("no such gripper")
        << "\"scene\": \"box_and_block\","
        << "\"scene\": \"box_and_block\", \"options\": {\"gripper\": \"claw\"},"
        << "/options/gripper: no gripper adapter 'claw'";
    QTest::newRow("an item named as a task metric")
        << "\"id\": \"real\""
        << "\"id\": \"cubes_transferred\""
        << "/questionnaires/afterCondition/1: 'cubes_transferred' is the name of a task metric";
    QTest::newRow("a scene file that is no scene") << "\"box_and_block\""
                                                   << "\"protocol.json\""
                                                   << "/scene: ";
    QTest::newRow("asked after a condition it does not have")
        << "\"id\": \"real\","
        << "\"id\": \"real\", \"conditions\": [\"B\", \"E\"],"
        << "/questionnaires/afterCondition/1/conditions/1: 'E' is not a condition of the protocol";
    QTest::newRow("asked after a condition twice")
        << "\"id\": \"real\","
        << "\"id\": \"real\", \"conditions\": [\"B\", \"B\"],"
        << "/questionnaires/afterCondition/1/conditions/1: names condition 'B' twice";
    QTest::newRow("asked after no condition")
        << "\"id\": \"real\","
        << "\"id\": \"real\", \"conditions\": [],"
        << "/questionnaires/afterCondition/1/conditions: names no condition";
    QTest::newRow("a final item after some conditions")
        << "\"atTheEnd\": [{\"type\": \"ranking\"}"
        << "\"atTheEnd\": [{\"type\": \"ranking\"}, {\"type\": \"notes\", \"conditions\": "
           "[\"A\"]}"
        << "/questionnaires/atTheEnd/1/conditions: only an afterCondition item is asked after "
           "some conditions";
    QTest::newRow("no trials") << "\"trials\""
                               << "\"trial\""
                               << "unknown key 'trial'";
}

void TestStudy::badProtocolsAreRefused()
{
    QFETCH(QString, from);
    QFETCH(QString, to);
    QFETCH(QString, error);
    QString text = QStringLiteral(R"({"format": "semhap.study/1", "name": "test",
        "scene": "box_and_block",
        "conditions": [{"id": "A", "label": "A", "router": "C1"}, {"id": "B", "label": "B", "router": "C2"},
                       {"id": "C", "label": "C", "router": "C3"}, {"id": "D", "label": "D", "router": "C4"}],
        "order": {"scheme": "williams"},
        "trials": {"count": 2, "seconds": 60},
        "questionnaires": {
          "afterCondition": [{"type": "nasa_tlx"},
                             {"type": "likert", "id": "real", "text": "Real?", "anchors": ["no", "yes"], "points": 7}],
          "atTheEnd": [{"type": "ranking"}]}})");
    if (QString::fromUtf8(QTest::currentDataTag()).startsWith(QLatin1String("factorial"))) {
        // The paper's first study: grasp and break modality crossed.
        text.replace(QLatin1String("\"order\""),
                     QLatin1String("\"factors\": [{\"id\": \"grasp\", \"levels\": [\"vib\", "
                                   "\"air\"]}, {\"id\": \"break\", \"levels\": [\"vib\", "
                                   "\"air\"]}], \"order\""));
        const char *cells[] = {"vib\", \"break\": \"vib", "vib\", \"break\": \"air",
                               "air\", \"break\": \"vib", "air\", \"break\": \"air"};
        for (int c = 0; c < 4; ++c) {
            const QString router = QStringLiteral("\"router\": \"C%1\"").arg(c + 1);
            text.replace(router, router + QStringLiteral(", \"levels\": {\"grasp\": \"%1\"}")
                                              .arg(QLatin1String(cells[c])));
        }
    }
    QVERIFY2(text.contains(from), qPrintable(from));
    text.replace(from, to);
    QTemporaryDir dir;
    const QString path = dir.filePath("protocol.json");
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(text.toUtf8());
    file.close();
    StudyProtocol protocol;
    LoadError loadError;
    QVERIFY(!StudyProtocol::read(path, &protocol, &loadError));
    QVERIFY2(loadError.toString().contains(path + ": " + error) ||
                 loadError.toString().contains(error),
             qPrintable(loadError.toString()));
}

void TestStudy::factorsMayBeNamedInAnyLanguage()
{
    QTemporaryDir dir;
    QFile file(dir.filePath(QStringLiteral("stärke.json")));
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(
        QStringLiteral(R"({"format": "semhap.study/1", "name": "Stärke", "scene": "box_and_block",
        "factors": [{"id": "Stärke", "levels": ["schwach", "stark"]}],
        "conditions": [{"id": "A", "label": "A", "router": "C1", "levels": {"Stärke": "schwach"}},
                       {"id": "B", "label": "B", "router": "C2", "levels": {"Stärke": "stark"}}],
        "trials": {"count": 1, "seconds": 10}})")
            .toUtf8());
    file.close();
    StudyProtocol protocol;
    LoadError error;
    QVERIFY2(StudyProtocol::read(file.fileName(), &protocol, &error),
             qPrintable(error.toString()));
    QCOMPARE(protocol.conditions[1].levels, QStringList{QStringLiteral("stark")});
}

void TestStudy::practiceEndsAtItsGoal_data()
{
    QTest::addColumn<int>("goal");       // transfers; 0: none
    QTest::addColumn<double>("limit");   // seconds; 0: none
    QTest::addColumn<int>("transfers");  // so far
    QTest::addColumn<double>("seconds"); // so far
    QTest::addColumn<bool>("done");
    QTest::newRow("the transfers reached") << 10 << 300.0 << 10 << 42.0 << true;
    QTest::newRow("short of both") << 10 << 300.0 << 9 << 299.9 << false;
    QTest::newRow("the time is up") << 10 << 300.0 << 3 << 300.0 << true;
    QTest::newRow("transfers only") << 10 << 0.0 << 9 << 5000.0 << false;
    QTest::newRow("time only") << 0 << 300.0 << 50 << 120.0 << false;
}

void TestStudy::practiceEndsAtItsGoal()
{
    QFETCH(int, goal);
    QFETCH(double, limit);
    QFETCH(int, transfers);
    QFETCH(double, seconds);
    QFETCH(bool, done);
    StudyProtocol protocol;
    protocol.practiceTransfers = goal;
    protocol.practiceSeconds = limit;
    // The task's metrics name transfers as docs/metrics.md does.
    const QJsonObject metrics{{"cubes_transferred", transfers}, {"cubes_broken", 1}};
    QCOMPARE(StudyProtocol::transfers(metrics), transfers);
    QCOMPARE(protocol.practiceDone(metrics, seconds), done);
}

QTEST_GUILESS_MAIN(TestStudy)
#include "tst_study.moc"
