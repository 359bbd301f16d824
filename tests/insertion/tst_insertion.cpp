// SPDX-License-Identifier: MIT
// usb_insertion: the scene's signals are on the right frames, the task counts a collision
// and an insertion when a test driver makes them and lays the scene out again by the seed
// (`semhap run` and `compare` on the scene: tests/simrun).
#include "insertiontask.h"
#include "nametable.h"
#include "operator.h"
#include "personparameters.h"
#include "task.h"
#include "tasktype.h"
#include "world.h"

#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <functional>

using namespace semhap;

namespace {

std::unique_ptr<World> loadScene()
{
    QString error;
    std::unique_ptr<World> world = World::load("usb_insertion", SceneOptions{}, &error);
    if (!world)
        qFatal("%s", qPrintable(error));
    return world;
}

double signalOf(const World &world, const char *name)
{
    const double *value =
        world.frame(Gripper::Right).signalValues.find(signalNames().find(QString(name)));
    return value ? *value : std::nan("");
}

double yawOf(const std::array<double, 4> &q)
{
    return std::atan2(2 * (q[1] * q[2] + q[0] * q[3]), 1 - 2 * (q[2] * q[2] + q[3] * q[3]));
}

/** Drives the right wrist: a linear move to `to` turned to `yaw`, stepping world and task. */
void moveTo(World &world, Task &task, const std::array<double, 3> &to, double yaw, double seconds)
{
    const Pose from = world.target(Gripper::Right);
    const int steps = int(std::lround(seconds / world.timestep()));
    for (int k = 1; k <= steps; ++k) {
        Pose p;
        for (size_t i = 0; i < 3; ++i)
            p.pos[i] = from.pos[i] + (to[i] - from.pos[i]) * k / steps;
        p.quat = yawQuaternion(yaw);
        world.setTarget(Gripper::Right, p);
        world.step();
        task.observe(world);
    }
}

/**
 * Lowers the held plug at 1 cm/s, the target never more than 0.1 mm below the wrist (a
 * gentle push), until `done` or 4 s have passed.
 */
void lower(World &world, Task &task, const std::function<bool()> &done)
{
    for (int k = 0; k < 2000 && !done(); ++k) {
        Pose p = world.target(Gripper::Right);
        p.pos[2] = std::max(p.pos[2] - 0.01 * world.timestep(),
                            world.gripperPose(Gripper::Right).pos[2] - 0.0001);
        world.setTarget(Gripper::Right, p);
        world.step();
        task.observe(world);
    }
}

} // namespace

class TestInsertion : public QObject
{
    Q_OBJECT

private slots:
    void signalsAreOnTheFrames();
    void seedLaysTheSceneOut();
    void taskCountsACollisionAndAnInsertion();
    void onlyItsOperators();
    void unknownTask();
};

void TestInsertion::signalsAreOnTheFrames()
{
    std::unique_ptr<World> world = loadScene();
    QCOMPARE(world->taskName(), QString("usb_insertion"));
    QCOMPARE(world->signalNames(Gripper::Right),
             (QStringList{"plug.lateral", "plug.angle", "plug.depth", "plug.force"}));
    world->step();
    QCOMPARE(world->frame(Gripper::Right).signalValues.size(), 4);
    // Standing on the table (0.5 mm above it as laid out), its tip is 24.5 mm below the
    // port's face, 20 cm from the port's axis, and nothing pushes on the port.
    QVERIFY(std::abs(signalOf(*world, "plug.depth") - 0.0245) < 1e-4);
    QVERIFY(std::abs(signalOf(*world, "plug.lateral") - 0.2) < 1e-4);
    QCOMPARE(signalOf(*world, "plug.angle"), 0.0);
    QCOMPARE(signalOf(*world, "plug.force"), 0.0);
}

void TestInsertion::seedLaysTheSceneOut()
{
    const auto layout = [](std::uint64_t seed) {
        std::unique_ptr<World> world = loadScene();
        QString error;
        const std::unique_ptr<Task> task = makeTask(*world, seed, 0.25, DefaultHorizon, &error);
        if (!task)
            qFatal("%s", qPrintable(error));
        const Pose mouth = *world->sitePose("port.mouth");
        const Pose plug = world->objectPose(world->objectIndex("plug"));
        return std::array<double, 6>{mouth.pos[0], mouth.pos[1], yawOf(mouth.quat),
                                     plug.pos[0],  plug.pos[1],  yawOf(plug.quat)};
    };
    const std::array<double, 6> one = layout(1);
    QCOMPARE(layout(1), one);
    QVERIFY(layout(2) != one);
    // Within ±3 cm and ±20 degrees of where the scene puts them.
    QVERIFY(std::abs(one[0] - 0.1) <= InsertionTask::Scatter && std::abs(one[1]) <= 0.03);
    QVERIFY(std::abs(one[3] + 0.1) <= InsertionTask::Scatter && std::abs(one[4]) <= 0.03);
    QVERIFY(std::abs(one[2]) <= InsertionTask::MaxYaw &&
            std::abs(one[5]) <= InsertionTask::MaxYaw);
}

void TestInsertion::taskCountsACollisionAndAnInsertion()
{
    std::unique_ptr<World> world = loadScene();
    QString error;
    const std::unique_ptr<Task> task = makeTask(*world, 3, 0.25, DefaultHorizon, &error);
    QVERIFY2(task, qPrintable(error));
    const int plug = world->objectIndex("plug");
    const Pose start = world->objectPose(plug);
    const double plugYaw = yawOf(start.quat);

    // Take it from above, the fingers across its thickness, and lift it.
    world->setGrip(Gripper::Right, -20);
    moveTo(*world, *task, {start.pos[0], start.pos[1], 0.2}, plugYaw, 1.0);
    moveTo(*world, *task, {start.pos[0], start.pos[1], start.pos[2] + 0.074}, plugYaw, 1.0);
    for (int k = 1; k <= 250; ++k) {
        world->setGrip(Gripper::Right, 25.0 * k / 250);
        world->step();
        task->observe(*world);
    }
    moveTo(*world, *task, {start.pos[0], start.pos[1], 0.2}, plugYaw, 0.8);
    QCOMPARE(task->metrics().value("plug_pickups").toInt(), 1);

    // Over the port, turned to it, the tip 1 cm above the face and 1.5 mm off its axis.
    const Pose mouth = *world->sitePose("port.mouth");
    const double portYaw = yawOf(mouth.quat);
    const double handYaw = yawOf(world->gripperPose(Gripper::Right).quat) + portYaw -
                           yawOf(world->objectPose(plug).quat);
    const auto overTheAxis = [&](double off, double above) {
        // Turn first, then place by where the tip is in the hand.
        const Pose wrist = world->gripperPose(Gripper::Right);
        const Pose tip = *world->sitePose("plug.tip");
        return std::array<double, 3>{
            mouth.pos[0] + off * std::cos(portYaw) + wrist.pos[0] - tip.pos[0],
            mouth.pos[1] + off * std::sin(portYaw) + wrist.pos[1] - tip.pos[1],
            mouth.pos[2] + above + wrist.pos[2] - tip.pos[2]};
    };
    moveTo(*world, *task, world->target(Gripper::Right).pos, handYaw, 0.5);
    moveTo(*world, *task, overTheAxis(0.0015, 0.01), handYaw, 1.5);
    moveTo(*world, *task, overTheAxis(0.0015, 0.01), handYaw, 0.5);
    QCOMPARE(task->metrics().value("collisions").toInt(), 0);
    lower(*world, *task, [&] { return signalOf(*world, "plug.force") > 1.0; });
    QVERIFY(signalOf(*world, "plug.lateral") > InsertionTask::Clearance);
    QVERIFY(std::abs(signalOf(*world, "plug.depth")) < 0.001);
    QCOMPARE(task->metrics().value("collisions").toInt(), 1);

    // Back up, onto the axis, and in.
    moveTo(*world, *task, overTheAxis(0.0015, 0.01), handYaw, 0.5);
    moveTo(*world, *task, overTheAxis(0.0, 0.01), handYaw, 0.5);
    moveTo(*world, *task, overTheAxis(0.0, 0.01), handYaw, 0.5);
    QCOMPARE(task->metrics().value("insertions").toInt(), 0);
    lower(*world, *task, [&] { return task->metrics().value("insertions").toInt() > 0; });
    QVERIFY2(signalOf(*world, "plug.depth") > InsertionTask::FullDepth - 0.001,
             qPrintable(QString::number(signalOf(*world, "plug.depth"))));
    const QJsonObject metrics = task->metrics();
    QCOMPARE(metrics.value("insertions").toInt(), 1);
    QCOMPARE(metrics.value("collisions").toInt(), 1);
    QVERIFY(metrics.value("time_to_insert").toDouble() > 1.0);
    QVERIFY(metrics.value("peak_insertion_force").toDouble() > 1.0);

    // Let go and rise: the plug goes back to the table, elsewhere.
    world->setGrip(Gripper::Right, -20);
    moveTo(*world, *task, world->target(Gripper::Right).pos, handYaw, 0.3);
    const auto up = world->target(Gripper::Right).pos;
    moveTo(*world, *task, {up[0], up[1], 0.2}, handYaw, 1.0);
    QVERIFY(signalOf(*world, "plug.lateral") > 0.05);
    QCOMPARE(task->metrics().value("insertions").toInt(), 1);
    QCOMPARE(task->metrics().value("plugs_dropped").toInt(), 0);
}

void TestInsertion::onlyItsOperators()
{
    std::unique_ptr<World> world = loadScene();
    QString error;
    QVERIFY(makeOperator("scripted", *world, 1, 0.25, {}, &error));
    QVERIFY(makeOperator("reactive", *world, 1, 0.25, {}, &error));
    QVERIFY(makeOperator("perceiving", *world, 1, 0.25, {}, &error));
    QVERIFY(!makeOperator("fast_squeeze", *world, 1, 0.25, {}, &error));
    QCOMPARE(error, QString("usb_insertion: the fast_squeeze operator cannot do usb_insertion "
                            "(operators: scripted, reactive, perceiving)"));
}

void TestInsertion::unknownTask()
{
    QTemporaryDir dir;
    QFile in(":/semhap/scenes/usb_insertion.xml");
    QVERIFY(in.open(QIODevice::ReadOnly));
    QByteArray xml = in.readAll();
    xml.replace("data=\"usb_insertion\"", "data=\"juggling\"");
    const QString path = dir.filePath("juggling.xml");
    QFile out(path);
    QVERIFY(out.open(QIODevice::WriteOnly) && out.write(xml) == xml.size());
    out.close();
    QString error;
    std::unique_ptr<World> world = World::load(path, SceneOptions{}, &error);
    QVERIFY2(world, qPrintable(error));
    QVERIFY(!makeTask(*world, 1, 0.25, DefaultHorizon, &error));
    // Every task of the table is named, the cube tasks' row (no name) left out.
    QStringList tasks;
    for (const TaskType &row : TaskType::all()) {
        if (*row.name)
            tasks.append(QLatin1String(row.name));
    }
    QVERIFY(tasks.contains("usb_insertion"));
    QCOMPARE(error, path + ": unknown task 'juggling' (tasks: " + tasks.join(", ") + ")");
}

QTEST_GUILESS_MAIN(TestInsertion)
#include "tst_insertion.moc"
