// SPDX-License-Identifier: MIT
// The keyboard teleoperation without a window: directions follow the camera, the
// workspace holds the wrist, Shift slows down, and taking over starts where the hands are.
#include "driveoperator.h"
#include "keyboarddrive.h"
#include "world.h"

#include <QSignalSpy>
#include <QTest>

#include <cmath>

using namespace semhap;

class TestKeyboardDrive : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void init();
    void directionsFollowTheView_data();
    void directionsFollowTheView();
    void workspaceHoldsTheWrist_data();
    void workspaceHoldsTheWrist();
    void shiftSlowsDown();
    void takingOverStartsWhereTheHandsAre();
    void unmappedKeysAreLeftAlone();
    void shortcutsAreLeftAlone_data();
    void shortcutsAreLeftAlone();

private:
    Pose heldFor(int key, double seconds, Qt::KeyboardModifiers modifiers = Qt::NoModifier);

    std::unique_ptr<World> m_world;
    DriveOperator m_operator;
    std::unique_ptr<KeyboardDrive> m_keyboardDrive;
};

void TestKeyboardDrive::initTestCase()
{
    QString error;
    m_world = World::load("box_and_block", SceneOptions(), &error);
    QVERIFY2(m_world, qPrintable(error));
}

void TestKeyboardDrive::init()
{
    m_keyboardDrive = std::make_unique<KeyboardDrive>();
    m_keyboardDrive->setOperator(&m_operator);
    m_keyboardDrive->setWorld(m_world.get());
}

Pose TestKeyboardDrive::heldFor(int key, double seconds, Qt::KeyboardModifiers modifiers)
{
    m_keyboardDrive->press(key, modifiers);
    m_keyboardDrive->advance(seconds);
    m_keyboardDrive->release(key);
    m_operator.act(*m_world);
    return m_world->target(Gripper::Right);
}

void TestKeyboardDrive::directionsFollowTheView_data()
{
    QTest::addColumn<double>("azimuth");
    QTest::addColumn<double>("x");
    QTest::addColumn<double>("y");
    // W moves away from the viewer along the table axis nearest the view.
    QTest::newRow("looking along +y") << 90.0 << 0.0 << 1.0;
    QTest::newRow("looking along +x") << 0.0 << 1.0 << 0.0;
    QTest::newRow("looking along -y") << -90.0 << 0.0 << -1.0;
    QTest::newRow("slanted, nearest -x") << 200.0 << -1.0 << 0.0;
}

void TestKeyboardDrive::directionsFollowTheView()
{
    QFETCH(double, azimuth);
    QFETCH(double, x);
    QFETCH(double, y);
    m_keyboardDrive->setViewAzimuth(azimuth);
    const Pose before = m_world->target(Gripper::Right);
    const Pose away = heldFor(Qt::Key_W, 0.2);
    QVERIFY(std::abs((away.pos[0] - before.pos[0]) - x * 0.2 * 0.15) < 0.004);
    QVERIFY(std::abs((away.pos[1] - before.pos[1]) - y * 0.2 * 0.15) < 0.004);
    // D is to the viewer's right: away turned a quarter clockwise seen from above.
    const Pose right = heldFor(Qt::Key_D, 0.2);
    QVERIFY(std::abs((right.pos[0] - away.pos[0]) - y * 0.2 * 0.15) < 0.004);
    QVERIFY(std::abs((right.pos[1] - away.pos[1]) + x * 0.2 * 0.15) < 0.004);
}

void TestKeyboardDrive::workspaceHoldsTheWrist_data()
{
    QTest::addColumn<int>("key");
    QTest::addColumn<int>("axis");
    QTest::addColumn<double>("limit");
    // box_and_block: pick and place span x -0.28..0.28, y -0.13..0.13; 12 cm around them.
    QTest::newRow("up") << int(Qt::Key_R) << 2 << 0.45;
    QTest::newRow("down to the table") << int(Qt::Key_F) << 2 << 0.06;
    QTest::newRow("right") << int(Qt::Key_D) << 0 << 0.40;
    QTest::newRow("left") << int(Qt::Key_A) << 0 << -0.40;
    QTest::newRow("away") << int(Qt::Key_W) << 1 << 0.25;
}

void TestKeyboardDrive::workspaceHoldsTheWrist()
{
    QFETCH(int, key);
    QFETCH(int, axis);
    QFETCH(double, limit);
    Pose pose;
    for (int k = 0; k < 40; ++k) // 10 s held, in ticks the length of a long stall
        pose = heldFor(key, 0.25);
    QVERIFY2(std::abs(pose.pos[size_t(axis)] - limit) < 1e-9,
             qPrintable(QString::number(pose.pos[size_t(axis)])));
}

void TestKeyboardDrive::shiftSlowsDown()
{
    const double z = m_world->target(Gripper::Right).pos[2];
    const double fast = heldFor(Qt::Key_R, 0.2).pos[2] - z;
    const double slow = heldFor(Qt::Key_F, 0.2, Qt::ShiftModifier).pos[2] - (z + fast);
    QVERIFY2(std::abs(slow / fast + KeyboardDrive::SlowFactor) < 0.05,
             qPrintable(QString("%1 vs %2").arg(slow).arg(fast)));
}

void TestKeyboardDrive::takingOverStartsWhereTheHandsAre()
{
    QSignalSpy engaged(m_keyboardDrive.get(), &KeyboardDrive::driveStarted);
    // Wherever the scripted operator left the hand, closed on something.
    std::array<std::optional<HandCommand>, 2> start{};
    start[1] = HandCommand{};
    start[1]->hand = Gripper::Right;
    start[1]->target.pos = {0.1, -0.05, 0.2};
    start[1]->grip = 42.0;
    m_keyboardDrive->setStartSource([&] { return start; });
    QVERIFY(m_keyboardDrive->press(Qt::Key_G));
    QCOMPARE(engaged.count(), 1);
    QCOMPARE(m_keyboardDrive->command(Gripper::Right)->target.pos, start[1]->target.pos);
    // It was closed: G opens it, ramping down from 42 N.
    QVERIFY(!m_keyboardDrive->isClosed(Gripper::Right));
    m_keyboardDrive->advance(0.1);
    QCOMPARE(m_keyboardDrive->command(Gripper::Right)->grip, 42.0 - 0.1 * KeyboardDrive::GripRate);
    m_operator.act(*m_world);
    QCOMPARE(m_world->target(Gripper::Right).pos, start[1]->target.pos);

    // Handed back and taken again: from wherever the hand is by then.
    m_keyboardDrive->endDrive();
    start[1]->target.pos = {-0.1, 0.05, 0.25};
    QVERIFY(m_keyboardDrive->press(Qt::Key_Plus));
    QCOMPARE(engaged.count(), 2);
    QCOMPARE(m_keyboardDrive->command(Gripper::Right)->target.pos, start[1]->target.pos);
}

void TestKeyboardDrive::unmappedKeysAreLeftAlone()
{
    QSignalSpy engaged(m_keyboardDrive.get(), &KeyboardDrive::driveStarted);
    QVERIFY(!m_keyboardDrive->press(Qt::Key_X));
    QVERIFY(!m_keyboardDrive->press(Qt::Key_Tab)); // one hand: Tab is the focus chain's
    QVERIFY(!m_keyboardDrive->press(Qt::Key_Shift));
    QCOMPARE(engaged.count(), 0);
    QVERIFY(!m_keyboardDrive->isDriving());
}

void TestKeyboardDrive::shortcutsAreLeftAlone_data()
{
    QTest::addColumn<int>("key");
    QTest::addColumn<int>("modifiers");
    QTest::newRow("Ctrl+R (reset)") << int(Qt::Key_R) << int(Qt::ControlModifier);
    QTest::newRow("Ctrl+F (forces)") << int(Qt::Key_F) << int(Qt::ControlModifier);
    QTest::newRow("Ctrl+= (faster)") << int(Qt::Key_Equal) << int(Qt::ControlModifier);
    QTest::newRow("Ctrl++ (faster)") << int(Qt::Key_Plus) << int(Qt::ControlModifier);
    QTest::newRow("Ctrl+Shift+R (record)")
        << int(Qt::Key_R) << int(Qt::ControlModifier | Qt::ShiftModifier);
    QTest::newRow("Alt+W") << int(Qt::Key_W) << int(Qt::AltModifier);
    QTest::newRow("Meta+Space") << int(Qt::Key_Space) << int(Qt::MetaModifier);
}

void TestKeyboardDrive::shortcutsAreLeftAlone()
{
    // The window's shortcuts reach the window: pressing one in the viewport neither moves a
    // hand nor takes the grippers from the operator.
    QFETCH(int, key);
    QFETCH(int, modifiers);
    QSignalSpy started(m_keyboardDrive.get(), &KeyboardDrive::driveStarted);
    QVERIFY(!m_keyboardDrive->press(key, Qt::KeyboardModifiers(modifiers)));
    QCOMPARE(started.count(), 0);
    QVERIFY(!m_keyboardDrive->isDriving());
    // The same key alone is the map's.
    if (key != Qt::Key_Equal && key != Qt::Key_Plus) {
        QVERIFY(m_keyboardDrive->press(key));
        QVERIFY(m_keyboardDrive->isDriving());
    }
}

QTEST_MAIN(TestKeyboardDrive)
#include "tst_keyboarddrive.moc"
