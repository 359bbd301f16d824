// SPDX-License-Identifier: MIT
// The keyboard teleoperation without a window: directions follow the camera, the
// workspace holds the wrist, Shift slows down, and taking over starts where the hands are.
#include "keyboardteleop.h"
#include "manualoperator.h"
#include "world.h"

#include <QSignalSpy>
#include <QTest>

#include <cmath>

using namespace semhap;

class TestKeyboardTeleop : public QObject
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

private:
    Pose heldFor(int key, double seconds, Qt::KeyboardModifiers modifiers = Qt::NoModifier);

    std::unique_ptr<World> m_world;
    ManualOperator m_manual;
    std::unique_ptr<KeyboardTeleop> m_teleop;
};

void TestKeyboardTeleop::initTestCase()
{
    QString error;
    m_world = World::load("box_and_block", SceneOptions(), &error);
    QVERIFY2(m_world, qPrintable(error));
}

void TestKeyboardTeleop::init()
{
    m_teleop = std::make_unique<KeyboardTeleop>();
    m_teleop->setOperator(&m_manual);
    m_teleop->setWorld(m_world.get());
}

Pose TestKeyboardTeleop::heldFor(int key, double seconds, Qt::KeyboardModifiers modifiers)
{
    m_teleop->press(key, modifiers);
    m_teleop->advance(seconds);
    m_teleop->release(key);
    m_manual.act(*m_world);
    return m_world->target(Gripper::Right);
}

void TestKeyboardTeleop::directionsFollowTheView_data()
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

void TestKeyboardTeleop::directionsFollowTheView()
{
    QFETCH(double, azimuth);
    QFETCH(double, x);
    QFETCH(double, y);
    m_teleop->setViewAzimuth(azimuth);
    const Pose before = m_world->target(Gripper::Right);
    const Pose away = heldFor(Qt::Key_W, 0.2);
    QVERIFY(std::abs((away.pos[0] - before.pos[0]) - x * 0.2 * 0.15) < 0.004);
    QVERIFY(std::abs((away.pos[1] - before.pos[1]) - y * 0.2 * 0.15) < 0.004);
    // D is to the viewer's right: away turned a quarter clockwise seen from above.
    const Pose right = heldFor(Qt::Key_D, 0.2);
    QVERIFY(std::abs((right.pos[0] - away.pos[0]) - y * 0.2 * 0.15) < 0.004);
    QVERIFY(std::abs((right.pos[1] - away.pos[1]) + x * 0.2 * 0.15) < 0.004);
}

void TestKeyboardTeleop::workspaceHoldsTheWrist_data()
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

void TestKeyboardTeleop::workspaceHoldsTheWrist()
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

void TestKeyboardTeleop::shiftSlowsDown()
{
    const double z = m_world->target(Gripper::Right).pos[2];
    const double fast = heldFor(Qt::Key_R, 0.2).pos[2] - z;
    const double slow = heldFor(Qt::Key_F, 0.2, Qt::ShiftModifier).pos[2] - (z + fast);
    QVERIFY2(std::abs(slow / fast + KeyboardTeleop::SlowFactor) < 0.05,
             qPrintable(QString("%1 vs %2").arg(slow).arg(fast)));
}

void TestKeyboardTeleop::takingOverStartsWhereTheHandsAre()
{
    QSignalSpy engaged(m_teleop.get(), &KeyboardTeleop::engaged);
    // Wherever the scripted operator left the hand, closed on something.
    std::array<HandCommand, 2> start{};
    start[1].present = true;
    start[1].target.pos = {0.1, -0.05, 0.2};
    start[1].grip = 42.0;
    m_teleop->setStartSource([&] { return start; });
    QVERIFY(m_teleop->press(Qt::Key_G));
    QCOMPARE(engaged.count(), 1);
    QCOMPARE(m_teleop->command(Gripper::Right).target.pos, start[1].target.pos);
    // It was closed: G opens it, ramping down from 42 N.
    QVERIFY(!m_teleop->isClosed(Gripper::Right));
    m_teleop->advance(0.1);
    QCOMPARE(m_teleop->command(Gripper::Right).grip, 42.0 - 0.1 * KeyboardTeleop::GripRate);
    m_manual.act(*m_world);
    QCOMPARE(m_world->target(Gripper::Right).pos, start[1].target.pos);

    // Handed back and taken again: from wherever the hand is by then.
    m_teleop->disengage();
    start[1].target.pos = {-0.1, 0.05, 0.25};
    QVERIFY(m_teleop->press(Qt::Key_Plus));
    QCOMPARE(engaged.count(), 2);
    QCOMPARE(m_teleop->command(Gripper::Right).target.pos, start[1].target.pos);
}

void TestKeyboardTeleop::unmappedKeysAreLeftAlone()
{
    QSignalSpy engaged(m_teleop.get(), &KeyboardTeleop::engaged);
    QVERIFY(!m_teleop->press(Qt::Key_X));
    QVERIFY(!m_teleop->press(Qt::Key_Tab)); // one hand: Tab is the focus chain's
    QVERIFY(!m_teleop->press(Qt::Key_Shift));
    QCOMPARE(engaged.count(), 0);
    QVERIFY(!m_teleop->isEngaged());
}

QTEST_MAIN(TestKeyboardTeleop)
#include "tst_keyboardteleop.moc"
