// SPDX-License-Identifier: MIT
// The simulation viewport in a real window with OpenGL (run under Xvfb): it draws the
// scene, the mouse moves the camera, teleoperation keys move the active gripper's target
// through a DriveOperator. Screenshots are saved beside the test binary to be looked at.
#include "driveoperator.h"
#include "framepace.h"
#include "handdrive.h"
#include "imagechecks.h"
#include "scenefeed.h"
#include "simviewport.h"
#include "world.h"

#include <QAction>
#include <QSet>
#include <QSignalSpy>
#include <QTest>

#include <algorithm>
#include <cmath>

using namespace semhap;

namespace {

/** A world, its feed and the operator the keys drive: what the engine will own. */
struct Scene
{
    std::unique_ptr<World> world;
    std::unique_ptr<SceneFeed> feed;
    DriveOperator manual;
};

std::unique_ptr<Scene> loadScene(const QString &name, int steps)
{
    auto scene = std::make_unique<Scene>();
    QString error;
    scene->world = World::load(name, SceneOptions(), &error);
    if (!scene->world) {
        qWarning("%s", qPrintable(error));
        return nullptr;
    }
    for (int k = 0; k < steps; ++k)
        scene->world->step();
    scene->feed = std::make_unique<SceneFeed>(*scene->world);
    return scene;
}

double yaw(const Pose &pose)
{
    const auto &q = pose.quat;
    return std::atan2(2 * (q[0] * q[3] + q[1] * q[2]), 1 - 2 * (q[2] * q[2] + q[3] * q[3]));
}

} // namespace

class TestViewport : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void waitsForThePicture();
    void drawsTheScene();
    void paceFollowsTheFramesCost_data();
    void paceFollowsTheFramesCost();
    void drawsNothingWhileMinimised();
    void survivesAMoveToAnotherWindow();
    void leftDragOrbits();
    void rightDragPans();
    void wheelZooms();
    void doubleClickResetsTheCamera();
    void keysMoveTheActiveHand_data();
    void keysMoveTheActiveHand();
    void gripKeysRampTheGrip();
    void forcesToggleReachesTheFeed();
    void tabSwitchesHands();
    void cameraPresetsOnKeys();
    void ghostShowsTheTarget();
    void screenshots_data();
    void screenshots();
    void presetsAreWellExposed_data();
    void presetsAreWellExposed();
    void showsThePlaceholder();

private:
    /** Runs the event loop for `ms`, capturing whenever the viewport asks (the sim thread). */
    void pump(int ms, const SceneOverlay &overlay = {});
    /** Feeds the viewport until it has drawn a frame after `frames`; false after 10 s. */
    bool pumpUntilDrawn(quint64 frames);
    /** Puts the viewport into `window`, shown, and feeds it until it has drawn there. */
    bool drawnIn(QWidget &window);
    QImage grab();
    /** Shows scene `name`, settled for a second, at 1280×800; the scene shown before. */
    std::unique_ptr<Scene> showSettled(const QString &name);
    /** Shows `previous` again, at the tests' usual 800×600. */
    void showAgain(std::unique_ptr<Scene> previous);

    std::unique_ptr<Scene> m_scene;
    SimViewport m_viewport;
    HandDrive m_handDrive;
};

void TestViewport::pump(int ms, const SceneOverlay &overlay)
{
    QElapsedTimer clock;
    clock.start();
    while (clock.elapsed() < ms) {
        if (m_scene->feed->wantsCapture())
            m_scene->feed->capture(*m_scene->world, overlay);
        QTest::qWait(5);
    }
}

bool TestViewport::pumpUntilDrawn(quint64 frames)
{
    QElapsedTimer clock;
    clock.start();
    while (m_viewport.renderedFrames() <= frames && clock.elapsed() < 10000)
        pump(20);
    return m_viewport.renderedFrames() > frames;
}

bool TestViewport::drawnIn(QWidget &window)
{
    window.resize(820, 620);
    m_viewport.setParent(&window);
    window.show();
    if (!QTest::qWaitForWindowExposed(&window))
        return false;
    m_scene->world->step();
    return pumpUntilDrawn(m_viewport.renderedFrames());
}

QImage TestViewport::grab()
{
    const QImage image = m_viewport.grabFramebuffer();
    return image.convertToFormat(QImage::Format_ARGB32);
}

std::unique_ptr<Scene> TestViewport::showSettled(const QString &name)
{
    auto shown = loadScene(name, 500);
    if (!shown)
        return nullptr;
    std::swap(m_scene, shown);
    m_viewport.setScene(m_scene->world.get(), m_scene->feed.get());
    m_viewport.resize(1280, 800);
    return shown;
}

void TestViewport::showAgain(std::unique_ptr<Scene> previous)
{
    m_scene = std::move(previous);
    m_viewport.setScene(m_scene->world.get(), m_scene->feed.get());
    m_viewport.resize(800, 600);
}

void TestViewport::initTestCase()
{
    m_scene = loadScene("box_and_block", 50);
    QVERIFY(m_scene);
    m_handDrive.setOperator(&m_scene->manual);
    m_viewport.setHandDrive(&m_handDrive);
    m_viewport.resize(800, 600);
    m_viewport.show();
    QVERIFY(QTest::qWaitForWindowExposed(&m_viewport));
    m_viewport.activateWindow();
    m_viewport.setFocus();
    QVERIFY(QTest::qWaitForWindowActive(&m_viewport));
}

void TestViewport::waitsForThePicture()
{
    m_viewport.setScene(m_scene->world.get(), m_scene->feed.get());
    QTest::qWait(50); // no capture: the simulation has not answered yet
    QCOMPARE(m_viewport.renderedFrames(), quint64(0));
    const QImage image = grab();
    QSet<QRgb> colours;
    for (int y = 0; y < image.height(); y += 4) {
        for (int x = 0; x < image.width(); x += 4)
            colours.insert(image.pixel(x, y));
    }
    QVERIFY2(colours.size() < 100, "only the background and the waiting text");
}

void TestViewport::drawsTheScene()
{
    QVERIFY(pumpUntilDrawn(0));
    const QImage image = grab();
    QCOMPARE(image.size(), QSize(800, 600));
    QString why;
    QVERIFY2(looksDrawn(image, &why), qPrintable(why));
    // Frames keep coming: the painter's overlay does not break MuJoCo's next frame.
    const quint64 before = m_viewport.renderedFrames();
    m_scene->world->step();
    QVERIFY(pumpUntilDrawn(before));
    const QImage again = grab();
    QSet<QRgb> colours2;
    for (int y = 0; y < again.height(); y += 4) {
        for (int x = 0; x < again.width(); x += 4)
            colours2.insert(again.pixel(x, y) & 0xffffff);
    }
    QVERIFY(colours2.size() > 100);

    // How fast the viewport draws with the simulation always answering (software GL here).
    const quint64 start = m_viewport.renderedFrames();
    pump(1000);
    qInfo("%llu frames/s at 800x600", m_viewport.renderedFrames() - start);
}

void TestViewport::paceFollowsTheFramesCost_data()
{
    QTest::addColumn<double>("display"); // Hz
    QTest::addColumn<double>("cost");    // CPU s a frame
    QTest::addColumn<double>("interval");
    // A GPU: the display's rate.
    QTest::newRow("cheap, 60 Hz") << 60.0 << 0.001 << 1.0 / 60;
    QTest::newRow("cheap, 144 Hz") << 144.0 << 0.001 << 1.0 / 144;
    // Software GL: a third of a core at most.
    QTest::newRow("30 ms") << 60.0 << 0.03 << 0.1;
    QTest::newRow("60 ms") << 60.0 << 0.06 << 0.2;
    // However dear, the picture still moves four times a second.
    QTest::newRow("a second") << 60.0 << 1.0 << FramePace::LongestInterval;
    // A screen that says no rate counts as 60 Hz.
    QTest::newRow("no rate") << 0.0 << 0.0 << 1.0 / 60;
}

void TestViewport::paceFollowsTheFramesCost()
{
    QFETCH(double, display);
    QFETCH(double, cost);
    QFETCH(double, interval);
    FramePace pace(display);
    QVERIFY(pace.due(0.0)); // the first frame at once
    for (int k = 0; k < 50; ++k)
        pace.frameDrawn(k, cost); // smoothed: it settles on the cost
    QVERIFY2(std::abs(pace.interval() - interval) < 1e-6,
             qPrintable(QString::number(pace.interval())));
    QVERIFY(!pace.due(49.0 + interval / 2));
    QVERIFY(pace.due(49.0 + interval));
}

void TestViewport::drawsNothingWhileMinimised()
{
    // Minimised, the window shows nothing: nothing is drawn, nothing asked of the simulation.
    QWidget window;
    QVERIFY(drawnIn(window));
    window.showMinimized();
    QTRY_VERIFY(window.isMinimized());
    pump(100); // a frame asked for before goes
    const quint64 minimised = m_viewport.renderedFrames();
    for (int k = 0; k < 5; ++k) {
        m_scene->world->step();
        pump(100);
    }
    QCOMPARE(m_viewport.renderedFrames(), minimised);
    window.showNormal();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    m_scene->world->step();
    QVERIFY(pumpUntilDrawn(minimised));
    m_viewport.setParent(nullptr);
    m_viewport.show();
    QVERIFY(QTest::qWaitForWindowExposed(&m_viewport));
}

void TestViewport::survivesAMoveToAnotherWindow()
{
    // A floating dock: the viewport gets a new top-level window and a new GL context, and
    // MuJoCo's resources must be made again in it.
    QWidget window;
    QVERIFY(drawnIn(window));
    QSet<QRgb> colours;
    const QImage image = grab();
    for (int y = 0; y < image.height(); y += 4) {
        for (int x = 0; x < image.width(); x += 4)
            colours.insert(image.pixel(x, y) & 0xffffff);
    }
    QVERIFY(colours.size() > 100);

    m_viewport.setParent(nullptr);
    m_viewport.show();
    QVERIFY(QTest::qWaitForWindowExposed(&m_viewport));
    m_viewport.activateWindow();
    m_viewport.setFocus();
    QVERIFY(QTest::qWaitForWindowActive(&m_viewport));
    m_scene->world->step();
    QVERIFY(pumpUntilDrawn(m_viewport.renderedFrames()));
}

void TestViewport::leftDragOrbits()
{
    m_viewport.resetCamera();
    const OrbitCamera before = m_viewport.camera();
    QSignalSpy changed(&m_viewport, &SimViewport::cameraChanged);
    QTest::mousePress(&m_viewport, Qt::LeftButton, {}, QPoint(400, 300));
    QTest::mouseMove(&m_viewport, QPoint(450, 320));
    QTest::mouseMove(&m_viewport, QPoint(500, 340));
    QTest::mouseRelease(&m_viewport, Qt::LeftButton, {}, QPoint(500, 340));
    QVERIFY(changed.count() > 0);
    QVERIFY(std::abs(m_viewport.camera().azimuth - before.azimuth) > 10);
    QVERIFY(m_viewport.camera().elevation < before.elevation); // dragged down: from higher
    QCOMPARE(m_viewport.camera().distance, before.distance);

    // Dragging far down stops looking straight down, never from under the table.
    QTest::mousePress(&m_viewport, Qt::LeftButton, {}, QPoint(400, 10));
    QTest::mouseMove(&m_viewport, QPoint(400, 590));
    QTest::mouseRelease(&m_viewport, Qt::LeftButton, {}, QPoint(400, 590));
    QVERIFY(m_viewport.camera().elevation >= -89.0);
    QTest::mousePress(&m_viewport, Qt::LeftButton, {}, QPoint(400, 590));
    QTest::mouseMove(&m_viewport, QPoint(400, 10));
    QTest::mouseRelease(&m_viewport, Qt::LeftButton, {}, QPoint(400, 10));
    QVERIFY(m_viewport.camera().elevation <= 0.0);
}

void TestViewport::rightDragPans()
{
    m_viewport.resetCamera();
    const OrbitCamera before = m_viewport.camera();
    QTest::mousePress(&m_viewport, Qt::RightButton, {}, QPoint(400, 300));
    QTest::mouseMove(&m_viewport, QPoint(300, 300));
    QTest::mouseRelease(&m_viewport, Qt::RightButton, {}, QPoint(300, 300));
    const OrbitCamera after = m_viewport.camera();
    QCOMPARE(after.azimuth, before.azimuth);
    // Looking along +x, dragging the scene left moves the look-at point right (-y).
    QVERIFY(after.lookAt[1] < before.lookAt[1] - 0.05);
    QVERIFY(std::abs(after.lookAt[0] - before.lookAt[0]) < 1e-9);
}

void TestViewport::wheelZooms()
{
    m_viewport.resetCamera();
    const double before = m_viewport.camera().distance;
    auto wheel = [this](int notches, Qt::KeyboardModifiers modifiers) {
        const QPointF at(400, 300);
        QWheelEvent event(at, m_viewport.mapToGlobal(at), QPoint(), QPoint(0, 120 * notches),
                          Qt::NoButton, modifiers, Qt::NoScrollPhase, false);
        QApplication::sendEvent(&m_viewport, &event);
    };
    wheel(2, Qt::NoModifier);
    QVERIFY(m_viewport.camera().distance < before * 0.85);
    for (int k = 0; k < 60; ++k)
        wheel(-1, Qt::NoModifier);
    QVERIFY(m_viewport.camera().distance <= 4.0);

    // Ctrl + wheel is the grip force, not the zoom.
    const double distance = m_viewport.camera().distance;
    const double grip = m_handDrive.gripSetpoint(Gripper::Right);
    wheel(1, Qt::ControlModifier);
    QCOMPARE(m_viewport.camera().distance, distance);
    QCOMPARE(m_handDrive.gripSetpoint(Gripper::Right), grip + HandDrive::GripStep);
    m_viewport.resetCamera();
}

void TestViewport::doubleClickResetsTheCamera()
{
    const OrbitCamera home = m_viewport.camera();
    QTest::mousePress(&m_viewport, Qt::LeftButton, {}, QPoint(400, 300));
    QTest::mouseMove(&m_viewport, QPoint(600, 200));
    QTest::mouseRelease(&m_viewport, Qt::LeftButton, {}, QPoint(600, 200));
    QVERIFY(m_viewport.camera().azimuth != home.azimuth);
    QTest::mouseDClick(&m_viewport, Qt::LeftButton, {}, QPoint(600, 200));
    QCOMPARE(m_viewport.camera().azimuth, home.azimuth);
    QCOMPARE(m_viewport.camera().elevation, home.elevation);
    QCOMPARE(m_viewport.camera().distance, home.distance);
    // Home, in the viewport, does it too.
    QTest::mousePress(&m_viewport, Qt::LeftButton, {}, QPoint(400, 300));
    QTest::mouseMove(&m_viewport, QPoint(600, 200));
    QTest::mouseRelease(&m_viewport, Qt::LeftButton, {}, QPoint(600, 200));
    QVERIFY(m_viewport.camera().azimuth != home.azimuth);
    QTest::keyClick(&m_viewport, Qt::Key_Home);
    QCOMPARE(m_viewport.camera().azimuth, home.azimuth);
}

void TestViewport::keysMoveTheActiveHand_data()
{
    QTest::addColumn<int>("key");
    QTest::addColumn<int>("axis"); // 0..2: position x, y, z; 3: yaw
    QTest::addColumn<int>("sign");
    // The default view looks across the jaws, along +x: away is +x, right is -y.
    QTest::newRow("W: away") << int(Qt::Key_W) << 0 << 1;
    QTest::newRow("S: toward") << int(Qt::Key_S) << 0 << -1;
    QTest::newRow("A: left") << int(Qt::Key_A) << 1 << 1;
    QTest::newRow("D: right") << int(Qt::Key_D) << 1 << -1;
    QTest::newRow("R: up") << int(Qt::Key_R) << 2 << 1;
    QTest::newRow("F: down") << int(Qt::Key_F) << 2 << -1;
    QTest::newRow("Up arrow: up") << int(Qt::Key_Up) << 2 << 1;
    QTest::newRow("Q: turn left") << int(Qt::Key_Q) << 3 << 1;
    QTest::newRow("E: turn right") << int(Qt::Key_E) << 3 << -1;
    QTest::newRow("Right arrow: turn right") << int(Qt::Key_Right) << 3 << -1;
}

void TestViewport::keysMoveTheActiveHand()
{
    QFETCH(int, key);
    QFETCH(int, axis);
    QFETCH(int, sign);
    m_viewport.resetCamera();
    m_viewport.setDriving(false); // the script drives; the key takes over
    World &world = *m_scene->world;
    const Pose before = world.target(Gripper::Right);
    QSignalSpy engaged(&m_handDrive, &HandDrive::driveStarted);

    QTest::keyPress(&m_viewport, Qt::Key(key));
    QTest::qWait(150);
    QTest::keyRelease(&m_viewport, Qt::Key(key));
    QCOMPARE(engaged.count(), 1);
    QVERIFY(m_viewport.isDriving());
    m_scene->manual.act(world);
    const Pose after = world.target(Gripper::Right);

    for (int a = 0; a < 3; ++a) {
        const double moved = after.pos[size_t(a)] - before.pos[size_t(a)];
        if (a == axis)
            QVERIFY2(moved * sign > 0.002, qPrintable(QString("moved %1 m").arg(moved)));
        else
            QVERIFY2(std::abs(moved) < 1e-9, qPrintable(QString("axis %1: %2").arg(a).arg(moved)));
    }
    const double turned = std::remainder(yaw(after) - yaw(before), 2 * M_PI);
    if (axis == 3)
        QVERIFY2(turned * sign > 0.02, qPrintable(QString("turned %1 rad").arg(turned)));
    else
        QVERIFY(std::abs(turned) < 1e-9);

    // Released: the hand's target stays (the simulation may still be landing on it).
    const Pose commanded = m_handDrive.command(Gripper::Right)->target;
    QTest::qWait(60);
    QCOMPARE(m_handDrive.command(Gripper::Right)->target.pos, commanded.pos);
}

void TestViewport::gripKeysRampTheGrip()
{
    m_viewport.setDriving(false);
    World &world = *m_scene->world;
    QVERIFY(world.grip(Gripper::Right) <= 0);
    QTest::keyClick(&m_viewport, Qt::Key_Space);
    QVERIFY(m_handDrive.isClosed(Gripper::Right));
    // A ramp, not a step: shortly after, the grip is on its way up.
    m_scene->manual.act(world);
    QVERIFY(world.grip(Gripper::Right) < m_handDrive.gripSetpoint(Gripper::Right));
    QTRY_COMPARE(m_handDrive.command(Gripper::Right)->grip,
                 m_handDrive.gripSetpoint(Gripper::Right));
    // Closing on nothing, the simulation holds the fingers to their approach force (the
    // guarded close, tests/handdrive).
    m_scene->manual.act(world);
    QCOMPARE(world.grip(Gripper::Right),
             std::min(m_handDrive.gripSetpoint(Gripper::Right),
                      world.closingForce(Gripper::Right, DriveOperator::ClosingSpeed)));

    QTest::keyClick(&m_viewport, Qt::Key_Plus);
    QTRY_COMPARE(m_handDrive.command(Gripper::Right)->grip,
                 m_handDrive.gripSetpoint(Gripper::Right));
    QVERIFY(m_handDrive.command(Gripper::Right)->grip > HandDrive::DefaultGrip);

    QTest::keyClick(&m_viewport, Qt::Key_G);
    QVERIFY(!m_handDrive.isClosed(Gripper::Right));
    QTRY_COMPARE(m_handDrive.command(Gripper::Right)->grip, HandDrive::OpenGrip);
}

void TestViewport::forcesToggleReachesTheFeed()
{
    QVERIFY(!m_scene->feed->showForces());
    m_viewport.showForcesAction()->trigger();
    QVERIFY(m_viewport.showForces());
    QVERIFY(m_scene->feed->showForces());
    m_viewport.setShowForces(false);
    QVERIFY(!m_scene->feed->showForces());
    QVERIFY(!m_viewport.showForcesAction()->isChecked());
}

void TestViewport::tabSwitchesHands()
{
    // box_and_block has one hand: Tab is left to the focus chain.
    QVERIFY(!m_handDrive.hasBothHands());

    auto bimanual = loadScene("bimanual_sorting", 50);
    QVERIFY(bimanual);
    std::swap(m_scene, bimanual);
    m_handDrive.setOperator(&m_scene->manual);
    m_viewport.setScene(m_scene->world.get(), m_scene->feed.get());
    m_viewport.setDriving(false);
    QVERIFY(m_handDrive.hasBothHands());
    QCOMPARE(m_handDrive.activeHand(), Gripper::Right);
    QSignalSpy engaged(&m_handDrive, &HandDrive::driveStarted);

    QTest::keyClick(&m_viewport, Qt::Key_Tab);
    QCOMPARE(m_handDrive.activeHand(), Gripper::Left);
    QCOMPARE(engaged.count(), 1);
    // Tab did not move the focus away (asked of the window: another test may own the display).
    QCOMPARE(m_viewport.window()->focusWidget(), &m_viewport);

    World &world = *m_scene->world;
    const Pose left = world.target(Gripper::Left);
    const Pose right = world.target(Gripper::Right);
    QTest::keyPress(&m_viewport, Qt::Key_D);
    QTest::qWait(100);
    QTest::keyRelease(&m_viewport, Qt::Key_D);
    m_scene->manual.act(world);
    QVERIFY(world.target(Gripper::Left).pos[1] < left.pos[1] - 0.005);
    QCOMPARE(world.target(Gripper::Right).pos, right.pos);

    QTest::keyClick(&m_viewport, Qt::Key_Tab);
    QCOMPARE(m_handDrive.activeHand(), Gripper::Right);
    std::swap(m_scene, bimanual);
    m_handDrive.setOperator(&m_scene->manual);
    m_viewport.setScene(m_scene->world.get(), m_scene->feed.get());
}

void TestViewport::cameraPresetsOnKeys()
{
    // 1–4 in the viewport: across the jaws (the default), top, side, follow the hand. The
    // presets frame the scene's regions, so the scene is shown here (this runs alone too).
    m_viewport.setScene(m_scene->world.get(), m_scene->feed.get());
    QTest::keyClick(&m_viewport, Qt::Key_2);
    QCOMPARE(m_viewport.cameraPreset(), CameraPreset::Top);
    QCOMPARE(m_viewport.camera().elevation, -89.0);
    QTest::keyClick(&m_viewport, Qt::Key_3);
    QCOMPARE(m_viewport.camera().azimuth, 90.0);
    QVERIFY(m_viewport.cameraPresetAction(CameraPreset::Side)->isChecked());
    QTest::keyClick(&m_viewport, Qt::Key_1);
    QCOMPARE(m_viewport.camera().azimuth, 0.0);
    QCOMPARE(m_viewport.camera().elevation, -30.0);

    m_viewport.setDriving(false);
    QTest::keyClick(&m_viewport, Qt::Key_4);
    QCOMPARE(m_viewport.cameraPreset(), CameraPreset::Follow);
    QTest::keyPress(&m_viewport, Qt::Key_W); // takes the grippers and moves the hand
    QTest::qWait(200);
    QTest::keyRelease(&m_viewport, Qt::Key_W);
    World &world = *m_scene->world;
    const Pose start = world.gripperPose(m_handDrive.activeHand());
    for (int k = 0; k < 200; ++k) { // the hand follows its target
        m_scene->manual.act(world);
        world.step();
    }
    // The view follows the hand itself, halfway down to its pads, once the viewport has drawn
    // the scene as it is now: the scene is captured until it has (a busy machine draws late).
    const Pose hand = world.gripperPose(m_handDrive.activeHand());
    QVERIFY(hand.pos[0] > start.pos[0] + 0.01);
    const auto off = [&](size_t axis) {
        return std::abs(m_viewport.camera().lookAt[axis] - hand.pos[axis]);
    };
    QElapsedTimer waited;
    waited.start();
    do
        pump(20);
    while ((off(0) >= 0.002 || off(1) >= 0.002) && waited.elapsed() < 10000);
    for (size_t axis = 0; axis < 2; ++axis)
        QVERIFY2(off(axis) < 0.002, qPrintable(QString("axis %1: looks at %2, the hand is at %3")
                                                   .arg(axis)
                                                   .arg(m_viewport.camera().lookAt[axis])
                                                   .arg(hand.pos[axis])));
    // The gamepad's camera button goes round them all.
    m_viewport.nextCameraPreset();
    QCOMPARE(m_viewport.cameraPreset(), CameraPreset::AcrossJaws);
    m_viewport.setDriving(false);
}

void TestViewport::ghostShowsTheTarget()
{
    // While the user drives, the wrist target shows as a cyan ghost with a drop line; the
    // scripted operator's run shows none.
    auto cyan = [this] { return ghostPixels(grab()); };
    m_viewport.resetCamera();
    m_viewport.setDriving(false);
    pump(150);
    const int scripted = cyan();
    QTest::keyPress(&m_viewport, Qt::Key_R); // drive: up a little
    QTest::qWait(50);
    QTest::keyRelease(&m_viewport, Qt::Key_R);
    m_scene->manual.act(*m_scene->world); // the operator reports the target and the surface
    QVERIFY(m_handDrive.status(Gripper::Right).surface);
    m_viewport.update();
    pump(150);
    const int driving = cyan();
    qInfo("cyan pixels: %d scripted, %d driving", scripted, driving);
    QVERIFY(driving > scripted + 100);
    m_viewport.setDriving(false);
}

void TestViewport::screenshots_data()
{
    QTest::addColumn<QString>("scene");
    QTest::addColumn<bool>("confirm");
    QTest::addColumn<bool>("manual");
    QTest::newRow("box_and_block") << "box_and_block" << true << true;
    QTest::newRow("bimanual_sorting") << "bimanual_sorting" << false << false;
    QTest::newRow("usb_insertion") << "usb_insertion" << false << false;
    QTest::newRow("dish_wiping") << "dish_wiping" << false << false;
}

void TestViewport::screenshots()
{
    QFETCH(QString, scene);
    QFETCH(bool, confirm);
    QFETCH(bool, manual);
    auto previous = showSettled(scene);
    QVERIFY(previous);
    m_viewport.setDriving(manual);
    m_viewport.setShowForces(true);
    SceneOverlay overlay;
    overlay.rightConfirm = confirm ? 1.0 : 0.0;
    pump(300, overlay);
    const QImage image = grab();
    QCOMPARE(image.size(), QSize(1280, 800));
    image.save(QString("%1/viewport-%2.png").arg(QCoreApplication::applicationDirPath(), scene));
    m_viewport.setShowForces(false);
    m_viewport.setDriving(false);
    showAgain(std::move(previous));
}

void TestViewport::presetsAreWellExposed_data()
{
    QTest::addColumn<QString>("scene");
    QTest::addColumn<int>("key");
    for (const char *scene :
         {"box_and_block", "bimanual_sorting", "usb_insertion", "dish_wiping"}) {
        const char *names[] = {"across the jaws", "top", "side", "follow"};
        for (int preset = 0; preset < 4; ++preset)
            QTest::addRow("%s, %s", scene, names[preset]) << QString(scene) << Qt::Key_1 + preset;
    }
}

// Each camera preset (keys 1–4) shows the scene without burnt white: the top view looked at
// a floor and cubes burnt white by two lights, and the mirroring floor showed white inside
// the boxes. Pictures beside the binary, or in $SEMHAP_SCREENSHOTS.
void TestViewport::presetsAreWellExposed()
{
    QFETCH(QString, scene);
    QFETCH(int, key);
    auto previous = showSettled(scene);
    QVERIFY(previous);
    m_viewport.setFocus();
    QTest::keyClick(&m_viewport, Qt::Key(key));
    pump(300);
    const QImage image = grab();
    const QString dir = qEnvironmentVariableIsSet("SEMHAP_SCREENSHOTS")
                            ? qEnvironmentVariable("SEMHAP_SCREENSHOTS")
                            : QCoreApplication::applicationDirPath();
    image.save(
        QString("%1/viewport-%2.png")
            .arg(dir, QString(QTest::currentDataTag()).replace(", ", "-").replace(' ', '_')));
    QString why;
    QVERIFY2(looksDrawn(image, &why), qPrintable(why));
    QVERIFY2(looksExposed(image, &why), qPrintable(why));
    QTest::keyClick(&m_viewport, Qt::Key_1);
    showAgain(std::move(previous));
}

void TestViewport::showsThePlaceholder()
{
    // A live rig or a replay without scene state: the viewport says why it shows nothing.
    m_viewport.setScene(nullptr, nullptr);
    m_viewport.setPlaceholder("Live rig on udp:127.0.0.1:9871");
    QTest::qWait(50);
    const QImage image = grab();
    const QRgb background = image.pixel(2, 2);
    int text = 0;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x)
            text += image.pixel(x, y) != background ? 1 : 0;
    }
    QVERIFY2(text > 200, qPrintable(QString::number(text)));
    image.save(QCoreApplication::applicationDirPath() + "/viewport-placeholder.png");
}

QTEST_MAIN(TestViewport)
#include "tst_viewport.moc"
