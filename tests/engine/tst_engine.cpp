// SPDX-License-Identifier: MIT
// The studio's engine: the simulation runs on its own thread at the asked speed, its streams
// reach the live history, devices are bound and rebound at tick boundaries, and the user
// can take the grippers over.
#include "devicemanager.h"
#include "manualoperator.h"
#include "scenefeed.h"
#include "simengine.h"
#include "world.h"

#include <QSignalSpy>
#include <QTest>

using namespace semhap;

class TestEngine : public QObject
{
    Q_OBJECT

private slots:
    void loadsPausedWithVirtualDevices();
    void refusesABadSceneKeepingTheRun();
    void runsAtTheAskedSpeed_data();
    void runsAtTheAskedSpeed();
    void streamsReachTheHistory();
    void stepAdvancesOneDisplayFrame();
    void rebindsADeviceWhileRunning();
    void userTakesOver();
    void resetStartsAgain();
    void finishesAtTheDuration();
    void stopAllPauses();
};

namespace {

RunOptions options(const QString &scene = "box_and_block", const QString &router = "C3")
{
    RunOptions o;
    o.scene = scene;
    o.router = router;
    o.duration = 3600.0;
    return o;
}

} // namespace

void TestEngine::loadsPausedWithVirtualDevices()
{
    SimEngine engine;
    QSignalSpy loaded(&engine, &SimEngine::loaded);
    QString error;
    QVERIFY2(engine.load(options(), &error), qPrintable(error));
    QCOMPARE(loaded.count(), 1);
    QVERIFY(!engine.isRunning());
    QVERIFY(engine.world());
    QVERIFY(engine.sceneFeed());
    QCOMPARE(engine.simTime(), 0.0);
    const auto devices = engine.history().devices();
    QVERIFY(!devices.empty());
    for (const RunDevice &device : devices) {
        Transport *transport = engine.devices().transport(device.name);
        QVERIFY2(transport, qPrintable(device.name));
        QCOMPARE(transport->uri(), "virtual:" + device.name);
    }
    const GripperThresholds right = engine.history().thresholds()[size_t(Gripper::Right)];
    QVERIFY(right.hasForce);
    QCOMPARE(right.grasp, 20.0);
    QCOMPARE(right.brk, 80.0);
    QCOMPARE(right.max, 120.0);
}

void TestEngine::refusesABadSceneKeepingTheRun()
{
    SimEngine engine;
    QString error;
    QVERIFY(engine.load(options(), &error));
    QVERIFY(!engine.load(options("no_such_scene"), &error));
    QVERIFY2(error.contains("no_such_scene"), qPrintable(error));
    QVERIFY(!engine.load(options("box_and_block", "C9"), &error));
    QVERIFY2(error.contains("C9"), qPrintable(error));
    QCOMPARE(engine.options().scene, QString("box_and_block"));
    QVERIFY(engine.world());
}

void TestEngine::runsAtTheAskedSpeed_data()
{
    QTest::addColumn<double>("speed");
    QTest::newRow("real time") << 1.0;
    QTest::newRow("slower") << 0.25;
    QTest::newRow("faster") << 4.0;
}

void TestEngine::runsAtTheAskedSpeed()
{
    QFETCH(double, speed);
    SimEngine engine;
    QString error;
    QVERIFY(engine.load(options(), &error));
    engine.setSpeed(speed);
    engine.run();
    QElapsedTimer wall;
    wall.start();
    QTest::qWait(1500);
    const double ratio = engine.simTime() / (double(wall.elapsed()) / 1000.0);
    engine.pause();
    // Generous: the machine is shared; what matters is that the pacing follows the speed.
    QVERIFY2(ratio > 0.5 * speed && ratio < 1.3 * speed, qPrintable(QString::number(ratio)));
    QVERIFY(engine.realtimeFactor() > 0.0);
}

void TestEngine::streamsReachTheHistory()
{
    SimEngine engine;
    QString error;
    QVERIFY(engine.load(options(), &error));
    QSignalSpy updated(&engine.history(), &RunHistory::updated);
    engine.setSpeed(8.0);
    engine.run();
    // The scripted operator grasps its first cube within a few simulated seconds.
    QTRY_VERIFY_WITH_TIMEOUT(!engine.history().events().isEmpty(), 20000);
    engine.pause();
    QVERIFY(updated.count() > 2);
    const RunSeries<ContactFrame> &frames = engine.history().frames(Gripper::Right);
    QVERIFY(frames.end() - frames.begin() > 100);
    QVERIFY(frames.last().t > 0.0);
    bool deviceFrames = false;
    for (size_t d = 0; d < engine.history().devices().size(); ++d)
        deviceFrames = deviceFrames || !engine.history().deviceFrames(int(d)).isEmpty();
    QVERIFY(deviceFrames);
    QVERIFY(!engine.history().spans().empty());
    QCOMPARE(engine.dropped(), quint64(0));
    QTRY_VERIFY(engine.history().metrics().contains("cubes_transferred"));
}

void TestEngine::stepAdvancesOneDisplayFrame()
{
    SimEngine engine;
    QString error;
    QVERIFY(engine.load(options(), &error));
    engine.step();
    QTRY_VERIFY(engine.simTime() > 0.0);
    QTest::qWait(50);
    QVERIFY2(std::abs(engine.simTime() - 1.0 / 60.0) < 0.002,
             qPrintable(QString::number(engine.simTime())));
    QVERIFY(!engine.isRunning());
}

void TestEngine::rebindsADeviceWhileRunning()
{
    SimEngine engine;
    QString error;
    QVERIFY(engine.load(options(), &error));
    engine.setSpeed(4.0);
    engine.run();
    const QString name = engine.history().devices().front().name;
    QVERIFY2(engine.bindDevice(name, "virtual:elsewhere", &error), qPrintable(error));
    QCOMPARE(engine.devices().transport(name)->uri(), QString("virtual:elsewhere"));
    QVERIFY(!engine.bindDevice("no.such.device", "virtual:x", &error));
    QVERIFY(error.contains("no.such.device"));
    QTest::qWait(200);
    QVERIFY(engine.isRunning());
    // Loading again keeps the user's binding of a device whose model still fits.
    QVERIFY(engine.load(options(), &error));
    QCOMPARE(engine.devices().transport(name)->uri(), QString("virtual:elsewhere"));
}

void TestEngine::userTakesOver()
{
    SimEngine engine;
    QString error;
    QVERIFY(engine.load(options(), &error));
    QSignalSpy manual(&engine, &SimEngine::manualChanged);
    engine.setManual(true);
    QCOMPARE(manual.count(), 1);
    Pose target = engine.world()->target(Gripper::Right);
    target.pos[2] += 0.05;
    engine.manualOperator()->setTarget(Gripper::Right, target);
    engine.manualOperator()->setGrip(Gripper::Right, 7.0);
    engine.step();
    QTRY_VERIFY(engine.simTime() > 0.0);
    QTest::qWait(50);
    QCOMPARE(engine.world()->target(Gripper::Right).pos[2], target.pos[2]);
    QCOMPARE(engine.world()->grip(Gripper::Right), 7.0);
}

void TestEngine::resetStartsAgain()
{
    SimEngine engine;
    QString error;
    QVERIFY(engine.load(options(), &error));
    engine.setSpeed(4.0);
    engine.run();
    QTRY_VERIFY(engine.simTime() > 0.5);
    QSignalSpy reset(&engine.history(), &RunHistory::reset);
    QVERIFY(engine.reset(&error));
    QCOMPARE(reset.count(), 1);
    QVERIFY(engine.isRunning()); // reset keeps running what was running
    QVERIFY(engine.simTime() < 0.5);
    QVERIFY(engine.history().frames(Gripper::Right).end() -
                engine.history().frames(Gripper::Right).begin() <
            300);
}

void TestEngine::finishesAtTheDuration()
{
    SimEngine engine;
    QString error;
    RunOptions o = options();
    o.duration = 0.2;
    QVERIFY(engine.load(o, &error));
    QSignalSpy finished(&engine, &SimEngine::finished);
    engine.setSpeed(2.0);
    engine.run();
    QTRY_COMPARE(finished.count(), 1);
    QVERIFY(!engine.isRunning());
    QVERIFY(std::abs(engine.simTime() - 0.2) < 1e-9);
    engine.run(); // nothing left to run
    QVERIFY(!engine.isRunning());
}

void TestEngine::stopAllPauses()
{
    SimEngine engine;
    QString error;
    QVERIFY(engine.load(options(), &error));
    engine.run();
    engine.stopAll();
    QVERIFY(!engine.isRunning());
}

QTEST_MAIN(TestEngine)
#include "tst_engine.moc"
