// SPDX-License-Identifier: MIT
// The network pose input over loopback UDP: valid datagrams reach the DriveOperator (and
// through it the world's targets), bad ones are counted with a clear reason, and a flood
// is read without freezing the event loop.
#include "driveoperator.h"
#include "poseinput.h"
#include "world.h"

#include <QSignalSpy>
#include <QTest>
#include <QTimer>
#include <QUdpSocket>

#include <algorithm>
#include <cmath>

using namespace semhap;

class TestPoseInput : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void init();
    void validDatagramsDriveTheHand();
    void partialDatagramsKeepTheRest();
    void malformedDatagramsAreCounted_data();
    void malformedDatagramsAreCounted();
    void floodKeepsTheEventLoopRunning();

private:
    void send(const QByteArray &datagram);
    /** Waits until `count` datagrams were read in all. */
    bool waitFor(quint64 count);

    std::unique_ptr<World> m_world;
    DriveOperator m_driving;
    std::unique_ptr<PoseInput> m_input;
    QUdpSocket m_sender;
};

void TestPoseInput::initTestCase()
{
    QString error;
    m_world = World::load("box_and_block", SceneOptions(), &error);
    QVERIFY2(m_world, qPrintable(error));
}

void TestPoseInput::init()
{
    m_input = std::make_unique<PoseInput>();
    m_input->setOperator(&m_driving);
    m_input->setWorld(m_world.get());
    QVERIFY2(m_input->listen(0), qPrintable(m_input->errorString()));
    QVERIFY(m_input->isListening());
    QVERIFY(m_input->port() != 0);
}

void TestPoseInput::send(const QByteArray &datagram)
{
    QCOMPARE(m_sender.writeDatagram(datagram, QHostAddress::LocalHost, m_input->port()),
             qint64(datagram.size()));
}

bool TestPoseInput::waitFor(quint64 count)
{
    return QTest::qWaitFor([&] { return m_input->datagramCount() >= count; }, 2000);
}

void TestPoseInput::validDatagramsDriveTheHand()
{
    QSignalSpy engaged(m_input.get(), &PoseInput::driveStarted);
    send(R"({"hand":"right","pos":[0.05,-0.02,0.2],"yaw":0.5,"grip":12.5})");
    QVERIFY(waitFor(1));
    QCOMPARE(m_input->acceptedCount(), quint64(1));
    QCOMPARE(m_input->malformedCount(), quint64(0));
    QCOMPARE(engaged.count(), 1);

    // 10 cm down: the descent lands softly, over a few steps (longer than a glide, so the
    // next datagram starts afresh).
    for (int k = 0; k < 150; ++k) {
        m_driving.act(*m_world);
        m_world->step();
    }
    m_driving.act(*m_world);
    const Pose target = m_world->target(Gripper::Right);
    QCOMPARE(target.pos, (std::array<double, 3>{0.05, -0.02, 0.2}));
    QVERIFY(std::abs(target.quat[0] - std::cos(0.25)) < 1e-12);
    QVERIFY(std::abs(target.quat[3] - std::sin(0.25)) < 1e-12);
    // Closing on nothing: the guarded close holds the fingers to their approach force.
    QCOMPARE(m_world->grip(Gripper::Right),
             std::min(12.5, m_world->closingForce(Gripper::Right, DriveOperator::ClosingSpeed)));

    // A quaternion instead of a yaw, normalised on the way in; driveStarted() only once.
    send(R"({"hand":"right","pos":[0,0,0.25],"quat":[2,0,0,0]})");
    QVERIFY(waitFor(2));
    m_driving.act(*m_world);
    QCOMPARE(m_world->target(Gripper::Right).quat, (std::array<double, 4>{1, 0, 0, 0}));
    QCOMPARE(engaged.count(), 1);
}

void TestPoseInput::partialDatagramsKeepTheRest()
{
    send(R"({"hand":"right","pos":[0.1,0.0,0.3]})");
    send(R"({"hand":"right","yaw":1.0})");
    send(R"({"hand":"right","grip":-20})");
    QVERIFY(waitFor(3));
    QCOMPARE(m_input->acceptedCount(), quint64(3));
    m_driving.act(*m_world);
    const Pose target = m_world->target(Gripper::Right);
    QCOMPARE(target.pos, (std::array<double, 3>{0.1, 0.0, 0.3}));
    QVERIFY(std::abs(target.quat[3] - std::sin(0.5)) < 1e-12);
    QCOMPARE(m_world->grip(Gripper::Right), -20.0);
}

void TestPoseInput::malformedDatagramsAreCounted_data()
{
    QTest::addColumn<QByteArray>("datagram");
    QTest::addColumn<QString>("error");
    QTest::newRow("not JSON") << QByteArray("hello") << "datagram 1: not JSON";
    QTest::newRow("not an object") << QByteArray("[1,2,3]") << "expected a JSON object";
    QTest::newRow("no hand") << QByteArray(R"({"pos":[0,0,0.2]})") << "key 'hand' is missing";
    QTest::newRow("unknown hand") << QByteArray(R"({"hand":"middle"})")
                                  << R"(key 'hand': expected "left" or "right")";
    QTest::newRow("hand the scene lacks")
        << QByteArray(R"({"hand":"left","grip":5})") << "this scene has no left gripper";
    QTest::newRow("pos of 2") << QByteArray(R"({"hand":"right","pos":[0,0]})")
                              << "key 'pos': expected an array of 3 numbers";
    QTest::newRow("pos of strings") << QByteArray(R"({"hand":"right","pos":["a","b","c"]})")
                                    << "key 'pos': expected an array of 3 numbers";
    QTest::newRow("NaN") << QByteArray(R"({"hand":"right","pos":[NaN,0,0]})") << "not JSON";
    QTest::newRow("infinity") << QByteArray(R"({"hand":"right","pos":[1e999,0,0]})") << "not JSON";
    QTest::newRow("millimetres") << QByteArray(R"({"hand":"right","pos":[150,0,300]})")
                                 << "positions are in metres";
    QTest::newRow("grip as text") << QByteArray(R"({"hand":"right","grip":"hard"})")
                                  << "key 'grip': expected a number";
    QTest::newRow("zero quaternion")
        << QByteArray(R"({"hand":"right","quat":[0,0,0,0]})") << "key 'quat'";
    QTest::newRow("quat and yaw")
        << QByteArray(R"({"hand":"right","pos":[0,0,0.2],"quat":[1,0,0,0],"yaw":1})")
        << "'quat' and 'yaw'";
    QTest::newRow("turn before any position")
        << QByteArray(R"({"hand":"right","yaw":1})") << "key 'pos' is needed";
    QTest::newRow("typo") << QByteArray(R"({"hand":"right","gripp":5})") << "unknown key 'gripp'";
    QTest::newRow("oversize") << QByteArray(5000, ' ') << "5000 bytes, larger than the limit";
}

void TestPoseInput::malformedDatagramsAreCounted()
{
    QFETCH(QByteArray, datagram);
    QFETCH(QString, error);
    QSignalSpy malformed(m_input.get(), &PoseInput::malformed);
    QSignalSpy engaged(m_input.get(), &PoseInput::driveStarted);
    send(datagram);
    QVERIFY(waitFor(1));
    QCOMPARE(m_input->malformedCount(), quint64(1));
    QCOMPARE(m_input->acceptedCount(), quint64(0));
    QCOMPARE(malformed.count(), 1);
    QCOMPARE(engaged.count(), 0);
    QVERIFY2(m_input->lastError().startsWith("datagram 1: "), qPrintable(m_input->lastError()));
    QVERIFY2(m_input->lastError().contains(error), qPrintable(m_input->lastError()));

    // Still listening: the next good datagram is taken.
    send(R"({"hand":"right","grip":3})");
    QVERIFY(waitFor(2));
    QCOMPARE(m_input->acceptedCount(), quint64(1));
}

void TestPoseInput::floodKeepsTheEventLoopRunning()
{
    constexpr int Count = 10000;
    // A timer that must keep firing while the flood is read.
    int ticks = 0;
    QTimer timer;
    timer.setInterval(1);
    connect(&timer, &QTimer::timeout, [&] { ++ticks; });
    timer.start();

    QElapsedTimer clock;
    clock.start();
    for (int i = 0; i < Count; ++i) {
        const double x = 0.1 * i / Count;
        send(QString(R"({"hand":"right","pos":[%1,0,0.2],"grip":%2})")
                 .arg(x, 0, 'f', 6)
                 .arg(i % 50)
                 .toUtf8());
        // A rig sends in bursts: the kernel's buffer holds a few hundred datagrams.
        if (i % 200 == 199)
            QCoreApplication::processEvents();
    }
    const qint64 sendMs = clock.elapsed();
    QTest::qWait(200);
    const quint64 read = m_input->datagramCount();
    qInfo("%d datagrams sent in %lld ms: %llu read (%llu accepted), %.0f/s, %d timer ticks", Count,
          sendMs, read, m_input->acceptedCount(), m_input->rate(), ticks);
    QVERIFY(read > Count / 2);
    QCOMPARE(m_input->malformedCount(), quint64(0));
    QVERIFY(ticks > 20);
    QVERIFY(m_input->rate() > 1000);
    m_driving.act(*m_world);
    QVERIFY(m_world->target(Gripper::Right).pos[0] > 0.05); // late datagrams arrived
}

QTEST_MAIN(TestPoseInput)
#include "tst_poseinput.moc"
