// SPDX-License-Identifier: MIT
// block_stacking: the task counts levels, a finished tower, a topple and a dropped block when a
// test driver makes them, and puts blocks back as its rules say; its scripted operator
// builds a tower; the row lists the operators it can do.
#include "handplan.h"
#include "operator.h"
#include "personparameters.h"
#include "stackingtask.h"
#include "task.h"
#include "world.h"

#include <QJsonObject>
#include <QTest>

using namespace semhap;

namespace {

struct Run
{
    std::unique_ptr<World> world;
    std::unique_ptr<Task> task;

    Run()
    {
        QString error;
        world = World::load("block_stacking", SceneOptions{}, &error);
        if (!world)
            qFatal("%s", qPrintable(error));
        task = makeTask(*world, 1, 0.25, DefaultHorizon, &error);
        if (!task)
            qFatal("%s", qPrintable(error));
    }
    void step(double seconds, HandPlan *hand = nullptr)
    {
        const int steps = int(std::lround(seconds / world->timestep()));
        for (int k = 0; k < steps; ++k) {
            if (hand)
                hand->apply(*world);
            world->step();
            task->observe(*world);
        }
    }
    int metric(const char *name) const { return task->metrics().value(name).toInt(); }
    std::vector<int> blocks() const { return StackingTask::blocksOf(*world); }
    /** Puts `block` upright at rest on level `level` of the tower. */
    void stack(int block, int level)
    {
        const auto base = StackingTask::base(*world);
        const double size = StackingTask::blockSize(*world, block);
        Pose pose;
        pose.pos = {base[0], base[1], base[2] + size * (level + 0.5) + 0.0005};
        world->setObjectPose(block, pose);
    }
    bool atHome(int block) const
    {
        const auto at = world->objectPosition(block);
        const auto home = world->homePosition(block);
        return std::hypot(at[0] - home[0], at[1] - home[1], at[2] - home[2]) < 0.005;
    }
};

} // namespace

class TestStacking : public QObject
{
    Q_OBJECT

private slots:
    void countsLevelsAndClearsAFinishedTower();
    void countsAToppleAndPutsTheBlockBack();
    void countsABlockLetGoOfBesideTheTower();
    void scriptedOperatorBuildsATower_data();
    void scriptedOperatorBuildsATower();
    void rowListsItsOperators();
};

void TestStacking::countsLevelsAndClearsAFinishedTower()
{
    Run run;
    const std::vector<int> blocks = run.blocks();
    QCOMPARE(int(blocks.size()), 6);
    for (int level = 0; level < StackingTask::Levels; ++level) {
        run.stack(blocks[size_t(level)], level);
        run.step(0.5);
        QCOMPARE(run.metric("blocks_stacked"), level + 1);
    }
    QCOMPARE(run.metric("tallest_tower"), 5);
    QCOMPARE(run.metric("towers_built"), 1);
    QCOMPARE(run.metric("topples"), 0);
    // Finished, it stands while the hand is low (0.3 m: 3 cm above it), and goes back into
    // the pile once the hand has risen clear.
    run.step(1.0);
    QVERIFY(!run.atHome(blocks[0]));
    Pose high = run.world->target(Gripper::Right);
    high.pos[2] = 0.4;
    run.world->setTarget(Gripper::Right, high);
    run.step(1.0);
    for (int level = 0; level < StackingTask::Levels; ++level)
        QVERIFY2(run.atHome(blocks[size_t(level)]), qPrintable(QString::number(level)));
    QCOMPARE(int(StackingTask::tower(*run.world, blocks).size()), 0);
    QCOMPARE(run.metric("topples"), 0); // a cleared tower is no topple
    QCOMPARE(run.metric("blocks_stacked"), 5);
}

void TestStacking::countsAToppleAndPutsTheBlockBack()
{
    Run run;
    const std::vector<int> blocks = run.blocks();
    for (int level = 0; level < 3; ++level) {
        run.stack(blocks[size_t(level)], level);
        run.step(0.5);
    }
    QCOMPARE(run.metric("blocks_stacked"), 3);
    // Knocked off: the top block on the floor beside the tower.
    Pose floor;
    floor.pos = {0.0, -0.2, 0.026};
    run.world->setObjectPose(blocks[2], floor);
    run.step(0.5);
    QCOMPARE(run.metric("topples"), 1);
    QCOMPARE(run.metric("tallest_tower"), 3);
    QVERIFY(!run.atHome(blocks[2]));
    run.step(StackingTask::DropPenalty);
    QVERIFY(run.atHome(blocks[2]));
    QCOMPARE(run.metric("topples"), 1);
    // Stacked again: the level counts again.
    run.stack(blocks[3], 2);
    run.step(0.5);
    QCOMPARE(run.metric("blocks_stacked"), 4);
}

void TestStacking::countsABlockLetGoOfBesideTheTower()
{
    // The hand takes a block from the pile and lets go of it over the floor.
    Run run;
    const int block = run.blocks().front();
    const auto at = run.world->objectPosition(block);
    const double size = StackingTask::blockSize(*run.world, block);
    HandPlan hand(Gripper::Right);
    hand.grip(-20, 0.1);
    hand.move({at[0], at[1], 0.25}, 0.8);
    hand.move({at[0], at[1], at[2] + run.world->padDrop(Gripper::Right, size)}, 0.6);
    hand.grip(25, 0.5);
    hand.wait(0.2);
    hand.move({at[0], at[1], 0.2}, 0.6);
    hand.move({0.0, -0.2, 0.2}, 0.8);
    run.step(3.2, &hand);
    QVERIFY(run.world->isBetween(Gripper::Right, block));
    QCOMPARE(run.metric("blocks_dropped"), 0);
    hand.grip(-20, 0.15);
    run.step(1.0, &hand);
    QCOMPARE(run.metric("blocks_dropped"), 1);
    QCOMPARE(run.metric("blocks_stacked"), 0);
    QVERIFY(run.task->metrics().value("time_per_level").isNull());
    run.step(StackingTask::DropPenalty);
    QVERIFY(run.atHome(block));
}

void TestStacking::scriptedOperatorBuildsATower_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<int>("seed");
    QTest::newRow("scripted 1") << "scripted" << 1;
    QTest::newRow("scripted 2") << "scripted" << 2;
    QTest::newRow("reactive 3") << "reactive" << 3;
}

void TestStacking::scriptedOperatorBuildsATower()
{
    QFETCH(QString, name);
    QFETCH(int, seed);
    Run run;
    QString error;
    const std::unique_ptr<Operator> person =
        makeOperator(name, *run.world, std::uint64_t(seed), 0.25, PersonParameters{}, &error);
    QVERIFY2(person, qPrintable(error));
    QCOMPARE(person->name(), name);
    // 40 s: a tower of five (about 2.8 s a level, measured).
    const int steps = int(std::lround(40.0 / run.world->timestep()));
    for (int k = 0; k < steps; ++k) {
        person->act(*run.world);
        run.world->step();
        run.task->observe(*run.world);
    }
    const QJsonObject metrics = run.task->metrics();
    QCOMPARE(metrics.value("towers_built").toInt(), 1);
    QCOMPARE(metrics.value("tallest_tower").toInt(), 5);
    QVERIFY(metrics.value("blocks_stacked").toInt() >= 5);
    const double perLevel = metrics.value("time_per_level").toDouble();
    QVERIFY2(perLevel > 1.5 && perLevel < 5.0, qPrintable(QString::number(perLevel)));
}

void TestStacking::rowListsItsOperators()
{
    Run run;
    QString error;
    for (const char *name : {"scripted", "reactive", "perceiving"}) {
        QVERIFY2(makeOperator(name, *run.world, 1, 0.25, PersonParameters{}, &error),
                 qPrintable(error));
    }
    QVERIFY(!makeOperator("fast_squeeze", *run.world, 1, 0.25, PersonParameters{}, &error));
    QCOMPARE(error, QString("block_stacking: the fast_squeeze operator cannot do block_stacking "
                            "(operators: scripted, reactive, perceiving)"));
    // Its metrics are the table's, in its row's order.
    QStringList keys = run.task->metrics().keys();
    QStringList specs;
    for (const MetricSpec &spec : StackingTask::metricSpecs())
        specs.append(spec.name);
    keys.sort();
    specs.sort();
    QCOMPARE(keys, specs);
}

QTEST_MAIN(TestStacking)
#include "tst_stacking.moc"
