// SPDX-License-Identifier: MIT
// The MuJoCo world: scenes load, fingertips report the force they grip with, fragile cubes
// break above their force and not below, contact counts stay steady while an object slides.
#include "driveoperator.h"
#include "nametable.h"
#include "world.h"

#include <QDir>
#include <QTemporaryDir>

#include <thread>

#include <QTest>

#include <cmath>

using namespace semhap;

namespace {

std::unique_ptr<World> loadWorld(const QString &scene, int cubes = -1)
{
    QString error;
    std::unique_ptr<World> world = World::load(scene, SceneOptions{cubes, {}}, &error);
    if (!world)
        qFatal("%s", qPrintable(error));
    return world;
}

/** Moves the right gripper's target linearly to `to` over `seconds`, stepping the world. */
void moveTo(World &world, Gripper g, const std::array<double, 3> &to, double seconds)
{
    const Pose from = world.target(g);
    const int steps = int(std::lround(seconds / world.timestep()));
    for (int k = 1; k <= steps; ++k) {
        Pose p = from;
        for (int i = 0; i < 3; ++i)
            p.pos[size_t(i)] =
                from.pos[size_t(i)] + (to[size_t(i)] - from.pos[size_t(i)]) * k / steps;
        world.setTarget(g, p);
        world.step();
    }
}

void hold(World &world, double seconds)
{
    const int steps = int(std::lround(seconds / world.timestep()));
    for (int k = 0; k < steps; ++k)
        world.step();
}

/** Ramps the grip from its current command to `force` over `seconds`. */
void rampGrip(World &world, Gripper g, double force, double seconds)
{
    const double from = world.grip(g);
    const int steps = int(std::lround(seconds / world.timestep()));
    for (int k = 1; k <= steps; ++k) {
        world.setGrip(g, from + (force - from) * k / steps);
        world.step();
    }
}

/** Puts the right gripper's pads around a cube (gripper origin 6 cm above the pad centre). */
void graspCube(World &world, double force, int object = 0)
{
    const auto cube = world.objectPosition(object);
    world.setGrip(Gripper::Right, -10);
    moveTo(world, Gripper::Right, {cube[0], cube[1], cube[2] + 0.2}, 0.6);
    moveTo(world, Gripper::Right, {cube[0], cube[1], cube[2] + 0.06}, 0.6);
    hold(world, 0.2);
    rampGrip(world, Gripper::Right, force, 0.3);
    hold(world, 0.3);
}

/**
 * A small scene for the signals: a right gripper far away, sites a (at 0 0 0.5), b (3 cm
 * along a's x), c (at a, turned 90 degrees about z), a 200 g box resting on the floor with a
 * touch site under it, a ball falling from 2 m, a framepos sensor of b; `custom` is the
 * <custom> element's content.
 */
QByteArray signalScene(const QString &custom)
{
    return QStringLiteral(R"(<mujoco>
  <compiler autolimits="true"/>
  <option timestep="0.002"/>
  <custom>%1</custom>
  <worldbody>
    <geom name="floor" type="plane" size="1 1 0.1"/>
    <site name="a" pos="0 0 0.5"/>
    <site name="b" pos="0.03 0 0.5"/>
    <site name="c" pos="0 0 0.5" euler="0 0 90"/>
    <body name="box" pos="0.3 0 0.02">
      <freejoint/>
      <geom type="box" size="0.02 0.02 0.02" mass="0.2"/>
      <site name="under" type="box" pos="0 0 -0.02" size="0.021 0.021 0.002"/>
    </body>
    <body name="ball" pos="-0.3 0 2">
      <freejoint/>
      <geom type="sphere" size="0.01" mass="0.1" contype="0" conaffinity="0"/>
    </body>
    <body name="right.target" mocap="true" pos="0 0.5 0.5"/>
    <body name="right.gripper" pos="0 0.5 0.5">
      <freejoint/>
      <geom type="box" size="0.01 0.01 0.01" mass="0.1" contype="0" conaffinity="0"/>
      <body name="finger.left"><joint name="sl" type="slide" axis="0 1 0" range="0 0.01"/>
        <geom type="box" size="0.005 0.005 0.005" mass="0.01" contype="0" conaffinity="0"/>
      </body>
      <body name="finger.right"><joint name="sr" type="slide" axis="0 -1 0" range="0 0.01"/>
        <geom type="box" size="0.005 0.005 0.005" mass="0.01" contype="0" conaffinity="0"/>
      </body>
    </body>
  </worldbody>
  <equality><weld body1="right.gripper" body2="right.target"/></equality>
  <actuator>
    <motor name="right.grip.left" joint="sl" ctrlrange="-20 20"/>
    <motor name="right.grip.right" joint="sr" ctrlrange="-20 20"/>
  </actuator>
  <sensor>
    <framepos name="bpos" objtype="site" objname="b"/>
    <touch name="weight" site="under"/>
  </sensor>
</mujoco>
)")
        .arg(custom)
        .toUtf8();
}

/** Writes `xml` as scene.xml into `dir`; its path. */
QString writeScene(const QTemporaryDir &dir, const QByteArray &xml)
{
    const QString path = dir.filePath("scene.xml");
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(xml) != xml.size())
        qFatal("cannot write %s", qPrintable(path));
    return path;
}

QString signalText(const QString &name, const QString &data)
{
    return QStringLiteral("<text name=\"%1\" data=\"%2\"/>").arg(name, data);
}

} // namespace

class TestWorld : public QObject
{
    Q_OBJECT

private slots:
    void scenesLoad_data();
    void scenesLoad();
    void cubeCount();
    void badScenes_data();
    void badScenes();
    void includesResolveFromTheScenesFolder_data();
    void includesResolveFromTheScenesFolder();
    void squeezeReportsForce_data();
    void squeezeReportsForce();
    void fragileCubeBreaksAboveItsForce_data();
    void fragileCubeBreaksAboveItsForce();
    void liftHoldsOrSlips_data();
    void liftHoldsOrSlips();
    void countFallsRowByRowWhileSliding();
    void manualInputDrivesTheGripper();
    void guardedMoveStopsOnWhatIsBelow_data();
    void guardedMoveStopsOnWhatIsBelow();
    void sceneStateRoundTrip_data();
    void sceneStateRoundTrip();
    void restingCubesSleepUntilTouched();
    void clearanceBelowThePads_data();
    void clearanceBelowThePads();
    void signalsFromMjcf_data();
    void signalsFromMjcf();
    void signalsKeepTheirOrder();
    void badSignals_data();
    void badSignals();
};

void TestWorld::scenesLoad_data()
{
    QTest::addColumn<QString>("scene");
    QTest::addColumn<bool>("left");
    QTest::addColumn<int>("objects");
    QTest::newRow("box_and_block") << "box_and_block" << false << 12;
    QTest::newRow("bimanual_sorting") << "bimanual_sorting" << true << 13;
}

void TestWorld::scenesLoad()
{
    QFETCH(QString, scene);
    QFETCH(bool, left);
    QFETCH(int, objects);
    std::unique_ptr<World> world = loadWorld(scene);
    QVERIFY(world->hasGripper(Gripper::Right));
    QCOMPARE(world->hasGripper(Gripper::Left), left);
    QCOMPARE(int(world->objects().size()), objects);
    QCOMPARE(world->timestep(), 0.002);
    world->step();
    QCOMPARE(world->frame(Gripper::Right).t, 0.0);
    QCOMPARE(world->frame(Gripper::Right).left.n, 0);
}

void TestWorld::cubeCount()
{
    QCOMPARE(loadWorld("box_and_block", 3)->objects().size(), size_t(3));
    QCOMPARE(loadWorld("box_and_block", 24)->objects().size(), size_t(24));
    QCOMPARE(loadWorld("box_and_block", 0)->objects().size(), size_t(0));
    const std::unique_ptr<World> world = loadWorld("box_and_block", 2);
    QCOMPARE(world->objects()[1].name, QString("cube_1"));
    QCOMPARE(world->objects()[1].fragileForce, 120.0);
}

void TestWorld::badScenes_data()
{
    QTest::addColumn<QString>("scene");
    QTest::addColumn<int>("cubes");
    QTest::addColumn<QString>("error");
    QTest::newRow("unknown name") << "box_and_blocks" << -1
                                  << "box_and_blocks: no such scene (scenes: " +
                                         World::builtinScenes().join(", ") + ")";
    QTest::newRow("too many cubes")
        << "box_and_block" << 30 << "box_and_block: asked for 30 cubes, the scene has 24";
    QTest::newRow("missing file") << "/nonexistent/scene.xml" << -1
                                  << "/nonexistent/scene.xml: cannot read: No such file or "
                                     "directory";
    // Grips in newtons need force motors on the finger joints.
    static QTemporaryDir dir;
    QFile bundled(":/semhap/scenes/box_and_block.xml");
    bundled.open(QIODevice::ReadOnly);
    const QByteArray xml = bundled.readAll();
    const QByteArray motor = R"(<motor name="right.grip.left" joint="right.slide.left" gear="1")";
    const auto edited = [&](const char *file, const QByteArray &actuator) {
        QByteArray scene = xml;
        scene.replace(motor, actuator);
        const QString path = dir.filePath(file);
        QFile out(path);
        out.open(QIODevice::WriteOnly);
        out.write(scene);
        return path;
    };
    const QString servo = edited(
        "servo.xml", R"(<position name="right.grip.left" joint="right.slide.left" kp="100")");
    QTest::newRow("a position servo for a grip")
        << servo << -1
        << servo + ": actuator right.grip.left must be a motor on its finger's joint, force in "
                   "N closing (see sim/README.md): it is a servo (it has a bias: a position or "
                   "velocity actuator)";
    const QString affine =
        edited("affine.xml", R"(<general name="right.grip.left" joint="right.slide.left" )"
                             R"(gaintype="affine" gainprm="1 0 -50")");
    QTest::newRow("a grip whose gain follows the finger")
        << affine << -1
        << affine + ": actuator right.grip.left must be a motor on its finger's joint, force "
                    "in N closing (see sim/README.md): its gain is not fixed";
}

void TestWorld::badScenes()
{
    QFETCH(QString, scene);
    QFETCH(int, cubes);
    QFETCH(QString, error);
    QString message;
    QVERIFY(!World::load(scene, SceneOptions{cubes, {}}, &message));
    QCOMPARE(message, error);
}

void TestWorld::includesResolveFromTheScenesFolder_data()
{
    QTest::addColumn<int>("cubes");
    QTest::newRow("the declared cubes") << -1;
    QTest::newRow("--cubes 4 (compiled from memory)") << 4;
}

void TestWorld::includesResolveFromTheScenesFolder()
{
    // A user's scene keeps its assets in an <include> beside it, and declares semhap:cubes;
    // it is run from another folder. Every way of loading it resolves the include against the
    // scene's folder (the in-memory compile did so against the current folder).
    QFETCH(int, cubes);
    QFile bundled(":/semhap/scenes/box_and_block.xml");
    QVERIFY(bundled.open(QIODevice::ReadOnly));
    QByteArray xml = bundled.readAll();
    const int from = int(xml.indexOf("  <asset>"));
    const int to = int(xml.indexOf("  </asset>")) + int(qstrlen("  </asset>\n"));
    QVERIFY(from > 0 && to > from);
    QTemporaryDir dir;
    QVERIFY(QDir(dir.path()).mkpath("parts"));
    QFile include(dir.filePath("parts/assets.xml"));
    QVERIFY(include.open(QIODevice::WriteOnly));
    include.write("<mujoco>\n" + xml.mid(from, to - from) + "</mujoco>\n");
    include.close();
    xml.replace(from, to - from, "  <include file=\"parts/assets.xml\"/>\n");
    const QString path = writeScene(dir, xml);
    QTemporaryDir elsewhere;
    const QString was = QDir::currentPath();
    QVERIFY(QDir::setCurrent(elsewhere.path()));
    QString error;
    const std::unique_ptr<World> world = World::load(path, SceneOptions{cubes, {}}, &error);
    QVERIFY(QDir::setCurrent(was));
    QVERIFY2(world, qPrintable(error));
}

void TestWorld::squeezeReportsForce_data()
{
    QTest::addColumn<double>("force");
    QTest::newRow("20 N") << 20.0;
    QTest::newRow("40 N") << 40.0;
    QTest::newRow("80 N") << 80.0;
}

void TestWorld::squeezeReportsForce()
{
    QFETCH(double, force);
    std::unique_ptr<World> world = loadWorld("box_and_block", 1);
    graspCube(*world, force);
    const ContactFrame &frame = world->frame(Gripper::Right);
    qDebug() << "F" << frame.totalForce() << "n" << frame.left.n << frame.right.n << "actor"
             << frame.left.actor << frame.right.actor;
    QVERIFY(std::abs(frame.totalForce() - force) < 0.05 * force);
    // The command is the total of both fingers: each pad presses with half, along the grip
    // axis (y of the gripper frame), and the cube knows its friction.
    for (const Fingertip *tip : {&frame.left, &frame.right}) {
        QVERIFY2(std::abs(tip->f - force / 2) < 0.05 * force / 2,
                 qPrintable(QString::number(tip->f)));
        QVERIFY(std::abs(std::abs(tip->fxyz[1]) - tip->f) < 0.05 * tip->f);
        QCOMPARE(tip->mu, world->objects()[0].friction);
    }
    QCOMPARE(frame.left.n, 16);
    QCOMPARE(frame.right.n, 16);
    QCOMPARE(frame.left.actor, world->objects()[0].actor);
    QCOMPARE(frame.right.actor, world->objects()[0].actor);
}

void TestWorld::fragileCubeBreaksAboveItsForce_data()
{
    QTest::addColumn<double>("force");
    QTest::addColumn<bool>("breaks");
    QTest::newRow("110 N holds") << 110.0 << false;
    QTest::newRow("130 N breaks") << 130.0 << true;
}

void TestWorld::fragileCubeBreaksAboveItsForce()
{
    QFETCH(double, force);
    QFETCH(bool, breaks);
    std::unique_ptr<World> world = loadWorld("box_and_block", 1);
    graspCube(*world, force);
    QCOMPARE(world->objects()[0].broken, breaks);
    if (breaks) {
        QVERIFY(world->objectPosition(0)[2] < -1.0);
        QCOMPARE(world->frame(Gripper::Right).left.n, 0);
    }
}

void TestWorld::liftHoldsOrSlips_data()
{
    QTest::addColumn<double>("force");
    QTest::addColumn<bool>("lifted");
    // The cube weighs 0.08 kg at mu = 0.1: it needs about 8 N of grip.
    QTest::newRow("30 N lifts") << 30.0 << true;
    QTest::newRow("12 N lifts") << 12.0 << true;
    QTest::newRow("5 N slips") << 5.0 << false;
}

void TestWorld::liftHoldsOrSlips()
{
    QFETCH(double, force);
    QFETCH(bool, lifted);
    std::unique_ptr<World> world = loadWorld("box_and_block", 1);
    graspCube(*world, force);
    const double z0 = world->objectPosition(0)[2];
    const auto target = world->target(Gripper::Right).pos;
    moveTo(*world, Gripper::Right, {target[0], target[1], target[2] + 0.1}, 0.8);
    hold(*world, 0.5);
    const double rise = world->objectPosition(0)[2] - z0;
    QVERIFY2(lifted ? rise > 0.09 : rise < 0.01, qPrintable(QString::number(rise)));
}

void TestWorld::countFallsRowByRowWhileSliding()
{
    // Just under the grip the cube needs: it slides out of the pads. The count must fall a
    // row at a time and never flicker back up for a step (which would reset slip detection).
    std::unique_ptr<World> world = loadWorld("box_and_block", 1);
    graspCube(*world, 20.0);
    QCOMPARE(world->frame(Gripper::Right).totalContacts(), 32);
    const auto target = world->target(Gripper::Right).pos;
    Pose up = world->target(Gripper::Right);
    up.pos[2] = target[2] + 0.1;
    world->setTarget(Gripper::Right, up);
    world->setGrip(Gripper::Right, 6.0);
    QList<int> counts;
    for (int k = 0; k < 400; ++k) {
        world->step();
        const int n = world->frame(Gripper::Right).totalContacts();
        if (counts.isEmpty() || counts.last() != n)
            counts.append(n);
    }
    qDebug() << counts;
    QCOMPARE(counts.last(), 0);
    for (int i = 1; i < counts.size(); ++i)
        QVERIFY2(counts[i] < counts[i - 1], "the count went back up");
}

void TestWorld::manualInputDrivesTheGripper()
{
    // The pose-and-grip input, written from another thread as the studio or a rig would.
    std::unique_ptr<World> world = loadWorld("box_and_block", 1);
    DriveOperator input;
    const auto cube = world->objectPosition(0);
    std::thread rig([&] {
        Pose above;
        above.pos = {cube[0], cube[1], cube[2] + 0.06};
        input.setTarget(Gripper::Right, above);
        input.setGrip(Gripper::Right, -20);
    });
    rig.join();
    for (int k = 0; k < 500; ++k) {
        input.act(*world);
        world->step();
    }
    input.setGrip(Gripper::Right, 30);
    for (int k = 0; k < 400; ++k) {
        input.act(*world);
        world->step();
    }
    const ContactFrame &frame = world->frame(Gripper::Right);
    QVERIFY(std::abs(frame.totalForce() - 30.0) < 1.5);
    QCOMPARE(frame.left.actor, world->objects()[0].actor);
    QCOMPARE(input.name(), QString("drive"));
}

void TestWorld::guardedMoveStopsOnWhatIsBelow_data()
{
    QTest::addColumn<bool>("holding");
    // Open fingers pressed onto a cube's top; a held cube set down on the table.
    QTest::newRow("pads on a cube") << false;
    QTest::newRow("held cube on the table") << true;
}

void TestWorld::guardedMoveStopsOnWhatIsBelow()
{
    // A user holding "down" for two seconds (0.15 m/s, as the drive's full speed): the target
    // would end 30 cm below where the fingers are stopped. The guard keeps the push to what
    // the weld gives over DriveOperator::GuardDepth, and no cube breaks.
    QFETCH(bool, holding);
    std::unique_ptr<World> world = loadWorld("box_and_block", 1);
    const auto cube = world->objectPosition(0);
    const double cubeTop = cube[2] + 0.025;
    DriveOperator input;
    auto drive = [&](const std::array<double, 3> &to, double grip, double seconds) {
        const Pose from = world->target(Gripper::Right);
        const int steps = int(std::lround(seconds / world->timestep()));
        for (int k = 1; k <= steps; ++k) {
            Pose p = from;
            for (size_t i = 0; i < 3; ++i)
                p.pos[i] = from.pos[i] + (to[i] - from.pos[i]) * k / steps;
            input.setTarget(Gripper::Right, p);
            input.setGrip(Gripper::Right, grip);
            input.act(*world);
            world->step();
        }
    };
    if (holding) {
        drive({cube[0], cube[1], cube[2] + 0.2}, -20, 0.6);
        drive({cube[0], cube[1], cube[2] + 0.06}, -20, 0.6);
        drive({cube[0], cube[1], cube[2] + 0.06}, 30, 0.5);
        drive({cube[0], cube[1], cube[2] + 0.16}, 30, 0.6);
        // In the air: what is below is the table, seen through the held cube.
        const DriveStatus carrying = input.status(Gripper::Right);
        QVERIFY(carrying.surface);
        QVERIFY2(*carrying.surface < cube[2] - 0.02,
                 qPrintable(QString::number(*carrying.surface)));
        QVERIFY(!carrying.floor);
    } else {
        drive({cube[0], cube[1], cube[2] + 0.2}, -20, 0.6);
        // Over the cube: the drop line reaches its top.
        const DriveStatus above = input.status(Gripper::Right);
        QVERIFY(above.surface);
        QVERIFY2(std::abs(*above.surface - cubeTop) < 0.003,
                 qPrintable(QString::number(*above.surface)));
    }
    const Pose start = world->target(Gripper::Right);
    const double grip = holding ? 30 : -20;
    double peak = 0.0;
    double settledPush = 0.0;
    double settledWrist = 0.0;
    const int steps = int(std::lround(2.0 / world->timestep()));
    for (int k = 1; k <= steps; ++k) {
        Pose p = start;
        p.pos[2] -= 0.15 * k * world->timestep();
        input.setTarget(Gripper::Right, p);
        input.setGrip(Gripper::Right, grip);
        input.act(*world);
        world->step();
        QVERIFY(world->fractures().empty());
        peak = std::max(peak, world->frame(Gripper::Right).totalForce());
        if (k == steps * 3 / 4)
            settledWrist = world->gripperPose(Gripper::Right).pos[2];
        if (k > steps * 3 / 4)
            settledPush = std::max(settledPush, world->supportForce(Gripper::Right));
    }
    const DriveStatus status = input.status(Gripper::Right);
    QVERIFY(status.floor);
    // The world was given a target at the wrist, not 15 cm under it; the push settled.
    const double wrist = world->gripperPose(Gripper::Right).pos[2];
    QVERIFY(status.target.pos[2] > wrist - 0.001);
    QVERIFY2(settledWrist - wrist < 0.002, qPrintable(QString::number(settledWrist - wrist)));
    QVERIFY2(settledPush < DriveOperator::GuardPush + 0.5,
             qPrintable(QString::number(settledPush)));
    // The impact at full speed is over in a step or two; it is reported, not hidden.
    qInfo("impact peak %.1f N, settled push %.2f N", peak, settledPush);
}

void TestWorld::sceneStateRoundTrip_data()
{
    QTest::addColumn<QString>("scene");
    QTest::newRow("box_and_block") << "box_and_block";
    QTest::newRow("bimanual_sorting") << "bimanual_sorting";
}

void TestWorld::sceneStateRoundTrip()
{
    // What a session records puts a fresh world's bodies where the recorded ones were.
    QFETCH(QString, scene);
    std::unique_ptr<World> recorded = loadWorld(scene);
    QVERIFY(recorded);
    Pose target = recorded->target(Gripper::Right);
    target.pos[2] += 0.05;
    recorded->setTarget(Gripper::Right, target);
    recorded->setGrip(Gripper::Right, 10.0);
    for (int k = 0; k < 400; ++k)
        recorded->step();
    const std::vector<double> state = recorded->sceneState();
    QCOMPARE(int(state.size()), recorded->sceneStateSize());

    std::unique_ptr<World> shown = loadWorld(scene);
    QVERIFY(shown->sceneState() != state);
    QVERIFY(shown->setSceneState(state));
    // Equal but for MuJoCo normalising the quaternions again.
    const std::vector<double> got = shown->sceneState();
    for (size_t i = 0; i < state.size(); ++i)
        QVERIFY2(std::abs(got[i] - state[i]) < 1e-12, qPrintable(QString::number(i)));
    // Body positions are computed at the start of a step: the recorded world's lag its
    // state by one step of motion (< 1 mm).
    const auto near = [](const std::array<double, 3> &a, const std::array<double, 3> &b) {
        return std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) + std::abs(a[2] - b[2]) < 1e-3;
    };
    for (int i = 0; i < int(recorded->objects().size()); ++i)
        QVERIFY(near(shown->objectPosition(i), recorded->objectPosition(i)));
    QVERIFY(
        near(shown->gripperPose(Gripper::Right).pos, recorded->gripperPose(Gripper::Right).pos));
    QVERIFY(near(shown->target(Gripper::Right).pos, target.pos));

    // Another scene's state, or another number of cubes, does not fit.
    std::unique_ptr<World> fewer = loadWorld(scene, 3);
    QVERIFY(!fewer->setSceneState(state));
    QVERIFY(!shown->setSceneState({}));
}

void TestWorld::restingCubesSleepUntilTouched()
{
    // The pile settles and sleeps; reaching for a top cube wakes it and the cube it rests on,
    // the grasp then feels as it does on a cube that never slept, and the rest sleep on.
    std::unique_ptr<World> world = loadWorld("box_and_block");
    hold(*world, 0.5);
    QCOMPARE(world->sleepingObjects(), 12);
    const int top = world->objectIndex("cube_8"); // on cube_0
    const auto before = world->objectPosition(top);
    graspCube(*world, 40.0, top);
    QCOMPARE(world->sleepingObjects(), 10);
    const ContactFrame &frame = world->frame(Gripper::Right);
    QVERIFY(std::abs(frame.totalForce() - 40.0) < 2.0);
    QCOMPARE(frame.left.n, 16);
    QCOMPARE(frame.right.n, 16);
    QCOMPARE(frame.left.actor, world->objects()[size_t(top)].actor);
    // It slept where it came to rest: the grasp found it there.
    QVERIFY(std::abs(world->objectPosition(top)[0] - before[0]) < 0.002);
    const auto target = world->target(Gripper::Right).pos;
    moveTo(*world, Gripper::Right, {target[0], target[1], target[2] + 0.1}, 0.8);
    hold(*world, 0.5);
    QVERIFY(world->objectPosition(top)[2] - before[2] > 0.09);
    QCOMPARE(world->sleepingObjects(), 11); // cube_0, left behind, sleeps again
}

void TestWorld::clearanceBelowThePads_data()
{
    QTest::addColumn<double>("dy");      // the wrist beside the cube (m)
    QTest::addColumn<double>("surface"); // the top of what the right pad is over (m)
    // The right pad, 4.5 cm to the wrist's -y and 1 cm thick, over the cube (5 cm tall) or
    // over the table beside it.
    QTest::newRow("over the cube") << 0.04 << 0.05;
    QTest::newRow("over the table") << 0.12 << 0.0;
}

void TestWorld::clearanceBelowThePads()
{
    QFETCH(double, dy);
    QFETCH(double, surface);
    QString error;
    std::unique_ptr<World> world = World::load("box_and_block", SceneOptions{1, {}}, &error);
    QVERIFY2(world, qPrintable(error));
    const auto cube = world->objectPosition(0);
    Pose target = world->target(Gripper::Right);
    target.pos = {cube[0], cube[1] + dy, 0.16};
    world->setTarget(Gripper::Right, target);
    world->setGrip(Gripper::Right, -20.0);
    for (int k = 0; k < 1000; ++k)
        world->step();
    // The pads' lowest taxels: 7.5 cm below the wrist, 4 mm round, 0.5 mm margin.
    const double pads = world->gripperPose(Gripper::Right).pos[2] - 0.075 - 0.004 - 0.0005;
    const std::optional<double> clearance = world->clearanceBelow(Gripper::Right);
    QVERIFY(clearance);
    QVERIFY2(std::abs(*clearance - (pads - surface)) < 0.001,
             qPrintable(QString("%1 vs %2").arg(*clearance).arg(pads - surface)));
}

void TestWorld::signalsFromMjcf_data()
{
    QTest::addColumn<QString>("data");
    QTest::addColumn<int>("steps");
    QTest::addColumn<double>("value");
    QTest::addColumn<double>("tolerance");
    const double pi = 3.14159265358979323846;
    QTest::newRow("along") << "along a b x" << 1 << 0.03 << 1e-12;
    QTest::newRow("along, across the offset") << "along a b y" << 1 << 0.0 << 1e-12;
    QTest::newRow("across") << "across a b x" << 1 << 0.0 << 1e-12;
    QTest::newRow("across, another axis") << "across a b z" << 1 << 0.03 << 1e-12;
    QTest::newRow("along a turned frame") << "along c b y" << 1 << -0.03 << 1e-9;
    QTest::newRow("distance") << "distance b a" << 1 << 0.03 << 1e-12;
    QTest::newRow("a body") << "distance a box" << 1 << std::hypot(0.3, 0.48) << 1e-6;
    QTest::newRow("angle, a quarter turn") << "angle a x c x" << 1 << pi / 2 << 1e-9;
    QTest::newRow("angle, the same axis") << "angle a z c z" << 1 << 0.0 << 1e-6;
    QTest::newRow("angle, opposite") << "angle a x c y" << 1 << pi << 1e-6;
    // Falling from rest: the frame after step k has the speed after k - 1 steps.
    QTest::newRow("speed") << "speed a ball" << 51 << 9.81 * 0.002 * 50 << 1e-9;
    QTest::newRow("speed, both ways") << "speed ball a" << 51 << 9.81 * 0.002 * 50 << 1e-9;
    QTest::newRow("speed at rest") << "speed a b" << 51 << 0.0 << 1e-12;
    QTest::newRow("sensor, a component") << "sensor bpos x" << 1 << 0.03 << 1e-12;
    QTest::newRow("sensor, an index") << "sensor bpos 2" << 1 << 0.5 << 1e-12;
    QTest::newRow("sensor, a vector's norm")
        << "sensor bpos" << 1 << std::hypot(0.03, 0.5) << 1e-12;
    QTest::newRow("sensor, norm") << "sensor bpos norm" << 1 << std::hypot(0.03, 0.5) << 1e-12;
    // The box rests on the floor (before it would fall asleep, sim/README.md): its weight.
    QTest::newRow("touch under a resting box") << "sensor weight" << 50 << 0.2 * 9.81 << 0.01;
}

void TestWorld::signalsFromMjcf()
{
    QFETCH(QString, data);
    QFETCH(int, steps);
    QFETCH(double, value);
    QFETCH(double, tolerance);
    QTemporaryDir dir;
    const QString path =
        writeScene(dir, signalScene(signalText("signal:right:probe.value", data)));
    QString error;
    std::unique_ptr<World> world = World::load(path, SceneOptions{}, &error);
    QVERIFY2(world, qPrintable(error));
    QCOMPARE(world->signalNames(Gripper::Right), QStringList{"probe.value"});
    for (int k = 0; k < steps; ++k)
        world->step();
    const double *got =
        world->frame(Gripper::Right).signalValues.find(signalNames().find("probe.value"));
    QVERIFY(got);
    QVERIFY2(std::abs(*got - value) <= tolerance,
             qPrintable(QString("%1, expected %2").arg(*got, 0, 'g', 12).arg(value)));
}

void TestWorld::signalsKeepTheirOrder()
{
    QTemporaryDir dir;
    const QString path =
        writeScene(dir, signalScene(signalText("signal:right:zeta", "distance a b") +
                                    signalText("semhap:task", "probing") +
                                    signalText("signal:right:alpha", "along a b x")));
    QString error;
    std::unique_ptr<World> world = World::load(path, SceneOptions{}, &error);
    QVERIFY2(world, qPrintable(error));
    QCOMPARE(world->signalNames(Gripper::Right), (QStringList{"zeta", "alpha"}));
    QCOMPARE(world->signalNames(Gripper::Left), QStringList());
    QCOMPARE(world->taskName(), QString("probing"));
    world->step();
    const FrameSignals &values = world->frame(Gripper::Right).signalValues;
    QCOMPARE(values.size(), 2);
    QCOMPARE(values.begin()->id, signalNames().find("zeta"));
    // Stepping again sets the same signals: none added.
    world->step();
    QCOMPARE(world->frame(Gripper::Right).signalValues.size(), 2);
    QCOMPARE(loadWorld("box_and_block")->taskName(), QString());
}

void TestWorld::badSignals_data()
{
    QTest::addColumn<QString>("custom");
    QTest::addColumn<QString>("error");
    const auto one = [](const QString &name, const QString &data) {
        return signalText(name, data);
    };
    QTest::newRow("unknown kind")
        << one("signal:right:x", "twist a b")
        << "signal:right:x: unknown kind 'twist' (kinds: sensor, along, across, distance, "
           "angle, speed)";
    QTest::newRow("no kind") << one("signal:right:x", " ")
                             << "signal:right:x: unknown kind '' (kinds: sensor, along, "
                                "across, distance, angle, speed)";
    QTest::newRow("unknown sensor")
        << one("signal:right:x", "sensor nosuch") << "signal:right:x: no sensor 'nosuch'";
    QTest::newRow("no such component")
        << one("signal:right:x", "sensor bpos 3")
        << "signal:right:x: sensor 'bpos' has 3 values: no component '3'";
    QTest::newRow("a component of one value")
        << one("signal:right:x", "sensor weight y")
        << "signal:right:x: sensor 'weight' has 1 values: no component 'y'";
    QTest::newRow("unknown site") << one("signal:right:x", "along a nosuch x")
                                  << "signal:right:x: no site or body 'nosuch'";
    QTest::newRow("bad axis") << one("signal:right:x", "across a b w")
                              << "signal:right:x: axis 'w' is not x, y or z";
    QTest::newRow("bad second axis")
        << one("signal:right:x", "angle a x b 1") << "signal:right:x: axis '1' is not x, y or z";
    QTest::newRow("arguments missing") << one("signal:right:x", "along a b")
                                       << "signal:right:x: expected 'along|across A B x|y|z'";
    QTest::newRow("arguments over") << one("signal:right:x", "distance a b c")
                                    << "signal:right:x: expected 'distance|speed A B'";
    QTest::newRow("upper case name")
        << one("signal:right:Plug", "distance a b")
        << "signal:right:Plug: a signal name is 1 to 64 of a-z, 0-9, _ and .";
    QTest::newRow("empty name") << one("signal:right:", "distance a b")
                                << "signal:right:: a signal name is 1 to 64 of a-z, 0-9, _ and .";
    QTest::newRow("built-in name")
        << one("signal:right:left.f", "distance a b")
        << "signal:right:left.f: 'left.f' is a built-in quantity of every frame";
    QTest::newRow("friction") << one("signal:right:friction", "distance a b")
                              << "signal:right:friction: 'friction' is a built-in quantity of "
                                 "every frame";
    QTest::newRow("no left gripper")
        << one("signal:left:x", "distance a b") << "signal:left:x: the scene has no left gripper";
    QTest::newRow("no such hand")
        << one("signal:middle:x", "distance a b")
        << "signal:middle:x: expected signal:left:NAME or signal:right:NAME";
    QString many;
    for (int i = 0; i <= FrameSignals::Capacity; ++i)
        many += one(QString("signal:right:s%1").arg(i), "distance a b");
    QTest::newRow("too many") << many
                              << "signal:right:s64: more than 64 signals for the right gripper";
}

void TestWorld::badSignals()
{
    QFETCH(QString, custom);
    QFETCH(QString, error);
    QTemporaryDir dir;
    const QString path = writeScene(dir, signalScene(custom));
    QString message;
    QVERIFY(!World::load(path, SceneOptions{}, &message));
    QCOMPARE(message, path + ": " + error);
}

QTEST_GUILESS_MAIN(TestWorld)
#include "tst_world.moc"
