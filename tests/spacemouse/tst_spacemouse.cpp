// SPDX-License-Identifier: MIT
// The 3D mouse through the real libspnav against a fake spacenavd on a local socket: the
// cap's deflection drives the hand at its rate in spacenavd's frame, the dead zone neither
// moves it nor takes the grippers, the buttons grip and switch hands, losing the daemon or
// the device stops the hand, a daemon that comes back is found again, the device's name
// comes from a protocol 1 daemon, and short, unknown or absurd packets and a daemon that
// hangs up at once are harmless.
#include "driveoperator.h"
#include "handdrive.h"
#include "spacemouseinput.h"
#include "world.h"

#include <QFile>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <array>
#include <atomic>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <mutex>
#include <thread>

#include <linux/sockios.h>
#include <poll.h>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

using namespace semhap;

namespace {

// libspnav's src/proto.h: the requests' tag and the two requests the fake answers.
constexpr std::int32_t ReqTag = 0x7faa0000;
constexpr std::int32_t ReqChangeProto = 0x5500;
constexpr std::int32_t ReqDevName = 0x2000;
constexpr int StringChunk = 24;
constexpr std::int32_t StringContinued = 0x10000;
// Event types and device operations on the wire.
constexpr std::int32_t Motion = 0;
constexpr std::int32_t Press = 1;
constexpr std::int32_t Release = 2;
constexpr std::int32_t Device = 3;
constexpr std::int32_t DeviceAdded = 0;
constexpr std::int32_t DeviceRemoved = 1;

/** One event or request on the wire: eight 32-bit integers. */
using Packet = std::array<std::int32_t, 8>;

/**
 * A stand-in for spacenavd on a thread of its own (libspnav's handshake blocks the GUI
 * thread until the daemon answers): it takes one client at a time, answers the protocol
 * request with its version and, in protocol 1, the device-name requests. The test writes
 * the events to the client from the GUI thread.
 */
class FakeDaemon
{
public:
    enum class Manner
    {
        Serve,
        HangUpAtOnce, ///< closes every connection as soon as it is made
    };

    explicit FakeDaemon(const QString &path, int protocol = 0, Manner manner = Manner::Serve)
        : m_path(QFile::encodeName(path)), m_protocol(protocol), m_manner(manner)
    {}
    ~FakeDaemon() { stop(); }
    FakeDaemon(const FakeDaemon &) = delete;
    FakeDaemon &operator=(const FakeDaemon &) = delete;

    bool listen()
    {
        sockaddr_un address{};
        address.sun_family = AF_UNIX;
        if (size_t(m_path.size()) >= sizeof address.sun_path)
            return false;
        std::memcpy(address.sun_path, m_path.constData(), size_t(m_path.size()));
        m_listener = ::socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
        if (m_listener < 0 ||
            ::bind(m_listener, reinterpret_cast<sockaddr *>(&address), sizeof address) != 0 ||
            ::listen(m_listener, 4) != 0) {
            ::close(m_listener);
            m_listener = -1;
            return false;
        }
        m_running = true;
        m_thread = std::thread([this] { serve(); });
        return true;
    }

    /** Hangs up on the client and stops listening; the socket goes, as spacenavd's does. */
    void stop()
    {
        if (!m_thread.joinable())
            return;
        m_running = false;
        m_thread.join();
        ::close(m_listener);
        m_listener = -1;
        ::unlink(m_path.constData());
    }

    /** Closes the client's connection and goes on listening. */
    void hangUp()
    {
        const std::lock_guard<std::mutex> lock(m_mutex);
        if (m_client >= 0)
            ::shutdown(m_client, SHUT_RDWR);
    }

    int connections() const { return m_connections; }
    void setDeviceName(const QByteArray &name)
    {
        const std::lock_guard<std::mutex> lock(m_mutex);
        m_name = name;
    }

    bool send(const void *data, size_t size)
    {
        const std::lock_guard<std::mutex> lock(m_mutex);
        return m_client >= 0 && ::send(m_client, data, size, MSG_NOSIGNAL) == ssize_t(size);
    }
    bool send(const Packet &packet) { return send(packet.data(), sizeof packet); }
    bool motion(int x, int y, int z, int rx = 0, int ry = 0, int rz = 0)
    {
        return send(Packet{Motion, x, y, z, rx, ry, rz, 16});
    }
    bool button(int number, bool press) { return send(Packet{press ? Press : Release, number}); }
    /** A device came or went: a SpaceNavigator's type and USB id, as spacenavd sends them. */
    bool device(std::int32_t op) { return send(Packet{Device, op, 0, 0x20c, 0x046d, 0xc626}); }

    /**
     * The bytes sent that the client has not read yet (-1: no client). Zero means handled
     * too: the input reads and handles an event in one call on the GUI thread.
     */
    int unread()
    {
        const std::lock_guard<std::mutex> lock(m_mutex);
        int queued = 0;
        if (m_client < 0 || ::ioctl(m_client, SIOCOUTQ, &queued) != 0)
            return -1;
        return queued;
    }

private:
    void serve()
    {
        while (m_running) {
            pollfd ready{m_listener, POLLIN, 0};
            if (::poll(&ready, 1, 20) <= 0)
                continue;
            const int client = ::accept4(m_listener, nullptr, nullptr, SOCK_CLOEXEC);
            if (client < 0)
                continue;
            ++m_connections;
            if (m_manner == Manner::HangUpAtOnce) {
                ::close(client);
                continue;
            }
            {
                const std::lock_guard<std::mutex> lock(m_mutex);
                m_client = client;
            }
            std::int32_t request = 0;
            if (readFully(client, &request, sizeof request) &&
                (request & ~0xff) == (ReqTag | ReqChangeProto)) {
                const std::int32_t reply =
                    ReqTag | ReqChangeProto | std::min(request & 0xff, m_protocol);
                ::send(client, &reply, sizeof reply, MSG_NOSIGNAL);
                Packet packet{};
                while (readFully(client, packet.data(), sizeof packet)) {
                    if (packet[0] == (ReqTag | ReqDevName))
                        answerName(client, packet[0]);
                }
            }
            const std::lock_guard<std::mutex> lock(m_mutex);
            m_client = -1;
            ::close(client);
        }
    }

    bool readFully(int fd, void *data, size_t size)
    {
        auto *at = static_cast<char *>(data);
        while (size > 0) {
            if (!m_running)
                return false;
            pollfd ready{fd, POLLIN, 0};
            if (::poll(&ready, 1, 20) <= 0)
                continue;
            const ssize_t got = ::recv(fd, at, size, 0);
            if (got <= 0)
                return false;
            at += got;
            size -= size_t(got);
        }
        return true;
    }

    /** The name in chunks of 24 bytes, each with the length still to come, as spacenavd does. */
    void answerName(int client, std::int32_t type)
    {
        QByteArray name;
        {
            const std::lock_guard<std::mutex> lock(m_mutex);
            name = m_name;
        }
        int remaining = int(name.size());
        for (bool first = true; first || remaining > 0; first = false) {
            Packet response{};
            response[0] = type;
            const int chunk = std::min(remaining, StringChunk);
            std::memcpy(&response[1], name.constData() + (name.size() - remaining), size_t(chunk));
            response[7] = remaining | (first ? 0 : StringContinued);
            ::send(client, response.data(), sizeof response, MSG_NOSIGNAL);
            remaining -= chunk;
        }
    }

    const QByteArray m_path;
    const int m_protocol;
    const Manner m_manner;
    int m_listener = -1;
    std::thread m_thread;
    std::atomic<bool> m_running{false};
    std::atomic<int> m_connections{0};
    std::mutex m_mutex;
    int m_client = -1;
    QByteArray m_name = "SpaceNavigator";
};

} // namespace

class TestSpaceMouse : public QObject
{
    Q_OBJECT

private slots:
    void init();
    void cleanup();
    void mappingFollowsTheCap_data();
    void mappingFollowsTheCap();
    void pushingAwayMovesTheHandAway();
    void deadZoneLeavesTheHandAlone();
    void buttonsGripAndSwitchHands();
    void daemonHangingUpStopsTheHand();
    void deviceRemovalStopsTheHand();
    void daemonComingBackIsFound();
    void deviceNameComesFromTheDaemon();
    void malformedPacketsAreHarmless();
    void daemonHangingUpAtOnceIsSurvived();
    void onlyOneInstanceStarts();

private:
    /** Loads `scene` and drives it. */
    void drive(const char *scene);
    /** How far the active hand's target moves in `seconds` of the drive's integration (m). */
    double travel(double seconds);
    Pose target() const { return m_drive->command(m_drive->activeHand())->target; }

    QTemporaryDir m_dir;
    QString m_path;
    int m_run = 0;
    std::unique_ptr<World> m_world;
    std::unique_ptr<DriveOperator> m_operator;
    std::unique_ptr<HandDrive> m_drive;
    std::unique_ptr<SpaceMouseInput> m_input;
};

void TestSpaceMouse::init()
{
    QVERIFY(m_dir.isValid());
    // A socket of its own per test: libspnav finds it through the variable.
    m_path = m_dir.filePath(QString("spnav%1.sock").arg(m_run++));
    qputenv("SPNAV_SOCKET", QFile::encodeName(m_path));
    drive("box_and_block");
    m_input = std::make_unique<SpaceMouseInput>();
    m_input->setDrive(m_drive.get());
}

void TestSpaceMouse::cleanup()
{
    m_input.reset();
    m_drive.reset();
}

void TestSpaceMouse::drive(const char *scene)
{
    QString error;
    m_world = World::load(scene, SceneOptions(), &error);
    QVERIFY2(m_world, qPrintable(error));
    m_operator = std::make_unique<DriveOperator>();
    if (!m_drive)
        m_drive = std::make_unique<HandDrive>();
    m_drive->setOperator(m_operator.get());
    m_drive->setWorld(m_world.get());
}

double TestSpaceMouse::travel(double seconds)
{
    const Pose before = target();
    m_drive->advance(seconds);
    const Pose after = target();
    double squared = 0.0;
    for (size_t axis = 0; axis < 3; ++axis)
        squared += (after.pos[axis] - before.pos[axis]) * (after.pos[axis] - before.pos[axis]);
    return std::sqrt(squared);
}

void TestSpaceMouse::mappingFollowsTheCap_data()
{
    QTest::addColumn<int>("axis"); // spacenavd's x, y, z, rx, ry, rz
    QTest::addColumn<int>("value");
    QTest::addColumn<QString>("rate");
    QTest::addColumn<double>("expected");
    QTest::newRow("pushed right: right") << 0 << 350 << "right" << 1.0;
    QTest::newRow("pulled up: up") << 1 << 350 << "up" << 1.0;
    QTest::newRow("pushed away: forward") << 2 << 350 << "forward" << 1.0;
    QTest::newRow("pulled toward the user: back") << 2 << -350 << "forward" << -1.0;
    // The fingers hang below the cap's centre: the top toward the user swings them away.
    QTest::newRow("top toward the user: fingers away") << 3 << 350 << "tilt" << 1.0;
    QTest::newRow("twisted counter-clockwise: turn left") << 4 << 350 << "turn" << 1.0;
    QTest::newRow("top to the right: fingers left") << 5 << 350 << "roll" << -1.0;
    QTest::newRow("half: less the dead zone") << 2 << 175 << "forward" << (0.5 - 0.05) / 0.95;
    QTest::newRow("inside the dead zone") << 0 << 17 << "right" << 0.0;
    QTest::newRow("beyond full scale: clamped") << 1 << -5000 << "up" << -1.0;
    QTest::newRow("INT_MIN: clamped") << 4 << INT_MIN << "turn" << -1.0;
}

void TestSpaceMouse::mappingFollowsTheCap()
{
    QFETCH(int, axis);
    QFETCH(int, value);
    QFETCH(QString, rate);
    QFETCH(double, expected);
    std::array<int, 6> motion{};
    motion[size_t(axis)] = value;
    const DriveRates rates = SpaceMouseInput::ratesFor(motion, 350, 0.05);
    const std::array<std::pair<QString, double>, 6> all{{{"forward", rates.forward},
                                                         {"right", rates.right},
                                                         {"up", rates.up},
                                                         {"turn", rates.turn},
                                                         {"tilt", rates.tilt},
                                                         {"roll", rates.roll}}};
    for (const auto &[name, got] : all) {
        const double want = name == rate ? expected : 0.0;
        QVERIFY2(std::abs(got - want) < 1e-12,
                 qPrintable(QString("%1 = %2, want %3").arg(name).arg(got).arg(want)));
    }
    QVERIFY(!rates.grip);
}

void TestSpaceMouse::pushingAwayMovesTheHandAway()
{
    FakeDaemon daemon(m_path);
    QVERIFY(daemon.listen());
    QSignalSpy connected(m_input.get(), &SpaceMouseInput::connectionChanged);
    QSignalSpy started(m_drive.get(), &HandDrive::driveStarted);
    QVERIFY(m_input->start());
    QVERIFY(m_input->isConnected());
    QCOMPARE(connected.count(), 1);
    QCOMPARE(connected.at(0).at(0).toBool(), true);
    QCOMPARE(m_input->deviceName(), SpaceMouseInput::genericName()); // protocol 0 cannot say

    QVERIFY(daemon.motion(0, 0, 350)); // full deflection away: spacenavd's +z
    QTRY_COMPARE(started.count(), 1);
    // The default view looks along +y: away is +y, at full speed.
    const Pose before = target();
    m_drive->advance(0.5);
    m_operator->act(*m_world);
    const Pose after = m_world->target(Gripper::Right);
    QVERIFY2(std::abs(after.pos[1] - before.pos[1] - 0.5 * HandDrive::DefaultSpeed) < 1e-9,
             qPrintable(QString::number(after.pos[1] - before.pos[1])));
    QVERIFY(std::abs(after.pos[0] - before.pos[0]) < 1e-12);
    QVERIFY(std::abs(after.pos[2] - before.pos[2]) < 1e-12);

    // Half way: half the speed, less the dead zone.
    QVERIFY(daemon.motion(0, 0, 175));
    const double half = (0.5 - 0.05) / 0.95 * HandDrive::DefaultSpeed * 0.1;
    QTRY_COMPARE(daemon.unread(), 0);
    QVERIFY(std::abs(travel(0.1) - half) < 1e-9);
    // Let go: the hand stays.
    QVERIFY(daemon.motion(0, 0, 0));
    QTRY_COMPARE(daemon.unread(), 0);
    QCOMPARE(travel(0.1), 0.0);

    // Stopping the input lets go of a held deflection too.
    QVERIFY(daemon.motion(0, 350, 0));
    QTRY_COMPARE(daemon.unread(), 0);
    QVERIFY(travel(0.1) > 0.0);
    m_input->stop();
    QCOMPARE(travel(0.5), 0.0);
    QVERIFY(!m_input->isConnected());
    QCOMPARE(connected.count(), 2);
    QCOMPARE(connected.at(1).at(0).toBool(), false);
}

void TestSpaceMouse::deadZoneLeavesTheHandAlone()
{
    FakeDaemon daemon(m_path);
    QVERIFY(daemon.listen());
    QSignalSpy started(m_drive.get(), &HandDrive::driveStarted);
    QVERIFY(m_input->start());
    // A hand resting on the cap: every axis a little off, inside 5 % of 350.
    QVERIFY(daemon.motion(0, 0, 17));
    QVERIFY(daemon.motion(10, -15, 12, 17, -17, 5));
    QVERIFY(daemon.motion(0, 0, 0));
    QTRY_COMPARE(daemon.unread(), 0);
    QCOMPARE(started.count(), 0);
    QVERIFY(!m_drive->isDriving());

    // A wider dead zone swallows what the default one lets through.
    m_input->setDeadZone(0.2);
    QVERIFY(daemon.motion(0, 0, 60));
    QTRY_COMPARE(daemon.unread(), 0);
    QCOMPARE(started.count(), 0);

    // Just outside it: a crawl, from zero at its edge.
    m_input->setDeadZone(SpaceMouseInput::DefaultDeadZone);
    QVERIFY(daemon.motion(0, 0, 35)); // 10 % of full scale
    QTRY_COMPARE(started.count(), 1);
    const double expected = (0.1 - 0.05) / 0.95 * HandDrive::DefaultSpeed;
    QVERIFY(std::abs(travel(1.0) - expected) < 1e-9);
}

void TestSpaceMouse::buttonsGripAndSwitchHands()
{
    drive("bimanual_sorting");
    FakeDaemon daemon(m_path);
    QVERIFY(daemon.listen());
    QVERIFY(m_input->start());
    QVERIFY(m_drive->hasBothHands());
    QCOMPARE(m_drive->activeHand(), Gripper::Right);

    QVERIFY(daemon.button(0, true));
    QTRY_VERIFY(m_drive->isClosed(Gripper::Right));
    QVERIFY(m_drive->isDriving());
    // Releases and buttons beyond the two do nothing.
    QVERIFY(daemon.button(0, false));
    QVERIFY(daemon.button(2, true));
    QTRY_COMPARE(daemon.unread(), 0);
    QVERIFY(m_drive->isClosed(Gripper::Right));
    m_drive->advance(1.0); // the ramp is long done
    QCOMPARE(m_drive->command(Gripper::Right)->grip, m_drive->gripSetpoint(Gripper::Right));

    // Button 1: the other hand, which button 0 then closes alone.
    QVERIFY(daemon.button(1, true));
    QTRY_COMPARE(m_drive->activeHand(), Gripper::Left);
    QVERIFY(!m_drive->isClosed(Gripper::Left));
    QVERIFY(daemon.button(0, true));
    QTRY_VERIFY(m_drive->isClosed(Gripper::Left));
    QVERIFY(m_drive->isClosed(Gripper::Right));
    // Pressed again: open.
    QVERIFY(daemon.button(0, true));
    QTRY_VERIFY(!m_drive->isClosed(Gripper::Left));
}

void TestSpaceMouse::daemonHangingUpStopsTheHand()
{
    FakeDaemon daemon(m_path);
    QVERIFY(daemon.listen());
    QVERIFY(m_input->start());
    QSignalSpy connected(m_input.get(), &SpaceMouseInput::connectionChanged);
    QVERIFY(daemon.motion(0, 0, 350));
    QTRY_COMPARE(daemon.unread(), 0);
    QVERIFY(travel(0.1) > 0.0);

    // The cap is still held, but nobody reports it any more: the hand must stop.
    daemon.hangUp();
    QTRY_COMPARE(connected.count(), 1);
    QCOMPARE(connected.at(0).at(0).toBool(), false);
    QVERIFY(!m_input->isConnected());
    QCOMPARE(travel(0.5), 0.0);
    QVERIFY(m_input->isStarted()); // and it keeps looking for the daemon
}

void TestSpaceMouse::deviceRemovalStopsTheHand()
{
    // spacenavd outlives its device: the unplugged cap's last deflection must not stay.
    FakeDaemon daemon(m_path);
    QVERIFY(daemon.listen());
    QVERIFY(m_input->start());
    QVERIFY(daemon.motion(350, 0, 0));
    QTRY_COMPARE(daemon.unread(), 0);
    QVERIFY(travel(0.1) > 0.0);
    QVERIFY(daemon.device(DeviceRemoved));
    QTRY_COMPARE(daemon.unread(), 0);
    QCOMPARE(travel(0.1), 0.0);
    QVERIFY(m_input->isConnected());
    // Plugged in again and pushed: it drives again.
    QVERIFY(daemon.device(DeviceAdded));
    QVERIFY(daemon.motion(350, 0, 0));
    QTRY_COMPARE(daemon.unread(), 0);
    QVERIFY(travel(0.1) > 0.0);
}

void TestSpaceMouse::daemonComingBackIsFound()
{
    m_input->setRetryInterval(20);
    QSignalSpy connected(m_input.get(), &SpaceMouseInput::connectionChanged);
    // Started before the daemon: it keeps trying.
    QVERIFY(m_input->start());
    QVERIFY(!m_input->isConnected());
    {
        FakeDaemon daemon(m_path);
        QVERIFY(daemon.listen());
        QTRY_VERIFY(m_input->isConnected());
        QVERIFY(daemon.motion(0, 0, 350));
        QTRY_COMPARE(daemon.unread(), 0);
        QVERIFY(travel(0.1) > 0.0);
    } // the daemon stops: its socket goes
    QTRY_VERIFY(!m_input->isConnected());
    QCOMPARE(travel(0.1), 0.0);
    // Retries while nothing listens leave it waiting, connected to nothing.
    QTest::qWait(100);
    QVERIFY(!m_input->isConnected());

    FakeDaemon again(m_path);
    QVERIFY(again.listen());
    QTRY_VERIFY(m_input->isConnected());
    QCOMPARE(connected.count(), 3);
    QCOMPARE(connected.at(2).at(0).toBool(), true);
    QCOMPARE(again.connections(), 1);
    QVERIFY(again.motion(0, 0, -350));
    QTRY_COMPARE(again.unread(), 0);
    QVERIFY(travel(0.1) > 0.0);
}

void TestSpaceMouse::deviceNameComesFromTheDaemon()
{
    FakeDaemon daemon(m_path, 1);
    QVERIFY(daemon.listen());
    QVERIFY(m_input->start());
    QCOMPARE(m_input->deviceName(), QString("SpaceNavigator"));
    // Another device plugged in, with a name longer than one chunk of the protocol.
    daemon.setDeviceName("3Dconnexion SpaceMouse Pro Wireless");
    QVERIFY(daemon.device(DeviceAdded));
    QTRY_COMPARE(m_input->deviceName(), QString("3Dconnexion SpaceMouse Pro Wireless"));
    // Events still arrive after the requests.
    QVERIFY(daemon.motion(0, 350, 0));
    QTRY_COMPARE(daemon.unread(), 0);
    QVERIFY(travel(0.1) > 0.0);
    m_input->stop();
    QCOMPARE(m_input->deviceName(), SpaceMouseInput::genericName());
}

void TestSpaceMouse::malformedPacketsAreHarmless()
{
    FakeDaemon daemon(m_path);
    QVERIFY(daemon.listen());
    QSignalSpy started(m_drive.get(), &HandDrive::driveStarted);
    QVERIFY(m_input->start());
    // A motion cut short after x and y: libspnav would take the rest from its stack.
    const std::int32_t cut[3] = {Motion, 350, 350};
    QVERIFY(daemon.send(cut, sizeof cut));
    QTRY_COMPARE(daemon.unread(), 0);
    // An unknown type, buttons nobody has.
    QVERIFY(daemon.send(Packet{99, 350, 350, 350, 350, 350, 350, 16}));
    QVERIFY(daemon.button(-1, true));
    QVERIFY(daemon.button(INT_MAX, true));
    QTRY_COMPARE(daemon.unread(), 0);
    QCOMPARE(started.count(), 0);
    QVERIFY(m_input->isConnected());

    // Absurd counts are full deflection, no more; and the stream is still in step.
    QVERIFY(daemon.motion(0, 0, INT_MAX));
    QTRY_COMPARE(started.count(), 1);
    QVERIFY(std::abs(travel(0.1) - 0.1 * HandDrive::DefaultSpeed) < 1e-9);
}

void TestSpaceMouse::daemonHangingUpAtOnceIsSurvived()
{
    // libspnav writes to a daemon that already hung up (its protocol request, then the
    // sensitivity): SIGPIPE must not end the process.
    FakeDaemon daemon(m_path, 0, FakeDaemon::Manner::HangUpAtOnce);
    QVERIFY(daemon.listen());
    m_input->setRetryInterval(20);
    QVERIFY(m_input->start());
    QTRY_VERIFY(daemon.connections() >= 3);
    QTRY_VERIFY(!m_input->isConnected());
    QVERIFY(!m_drive->isDriving());
}

void TestSpaceMouse::onlyOneInstanceStarts()
{
    FakeDaemon daemon(m_path);
    QVERIFY(daemon.listen());
    SpaceMouseInput other;
    QVERIFY(m_input->start());
    QTest::ignoreMessage(QtWarningMsg,
                         "SpaceMouseInput: another instance holds libspnav's connection");
    QVERIFY(!other.start());
    QVERIFY(!other.isStarted());
    QVERIFY(m_input->isConnected());
    // Handed over: the other one connects.
    m_input->stop();
    QVERIFY(other.start());
    QTRY_VERIFY(other.isConnected());
    QTRY_COMPARE(daemon.connections(), 2);
}

QTEST_MAIN(TestSpaceMouse)
#include "tst_spacemouse.moc"
